"""ParticleBlock -> SPHStep -> H5Part writer -> reader keeps count, ids, arrays and times; the
same run written as H5MD (chosen by the .h5md extension) reads back identically, in H5MD's
conventions (h5py: /h5md version, position/value frames x N x 3, step, time), and a run whose
particle count changes between steps is refused for H5MD with the file left as it was."""
import glob
import os
import subprocess
import numpy as np
from paraview.simple import *
import pftest

pftest.load(globals())
out = pftest.scratch_dir()

block = ParticleBlock(Spacing=0.02, BlockBounds=[0, 0.2, 0, 0.1, 0, 0.3], DomainBounds=[0, 0.6, 0, 0.1, 0, 0.4])
sph = SPHStep(Input=block, OutputInterval=0.005, NumberOfOutputs=4, OutputAcceleration=1)
times = list(sph.TimestepValues)
pftest.check(len(times) == 5 and abs(times[1] - 0.005) < 1e-12, "SPH output times %s" % times)

# All time steps into one file, then back.
path = os.path.join(out, "all.h5part")
SaveData(path, proxy=sph, WriteAllTimeSteps=1)
reader = ParaFluidHDF5Particles(FileName=path)
read_times = list(reader.TimestepValues)
pftest.check(np.allclose(read_times, times), "times read back %s != written %s" % (read_times, times))
for t in (times[0], times[-1]):
    expected = pftest.fetch(sph, t)
    got = pftest.fetch(reader, t)
    n = expected.GetNumberOfPoints()
    pftest.check(n == got.GetNumberOfPoints() and n == 10 * 5 * 15, "particle count %d -> %d" % (n, got.GetNumberOfPoints()))
    pftest.check(got.GetNumberOfVerts() == n, "reader must emit one vertex per particle")
    pftest.check(np.array_equal(pftest.point_array(expected, "id"), pftest.point_array(got, "id")), "ids differ at t=%g" % t)
    pftest.check(np.array_equal(pftest.points(expected), pftest.points(got)), "positions differ at t=%g" % t)
    for name in ("velocity", "density", "pressure", "acceleration", "mass"):
        a, b = pftest.point_array(expected, name), pftest.point_array(got, name)
        pftest.check(a.shape == b.shape and np.array_equal(a, b), "array %s differs at t=%g" % (name, t))
    fd = got.GetFieldData()
    pftest.check(abs(fd.GetArray("time").GetValue(0) - t) < 1e-12, "time field data")
    pftest.check(abs(fd.GetArray("particle_spacing").GetValue(0) - 0.02) < 1e-12, "particle_spacing field data")
    pftest.check(fd.GetArray("domain_bounds").GetNumberOfTuples() == 6, "domain_bounds field data")
# the dam moved between the first and last step
first, last = pftest.points(pftest.fetch(reader, times[0])), pftest.points(pftest.fetch(reader, times[-1]))
pftest.check(np.abs(first - last).max() > 1e-3, "particles did not move")

# Only selected arrays are read.
reader.PointArrays = ["velocity"]
data = pftest.fetch(reader, times[-1])
pftest.check(pftest.array_names(data) == ["id", "velocity"], "array selection ignored: %s" % pftest.array_names(data))

# One step per write; a second write replaces the file whole and leaves no temporary behind.
single = os.path.join(out, "one.h5part")
SaveData(single, proxy=sph)
inode = os.stat(single).st_ino
UpdatePipeline(times[2], sph)
SaveData(single, proxy=sph)
pftest.check(os.stat(single).st_ino != inode, "the second write did not go through a renamed temporary file")
pftest.check(glob.glob(os.path.join(out, "*.tmp-*")) == [], "temporary files left behind")
one = ParaFluidHDF5Particles(FileName=single)
pftest.check(len(one.TimestepValues) in (0, 1) or isinstance(one.TimestepValues, float), "single-step file has %s" % one.TimestepValues)

# A write into a missing folder fails cleanly and does not touch the existing file.
before = open(single, "rb").read()
writer = CreateWriter(os.path.join(out, "missing", "x.h5part"), sph)
catcher = pftest.ErrorCatcher(writer)
writer.UpdatePipeline()
pftest.check("cannot create" in catcher.text(), "no clear error for an unwritable path: %r" % catcher.text())
pftest.check(open(single, "rb").read() == before, "existing file changed")
# H5MD: the same run, every step a frame.
h5md = os.path.join(out, "all.h5md")
SaveData(h5md, proxy=sph, WriteAllTimeSteps=1)
md = ParaFluidHDF5Particles(FileName=h5md)
md.UpdatePipelineInformation()
pftest.check(md.GetProperty("DetectedLayout").GetElement(0).startswith("H5MD 1.1"),
             "DetectedLayout %r" % md.GetProperty("DetectedLayout").GetElement(0))
pftest.check(np.allclose(list(md.TimestepValues), times), "H5MD times %s != %s" % (list(md.TimestepValues), times))
for t in (times[0], times[-1]):
    expected = pftest.fetch(sph, t)
    got = pftest.fetch(md, t).GetBlock(0)
    pftest.check(np.array_equal(pftest.points(expected), pftest.points(got)), "H5MD positions differ at t=%g" % t)
    pftest.check(np.array_equal(pftest.point_array(expected, "id"), pftest.point_array(got, "id")), "H5MD ids at t=%g" % t)
    for name in ("velocity", "density", "pressure", "mass"):
        pftest.check(np.array_equal(pftest.point_array(expected, name), pftest.point_array(got, name)),
                     "H5MD array %s differs at t=%g" % (name, t))
shape = subprocess.run(["/usr/bin/python3", "-c", "import h5py; f = h5py.File(%r, 'r'); "
                        "print(list(f['h5md'].attrs['version']), f['particles/all/position/value'].shape, "
                        "len(f['particles/all/position/time']), f['particles/all/box'].attrs['dimension'])" % h5md],
                       check=True, capture_output=True, text=True).stdout.split("\n")[0]
n = pftest.fetch(sph, times[0]).GetNumberOfPoints()
pftest.check(shape == "[1, 1] (5, %d, 3) 5 3" % n, "H5MD structure: %s" % shape)
varying = os.path.join(out, "varying.h5part")
pftest.write_h5(varying, """
for k, n in enumerate((4, 6)):
    g = f.create_group('Step#%d' % k); g.attrs['time'] = float(k)
    g['x'] = np.arange(n, dtype='f4'); g['y'] = np.zeros(n, dtype='f4'); g['z'] = np.zeros(n, dtype='f4')
""")
before = open(h5md, "rb").read()
writer = CreateWriter(h5md, ParaFluidHDF5Particles(FileName=varying))
writer.WriteAllTimeSteps = 1
catcher = pftest.ErrorCatcher(writer)
writer.UpdatePipeline()
pftest.check("same particles in every frame" in catcher.text(), "no clear error for a changing count: %r" % catcher.text())
pftest.check(open(h5md, "rb").read() == before, "the refused H5MD write changed the existing file")
print("round trip: ok")
