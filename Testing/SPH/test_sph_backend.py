"""SPH Step's Backend: CPU and Automatic run and say where (BackendUsed, and Automatic in the output
window); CUDA where it cannot run is an error that says why and what to choose; a Backend that is
no choice is refused and the old one kept."""
import numpy as np
from paraview.simple import *
import pftest

pftest.load(globals())
block = ParticleBlock(Spacing=0.02, BlockBounds=[0, 0.2, 0, 0.1, 0, 0.2], DomainBounds=[0, 0.6, 0, 0.1, 0, 0.4])


def used(proxy):
    proxy.UpdatePropertyInformation()
    return proxy.GetPropertyValue("BackendUsed")


settings = dict(Input=block, AdaptiveTimeStep=0, TimeStep=2e-4, OutputInterval=0.002, NumberOfOutputs=2)
cpu = SPHStep(Backend="CPU", **settings)
pftest.check(cpu.Backend == "CPU", "Backend CPU was not kept: %s" % cpu.Backend)
times = list(cpu.TimestepValues)
on_cpu = pftest.points(pftest.fetch(cpu, times[2]))
pftest.check(used(cpu) == "CPU", "BackendUsed with Backend CPU: %r" % used(cpu))

window = pftest.OutputWindowMessages()
automatic = SPHStep(**settings)
pftest.check(automatic.Backend == "Automatic", "Backend's default is %s, not Automatic" % automatic.Backend)
on_automatic = pftest.points(pftest.fetch(automatic, times[2]))
where = used(automatic)
print("Automatic ran on: %s" % where)
if where.startswith("CPU"):
    # No GPU here (CI): the CPU, saying why, with the CPU's result to the bit.
    pftest.check(where.startswith("CPU: ") and len(where) > 10, "Automatic on the CPU must say why: %r" % where)
    pftest.check(np.array_equal(on_automatic, on_cpu), "Automatic on the CPU differs from Backend CPU")
else:
    pftest.check(where.startswith("CUDA ("), "Automatic ran on neither the CPU nor CUDA: %r" % where)
    pftest.check(np.abs(on_automatic - on_cpu).max() < 1e-5, "the GPU's particles are more than 1e-5 m off the CPU's")

cuda = SPHStep(Backend="CUDA", **settings)
messages = pftest.Messages(cuda.GetClientSideObject())
result = pftest.fetch(cuda, times[2])
if where.startswith("CPU"):
    text = "\n".join(messages.errors)
    pftest.check("Backend CUDA" in text and "Backend CPU" in text,
                 "Backend CUDA without a GPU must be an error naming the property and the way out: %r" % text)
    pftest.check(result.GetNumberOfPoints() == 0, "Backend CUDA without a GPU still made %d particles" %
                 result.GetNumberOfPoints())
else:
    pftest.check(used(cuda).startswith("CUDA ("), "Backend CUDA ran on %r" % used(cuda))

# A Backend that is no choice is refused by name and the previous one kept.
refused = pftest.Messages(cpu.GetClientSideObject())
cpu.SMProxy.GetProperty("Backend").SetElement(0, 7)
cpu.SMProxy.UpdateVTKObjects()
pftest.check(any("Backend" in e for e in refused.errors), "Backend 7 was not refused by name: %r" % refused.errors)
printed = str(cpu.GetClientSideObject())
pftest.check("Backend: 1 (used: CPU)" in printed, "Backend 7 replaced Backend CPU: %s" %
             [line for line in printed.splitlines() if "Backend" in line])
# The Rain filter's runoff has the same choice; its default DFSPH does not run on the GPU yet, so
# CUDA is refused by name everywhere and Automatic runs on the CPU.
terrain = ProceduralTerrain(Resolution=[9, 9], Extent=[2, 2], HeightScale=0.2)
rain_settings = dict(Terrain=terrain, Cells=[4, 4], PrecipitationHeight=1.0, RainfallRate=5000, ParticleSpacing=0.1,
                     OutputInterval=0.5, NumberOfOutputs=2)
rain_cuda = Rain(Backend="CUDA", **rain_settings)
rain_messages = pftest.Messages(rain_cuda.GetClientSideObject())
pftest.fetch(rain_cuda, 1.0)
text = "\n".join(rain_messages.errors)
pftest.check("Backend CUDA" in text, "Rain with Backend CUDA must be refused by name: %r" % text)
rain_cpu = Rain(Backend="CPU", **rain_settings)
cpu_messages = pftest.Messages(rain_cpu.GetClientSideObject())
pftest.fetch(rain_cpu, 1.0)
rain_cpu.UpdatePropertyInformation()
pftest.check(not cpu_messages.errors, "Rain with Backend CPU: %r" % cpu_messages.errors)
pftest.check(rain_cpu.GetPropertyValue("WaterVolume") > 0, "Rain with Backend CPU made no water")
# With δ-SPH the runoff (on the terrain, a boundary surface) runs on the GPU where there is one.
rain_delta = Rain(Backend="CUDA", PressureSolver="δ-SPH", **rain_settings)
delta_messages = pftest.Messages(rain_delta.GetClientSideObject())
pftest.fetch(rain_delta, 1.0)
rain_delta.UpdatePropertyInformation()
if where.startswith("CPU"):
    text = "\n".join(delta_messages.errors)
    pftest.check("Backend CUDA" in text and "PressureSolver" not in text,
                 "Rain with δ-SPH and Backend CUDA without a GPU must say why (not the solver): %r" % text)
else:
    pftest.check(not delta_messages.errors, "Rain with δ-SPH on the GPU: %r" % delta_messages.errors)
    pftest.check(rain_delta.GetPropertyValue("WaterVolume") > 0, "Rain with δ-SPH on the GPU made no water")
print("ok")
