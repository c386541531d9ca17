"""Under MPI (pvbatch, 2 ranks), an error on one rank is every rank's: each collective filter and
the writer, failing on process 0 only, must end on both processes with the error reported, and
the session must go on working. Before, the writer to a missing folder and Particle Surface
without a spacing left process 1 waiting forever in the next gather."""
import builtins
import os
import tempfile

from paraview.simple import *
from paraview import servermanager
import pftest

pftest.load(globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
pftest.check(ranks == 2, "run with 2 MPI ranks (got %d)" % ranks)


def all_in(words, text):
    return builtins.all(w in text for w in words)


def expect_error(proxy, words, time=None):
    catcher = pftest.ErrorCatcher(proxy)
    if time is None:
        proxy.UpdatePipeline()
    else:
        proxy.UpdatePipeline(time)
    text = catcher.text()
    pftest.check(all_in(words, text), "%s: expected %s in the error, got %r" % (proxy.GetXMLLabel(), words, text))


def still_works():
    """A healthy pipeline after the failure: both processes are still in step."""
    block = ParticleBlock(BlockBounds=[0, 0.2, 0, 0.2, 0, 0.2], Spacing=0.05)
    data = pftest.fetch(block)
    pftest.check(data.GetNumberOfPoints() == 64, "after the error the session no longer works (%d points)" % data.GetNumberOfPoints())
    Delete(block)


# Particle Surface on one particle without particle_spacing: the error is raised on process 0 after
# the gather.
one = ProgrammableSource(Script=pftest.particle_script("P = np.zeros((1, 3))"))
expect_error(ParticleSurfaceMarchingCubes(Input=one), ["Particle Surface", "ParticleSpacing"])
still_works()

# Carpet Surface and Fluid Flow Lines likewise.
expect_error(CarpetSurface(Input=one), ["Carpet Surface"])
still_works()
expect_error(FluidFlowLines(Input=one), ["Fluid Flow Lines", "ParticleSpacing"])
still_works()

# SPH Step refusing NaN input on process 0.
nan = ProgrammableSource(Script=pftest.particle_script("P = np.array([[0, 0, 0], [np.nan, 0, 0]]); h = 0.1"))
expect_error(SPHStep(Input=nan, DomainBounds=[-1, 1, -1, 1, -1, 1]), ["SPH Step", "NaN"])
still_works()

def write_all_steps_fails(source, path, words):
    """Writing every time step of `source` to `path` ends on both processes with an error holding
    `words`, and leaves no file."""
    writer = CreateWriter(path, source)
    writer.WriteAllTimeSteps = 1
    catcher = pftest.ErrorCatcher(writer)
    writer.UpdatePipeline()
    pftest.check(all_in(words, catcher.text()), "writer to %s: %r" % (path, catcher.text()))
    pftest.check(not os.path.exists(path), "a file was left at %s by a failed write" % path)
    Delete(writer)
    still_works()


# The writer, all time steps, into a folder that does not exist.
block = ParticleBlock(BlockBounds=[0, 0.2, 0, 0.2, 0, 0.2], Spacing=0.05, DomainBounds=[0, 0.4, 0, 0.4, 0, 0.4])
sph = SPHStep(Input=block, OutputInterval=0.002, NumberOfOutputs=3)
missing = os.path.join(tempfile.mkdtemp(prefix="parafluid-mpi-"), "no-such-folder", "out.h5part")
write_all_steps_fails(sph, missing, ["cannot create"])

# And a good write after it, with every step.
good = os.path.join(tempfile.mkdtemp(prefix="parafluid-mpi-"), "out.h5part")
SaveData(good, proxy=sph, WriteAllTimeSteps=1)
copy = ParaFluidHDF5Particles(FileName=good)
pftest.check(len(copy.TimestepValues) == len(sph.TimestepValues), "the write after the error holds %d steps of %d" % (len(copy.TimestepValues), len(sph.TimestepValues)))

# The writer, all time steps, of an input that fails after the first: a block that reaches outside
# its domain is folded onto itself and blows up at the second step. The executive's
# continue-executing loop never ended when the input failed (both processes spun forever).
folded = ParticleBlock(BlockBounds=[0, 0.2, 0, 0.2, 0, 0.2], Spacing=0.05, DomainBounds=[0, 0.8, 0, 0.1, 0, 0.6])
# Müller's WCSPH: the folded particles (twice the rest density) stop it at once.
failing = SPHStep(Input=folded, PressureSolver="WCSPH (Müller)", OutputInterval=0.002, NumberOfOutputs=3)
write_all_steps_fails(failing, os.path.join(tempfile.mkdtemp(prefix="parafluid-mpi-"), "late.h5part"),
                      ["input failed"])
print("MPI error paths: ok")
