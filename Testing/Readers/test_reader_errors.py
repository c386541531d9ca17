"""Bad files give a clear error from the reader, an empty output and no crash."""
import os
from paraview.simple import *
import pftest

pftest.load(globals())
out = pftest.scratch_dir()


def expect_error(path, words):
    reader = ParaFluidHDF5Particles(FileName=path)
    catcher = pftest.ErrorCatcher(reader)
    reader.UpdatePipeline()
    text = catcher.text()
    pftest.check(all(w in text for w in words), "%s: expected %s in the error, got %r" % (os.path.basename(path), words, text))
    data = pftest.fetch(reader)
    pftest.check(data is None or data.GetNumberOfPoints() == 0, "%s: produced particles" % path)
    Delete(reader)


missing = os.path.join(out, "coordinates.h5part")
pftest.write_h5(missing, """
g = f.create_group('Step#0'); g['density'] = np.ones(4)
""")
expect_error(missing, ["no particle coordinates"])

mismatch = os.path.join(out, "mismatch.h5part")
pftest.write_h5(mismatch, """
g = f.create_group('Step#0'); g['x'] = np.ones(4); g['y'] = np.ones(4); g['z'] = np.ones(4); g['density'] = np.ones(3)
""")
expect_error(mismatch, ["density", "3 values for 4 particles"])

coords = os.path.join(out, "coords.h5part")
pftest.write_h5(coords, """
g = f.create_group('Step#0'); g['x'] = np.ones(4); g['y'] = np.ones(5); g['z'] = np.ones(4)
""")
expect_error(coords, ["equal length"])

empty = os.path.join(out, "empty.h5part")
pftest.write_h5(empty, """
f.create_group('Step#0')
""")
expect_error(empty, ["empty step"])

nosteps = os.path.join(out, "nosteps.h5part")
pftest.write_h5(nosteps, """
f['data'] = np.ones(3)
""")
expect_error(nosteps, ["no H5Part step groups"])

text = os.path.join(out, "text.h5part")
with open(text, "w") as f:
    f.write("not hdf5 at all\n")
expect_error(text, ["not an HDF5 file"])

expect_error(os.path.join(out, "does-not-exist.h5part"), ["missing or unreadable"])

# NaN coordinates are read (the file says so) but reported.
nan = os.path.join(out, "nan.h5part")
pftest.write_h5(nan, """
g = f.create_group('Step#0'); g['x'] = np.array([0.0, np.nan]); g['y'] = np.zeros(2); g['z'] = np.zeros(2)
""")
r = ParaFluidHDF5Particles(FileName=nan)
pftest.check(pftest.fetch(r).GetNumberOfPoints() == 2, "NaN file should still load")
# and the SPH filter refuses it with a clear message instead of computing garbage
block = ParticleBlock()
sph = SPHStep(Input=r, SmoothingLength=0.1, ParticleMass=1.0, DomainBounds=[-1, 1, -1, 1, -1, 1])
catcher = pftest.ErrorCatcher(sph)
sph.UpdatePipeline()
pftest.check("NaN" in catcher.text(), "SPH Step on NaN input: %r" % catcher.text())

# absurd SPH parameters are refused with the property's name
sph2 = SPHStep(Input=block, TimeStep=0.0)
catcher = pftest.ErrorCatcher(sph2)
sph2.UpdatePipeline()
pftest.check("TimeStep" in catcher.text(), "zero TimeStep: %r" % catcher.text())
sph3 = SPHStep(Input=block, DomainBounds=[1, 0, 0, 1, 0, 1])
catcher = pftest.ErrorCatcher(sph3)
sph3.UpdatePipeline()
pftest.check("DomainBounds" in catcher.text(), "inverted DomainBounds: %r" % catcher.text())

# zero particles: a block smaller than one spacing
zero = SPHStep(Input=ParticleBlock(BlockBounds=[0, 0.001, 0, 0.001, 0, 0.001]), NumberOfOutputs=2)
d = pftest.fetch(zero, zero.TimestepValues[-1])
pftest.check(d.GetNumberOfPoints() == 0, "zero particles in, zero out")
print("reader errors: ok")

# A run that needs millions of steps (Viscosity 1e6 Pa s shrinks the explicit viscous step) is
# announced before it starts, and can be aborted from the warning on.
slow = SPHStep(Input=ParticleBlock(), PressureSolver="WCSPH (Müller)", Viscosity=1e6, NumberOfOutputs=1)
slow_object = slow.GetClientSideObject()
long_run = []


@pftest.calldata_type(pftest.VTK_STRING)
def abort_on_warning(_o, _e, text):
    long_run.append(text)
    slow_object.SetAbortExecute(1)


slow_object.AddObserver("WarningEvent", abort_on_warning)
slow.UpdatePipeline(slow.TimestepValues[-1])
pftest.check(len(long_run) == 1 and "time steps" in long_run[0] and "Viscosity" in long_run[0], "no long-run warning: %r" % long_run)
print("long runs: ok")

# The memory budget: a step, a block or a simulation larger than it is refused with the sizes.
os.environ["PARAFLUID_MEMORY_BUDGET_MB"] = "1"
big = os.path.join(out, "big.h5part")
pftest.write_h5(big, """
g = f.create_group('Step#0'); g['x'] = np.zeros(200000); g['y'] = np.zeros(200000); g['z'] = np.zeros(200000)
""")
expect_error(big, ["would take", "PARAFLUID_MEMORY_BUDGET_MB"])
block_too_big = ParticleBlock(BlockBounds=[0, 1, 0, 1, 0, 1], Spacing=0.01)
catcher = pftest.ErrorCatcher(block_too_big)
block_too_big.UpdatePipeline()
pftest.check("would take" in catcher.text() and "Spacing" in catcher.text(), "block over the budget: %r" % catcher.text())
del os.environ["PARAFLUID_MEMORY_BUDGET_MB"]
print("memory budget: ok")
