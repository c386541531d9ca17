"""ParaFluid HDF5 Particles beyond one file read whole:
 - PySPH's own output, from the real producer (Debian's python3-pysph runs its elliptical-drop
   example for 20 steps): OpenDataFile picks the reader, the numbered files are one time series
   at the solver's times, positions, velocity (u, v, w), mass (m) and the iteration (count) read
   value for value; particles tagged remote or ghost are left out;
 - Stride keeps about one particle in n, the same particles (by id) at two times whose rows are
   in different orders;
 - SelectionBox returns exactly the particles inside it; on a SWIFT snapshot with its spatial
   index only the cells near the box are read from disk (bytes read, from /proc/self/io), with
   and without the cells' particle bounds, particles that drifted off their cell included;
 - a SelectionBox with min > max is an error naming it."""
import glob
import os
import sys
import subprocess

import numpy as np
from paraview.simple import *
import pftest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # pvbatch leaves the script's folder out
import cell_snapshot  # noqa: E402

pftest.load(globals())
out = pftest.scratch_dir()


def read_h5(path, expression):
    """The value of `expression` (of an open h5py File f) in /usr/bin/python3, as a NumPy array."""
    target = os.path.join(out, "value.npy")
    program = "import h5py, numpy as np\nwith h5py.File(%r, 'r') as f:\n    np.save(%r, np.asarray(%s))" % (
        path, target, expression)
    subprocess.run(["/usr/bin/python3", "-c", program], check=True)
    return np.load(target)


def block(reader, name=None, t=None):
    data = pftest.fetch(reader, t)
    for b in range(data.GetNumberOfBlocks()):
        if name is None or data.GetMetaData(b).Get(data.NAME()) == name:
            return data.GetBlock(b)
    raise AssertionError("no block %r" % name)


# --- PySPH, its own example's output --------------------------------------------------------------
run = os.path.join(out, "pysph")
subprocess.run(["/usr/bin/python3", "-m", "pysph.examples.elliptical_drop", "--max-steps", "20", "--pfreq", "10",
                "-d", run], check=True, cwd=out, stdout=subprocess.DEVNULL)
files = sorted(glob.glob(os.path.join(run, "elliptical_drop_*.hdf5")))
pftest.check(len(files) == 3, "PySPH wrote %s" % files)
reader = OpenDataFile(files[1])
pftest.check(reader.GetXMLName() == "H5ParaFluidParticlesReader", "OpenDataFile picks %s for PySPH" % reader.GetXMLName())
reader.UpdatePipelineInformation()
layout = reader.GetProperty("DetectedLayout").GetElement(0)
pftest.check(layout == "PySPH output, series of 3 files", "DetectedLayout %r" % layout)
times = [float(read_h5(path, "f['solver_data'].attrs['t']")) for path in files]
pftest.check(list(reader.TimestepValues) == times, "times %s, the files say %s" % (list(reader.TimestepValues), times))
for k, path in enumerate(files):
    fluid = block(reader, "fluid", times[k])
    x = np.stack([read_h5(path, "f['particles/fluid/arrays/%s'][:]" % a) for a in "xyz"], -1)
    pftest.check(np.array_equal(pftest.points(fluid), x), "file %d: positions differ from the file's x, y, z" % k)
    uvw = np.stack([read_h5(path, "f['particles/fluid/arrays/%s'][:]" % a) for a in "uvw"], -1)
    pftest.check(np.array_equal(pftest.point_array(fluid, "velocity"), uvw), "file %d: velocity is not u, v, w" % k)
    pftest.check(np.array_equal(pftest.point_array(fluid, "mass"), read_h5(path, "f['particles/fluid/arrays/m'][:]")),
                 "file %d: mass is not m" % k)
    pftest.check(np.array_equal(pftest.point_array(fluid, "id"), np.arange(len(x))),
                 "file %d: a serial run's unassigned gid should leave the rows as ids" % k)
    count = fluid.GetFieldData().GetArray("iteration").GetValue(0)
    pftest.check(count == 10 * k, "file %d: iteration %s" % (k, count))

