"""Time to read 1M particles x 5 arrays from H5Part: ParaFluid's reader against ParaView's built-in
H5PartReader, on the same files (uncompressed, and deflate-1 as ParaFluid's writer writes them).
Prints a table and writes read_benchmark.csv in the working directory.

  PARAFLUID_PLUGIN=<ParaFluid.so> pvpython Testing/Benchmarks/read_benchmark.py [particles] [repeats]"""
import os
import statistics
import subprocess
import sys
import tempfile
import time

from paraview.simple import *

LoadPlugin(os.environ["PARAFLUID_PLUGIN"], ns=globals())
n = int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000
repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 5
folder = tempfile.mkdtemp(prefix="parafluid-bench-")

files = {}
# The file: eight contiguous float32 datasets as h5py writes them, no id.
path = os.path.join(folder, "h5py8.h5part")
subprocess.run(["/usr/bin/python3", "-c", f"""
import h5py, numpy as np
rng = np.random.default_rng(2)
with h5py.File({path!r}, 'w') as f:
    g = f.create_group('Step#0')
    for name in ('x', 'y', 'z', 'vx', 'vy', 'vz', 'density', 'pressure'):
        g.create_dataset(name, data=rng.random({n}, dtype=np.float32))
"""], check=True)
files["h5py8"] = path
for label, compression in (("plain", None), ("deflate1", 1)):
    path = os.path.join(folder, "%s.h5part" % label)
    # h5py runs in its own process so this one holds only ParaView's HDF5.
    program = f"""
import h5py, numpy as np
rng = np.random.default_rng(1)
with h5py.File({path!r}, 'w') as f:
    g = f.create_group('Step#0')
    opts = dict(chunks=(65536,), compression='gzip', compression_opts={compression}, shuffle=True) if {compression!r} else {{}}
    for name in ('x', 'y', 'z', 'vx', 'vy', 'vz', 'density', 'pressure', 'mass'):
        g.create_dataset(name, data=rng.random({n}, dtype=np.float32), **opts)
    g.create_dataset('id', data=np.arange({n}, dtype=np.int64), **opts)
"""
    subprocess.run(["/usr/bin/python3", "-c", program], check=True)
    files[label] = path

def time_reader(make):
    times = []
    for _ in range(repeats):
        # drop what the OS caches would not hold for a cold file? no: both readers get a warm cache.
        reader = make()
        start = time.perf_counter()
        reader.UpdatePipeline()
        times.append(time.perf_counter() - start)
        count = reader.GetDataInformation().GetNumberOfPoints()
        arrays = reader.GetDataInformation().GetPointDataInformation().GetNumberOfArrays()
        Delete(reader)
    return statistics.median(times), count, arrays

rows = []
for label, path in files.items():
    ours = time_reader(lambda: ParaFluidHDF5Particles(FileName=path))
    builtin = time_reader(lambda: H5PartReader(FileName=path))
    rows.append((label, "ParaFluid H5Part Reader", *ours))
    rows.append((label, "ParaView H5PartReader", *builtin))

print("%-9s %-24s %10s %10s %7s" % ("file", "reader", "median s", "particles", "arrays"))
for r in rows:
    print("%-9s %-24s %10.3f %10d %7d" % r)
with open("read_benchmark.csv", "w") as out:
    out.write("file,reader,median_seconds,particles,point_arrays\n")
    for r in rows:
        out.write("%s,%s,%.4f,%d,%d\n" % r)
