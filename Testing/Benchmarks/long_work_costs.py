"""The per-unit costs behind the long-work estimates (Filters/Common/LongWork: each filter's
nominal cost on the 2-core machine) and the two cases of issue 65 whose cost a setting made
explode. Run under Xvfb (the Rain frame renders):

  PARAFLUID_PLUGIN=build/lib/paraview-5.11/plugins/ParaFluid/ParaFluid.so OMP_WAIT_POLICY=PASSIVE \\
    scripts/with-xvfb.sh pvpython Testing/Benchmarks/long_work_costs.py
"""
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from paraview.simple import *  # noqa: E402
import pftest  # noqa: E402

pftest.load(globals())


def seconds(proxy, t=None):
    start = time.time()
    proxy.UpdatePipeline() if t is None else proxy.UpdatePipeline(t)
    return time.time() - start


terrain = ProceduralTerrain()
terrain.UpdatePipeline()
small = ProceduralTerrain(Extent=[2, 2], Resolution=[33, 33], FeatureSize=1.5, HeightScale=0.3, Seed=5)
small.UpdatePipeline()
print("droplet erosion, 257^2, 64-step drops: %.2e s a drop" % (seconds(HydraulicErosion(Input=terrain, Drops=400000)) / 4e5))
print("pipe erosion, 257^2: %.2e s a cell and iteration" %
      (seconds(HydraulicErosion(Input=terrain, Method=1, Iterations=2000)) / 2000 / 257 ** 2))
print("pipe erosion, 33^2: %.2e s an iteration" % (seconds(HydraulicErosion(Input=small, Method=1, Iterations=20000)) / 2e4))
print("Stable Fluids, 64^3 defaults: %.2e s a cell and step" % (seconds(StableFluids(), 0.5) / 25 / 64 ** 3))
print("Rain, 33^2 terrain, 10 s of drop steps: %.2e s a step" %
      (seconds(Rain(Terrain=small, DropsPerRealDrop=0.01, PrecipitationHeight=2.0), 10.0) / 600))
block = ParticleBlock(BlockBounds=[0, 1, 0, 1, 0, 0.5], Spacing=0.01, DomainBounds=[0, 1, 0, 1, 0, 1])
block.UpdatePipeline()
n = block.GetDataInformation().GetNumberOfPoints()
stepped = SPHStep(Input=block, OutputInterval=0.002, NumberOfOutputs=1)
stepped.UpdatePipeline(0.002)
for name, proxy in (("Particle Surface", ParticleSurfaceMarchingCubes(Input=block)),
                    ("Fluid Flow Lines", FluidFlowLines(Input=stepped))):
    print("%s, %d particles: %.2e s a particle" % (name, n, seconds(proxy, 0.002) / n))
print("Gerstner Ocean, 1024^2: %.2e s a vertex" % (seconds(GerstnerOcean(Resolution=[1024, 1024]), 0.0) / 1024 ** 2))

# The cases whose cost a setting made explode.
fast = StableFluids(Resolution=[24, 24, 24], OpenFaces=[1] * 6, EmitterSpeed=1000)
print("Stable Fluids, 24^3 open, 1000 m/s emitter, to t = 0.5 s: %.1f s" % seconds(fast, 0.5))
flat = ProceduralTerrain(Extent=[4, 4], Resolution=[9, 9], HeightScale=0.0)
rain = Rain(Terrain=flat, Runoff=0, PrecipitationHeight=2.0)
view = CreateView("RenderView")
view.ViewSize = [400, 300]
view.ViewTime = 0.5
display = Show(OutputPort(rain, 0), view)
display.SetRepresentationType("Rain")
Render(view)
for width in (1.0, 1000.0):
    display.RainWidthScale = width
    Render(view)
    start = time.time()
    view.StillRender()
    print("Rain representation, %d drops, 400 x 300, RainWidthScale %g: %.3f s a frame" %
          (rain.GetDataInformation().GetNumberOfPoints(), width, time.time() - start))
