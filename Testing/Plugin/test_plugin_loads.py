"""The ParaFluid plugin loads in pvpython and registers its reader, writer, source and filter."""
from paraview.simple import *
from paraview import servermanager
import pftest

pftest.load(globals())
for name in ("ParaFluidHDF5Particles", "ParticleBlock", "SPHStep"):
    pftest.check(name in globals(), "%s is not available after LoadPlugin" % name)
pftest.check(servermanager.ProxyManager().GetPrototypeProxy("writers", "ParaFluidH5PartWriter") is not None,
             "the H5Part writer is not registered")
data = pftest.fetch(ParticleBlock())
pftest.check(data.GetNumberOfPoints() == 20 * 10 * 40, "default block has %d particles" % data.GetNumberOfPoints())
for array in ("velocity", "density", "pressure", "mass", "id"):
    pftest.check(data.GetPointData().GetArray(array) is not None, "Particle Block lacks %s" % array)
pftest.check(data.GetPointData().GetArray("id").GetDataTypeAsString() in ("long long", "long"), "id is not int64")
print("plugin loads: ok")