# Detailed output of a parallel run holds remote (1) and ghost (2) particles beside the real ones.
tagged = os.path.join(out, "tagged_00000.hdf5")
pftest.write_h5(tagged, """
s = f.create_group('solver_data'); s.attrs['t'] = 0.5; s.attrs['dt'] = 1e-3; s.attrs['count'] = 7
a = f.create_group('particles/fluid/arrays'); f.create_group('particles/fluid/constants')
for name, values in (('x', np.arange(6.0)), ('y', np.zeros(6)), ('z', np.zeros(6)), ('rho', np.full(6, 1000.0)),
                     ('gid', np.arange(6, dtype='u4') + 10), ('tag', np.array([0, 2, 0, 1, 0, 2], dtype='i4'))):
    a[name] = values; a[name].attrs['stored'] = True; a[name].attrs['stride'] = 1
a.create_dataset('au', (0,)).attrs['stored'] = False
a['gradv'] = np.zeros(54); a['gradv'].attrs['stride'] = 9
b = f.create_group('particles/empty/arrays')
for name in 'xyz':
    b[name] = np.zeros(0)
""")
t = ParaFluidHDF5Particles(FileName=tagged)
messages = pftest.Messages(t.GetClientSideObject())
fluid = block(t, "fluid")
pftest.check(list(pftest.point_array(fluid, "id")) == [10, 12, 14], "real particles: ids %s" % pftest.point_array(fluid, "id"))
pftest.check(list(pftest.points(fluid)[:, 0]) == [0.0, 2.0, 4.0], "real particles: x %s" % pftest.points(fluid)[:, 0])
pftest.check(pftest.array_names(fluid) == ["density", "id", "tag"], "arrays %s" % pftest.array_names(fluid))
pftest.check(any("gradv" in w for w in messages.warnings), "no warning names the stride-9 gradv: %s" % messages.warnings)

# --- Stride: the same particles at both times -------------------------------------------------------
for k, seed in enumerate((1, 2)):  # the same particles, their rows in another order
    pftest.write_h5(os.path.join(out, "snap_%03d.hdf5" % k), cell_snapshot.script(20000, 4, seed=5, drift=0.0)
                    + "\nh.attrs['Time'] = %d.0\n" % k + "\nperm = np.random.default_rng(%d).permutation(n)\n" % seed
                    + "for name in list(g.keys()):\n    values = g[name][:]\n    del g[name]\n    g[name] = values[perm]\n"
                    + "del f['Cells']\n")
series = ParaFluidHDF5Particles(FileName=os.path.join(out, "snap_000.hdf5"), Stride=8)
series.UpdatePipelineInformation()
pftest.check(list(series.TimestepValues) == [0.0, 1.0], "snapshot series times %s" % list(series.TimestepValues))
kept = [block(series, None, t) for t in (0.0, 1.0)]
ids = [np.sort(pftest.point_array(b, "id")) for b in kept]
pftest.check(abs(len(ids[0]) - 20000 / 8) < 200, "Stride 8 kept %d of 20000" % len(ids[0]))
pftest.check(np.array_equal(ids[0], ids[1]), "Stride picked other particles at the second time")
by_id = [dict(zip(pftest.point_array(b, "id"), pftest.points(b).tolist())) for b in kept]
pftest.check(all(by_id[0][i] == by_id[1][i] for i in ids[0]), "a particle kept by Stride has other coordinates")

# --- SelectionBox on a cell-indexed snapshot ---------------------------------------------------------
def bytes_read():
    with open("/proc/self/io") as io:
        return int(next(line for line in io if line.startswith("rchar")).split()[1])


box = [0.30, 0.52, 0.41, 0.66, 0.05, 0.27]  # metres: 1.2 % of the volume
for bounds in (True, False):
    path = os.path.join(out, "cells_%d.hdf5" % bounds)
    pftest.write_h5(path, cell_snapshot.script(200000, 16, bounds=bounds))
    x = read_h5(path, "f['PartType0/Coordinates'][:]")
    inside = np.all((x >= box[0::2]) & (x <= box[1::2]), axis=1)
    r = ParaFluidHDF5Particles(FileName=path, FileSeries=0)
    before = bytes_read()
    full = block(r)
    whole = bytes_read() - before
    r.UseSelectionBox = 1
    r.SelectionBox = box
    before = bytes_read()
    roi = block(r)
    part = bytes_read() - before
    got = pftest.points(roi)
    pftest.check(len(got) == inside.sum() and np.array_equal(np.sort(pftest.point_array(roi, "id")),
                                                             np.sort(read_h5(path, "f['PartType0/ParticleIDs'][:]")[inside])),
                 "bounds %s: the box returned %d particles, %d are inside" % (bounds, len(got), inside.sum()))
    limit = 0.12 if bounds else 0.2  # the cells near the box (without bounds widened by a cell) and the index
    pftest.check(part < limit * whole, "bounds %s: the box read %d bytes, the whole file %d" % (bounds, part, whole))
    print("SelectionBox, cell bounds %s: %d of %d particles, %.1f %% of the bytes" % (
        bounds, len(got), full.GetNumberOfPoints(), 100.0 * part / whole))

r.SelectionBox = [0.5, 0.4, 0, 1, 0, 1]
messages = pftest.Messages(r.GetClientSideObject())
r.UpdatePipeline()
pftest.check(any("SelectionBox" in e for e in messages.errors), "min > max: errors %s" % messages.errors)
print("particle subsets: ok")
