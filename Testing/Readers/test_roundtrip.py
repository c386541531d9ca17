"""ParticleBlock -> SPHStep -> H5Part writer -> reader keeps count, ids, arrays and times."""
import glob
import os
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
print("round trip: ok")
