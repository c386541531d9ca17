"""Compares the validation CSVs of two runs, every column but the wall time; prints each scene's
largest difference."""
import csv, glob, os, sys
a, b = sys.argv[1], sys.argv[2]
worst = 0.0
for fa in sorted(glob.glob(os.path.join(a, "*.csv"))):
    fb = os.path.join(b, os.path.basename(fa))
    if not os.path.exists(fb):
        print(os.path.basename(fa), "missing in", b); continue
    ra, rb = list(csv.reader(open(fa))), list(csv.reader(open(fb)))
    if len(ra) != len(rb):
        print(os.path.basename(fa), "rows", len(ra), len(rb)); worst = max(worst, 1.0); continue
    header = ra[0] if ra and not ra[0][0].replace('.','').isdigit() else []
    diff = 0.0; cells = 0
    for x, y in zip(ra, rb):
        for k, (u, v) in enumerate(zip(x, y)):
            if header and k < len(header) and header[k] in ("wall_s", "seconds"):
                continue
            if u == v: continue
            try:
                d = abs(float(u) - float(v)) / max(abs(float(u)), 1e-12)
            except ValueError:
                d = 1.0
            diff = max(diff, d); cells += 1
    worst = max(worst, diff)
    print("%-28s rows %5d  cells differing %5d  largest relative difference %.3g" % (os.path.basename(fa), len(ra), cells, diff))
print("largest relative difference over all:", worst)
