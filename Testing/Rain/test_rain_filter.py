"""The Rain filter in pvpython: its three outputs and their arrays, the water it inserts equal to the
rain that fell, time awareness (forward continues, back gives the output already made), a surface as
the terrain, drops and splashes without runoff, and errors that name the property."""
import numpy as np
import os

from paraview.simple import *
from paraview import servermanager
import pftest

pftest.load(globals())


def fetch(proxy, port, time):
    proxy.UpdatePipeline(time)
    return servermanager.Fetch(proxy, idx=port)


def info(proxy, name):
    proxy.UpdatePropertyInformation()
    return proxy.GetProperty(name).GetData()


terrain = ProceduralTerrain(Extent=[2, 2], Resolution=[33, 33], FeatureSize=1.5, HeightScale=0.3, Seed=5)
rain = Rain(Terrain=terrain, RainfallRate=2000, DropsPerRealDrop=0.01, ParticleSpacing=0.03, Cells=[8, 8],
            PrecipitationHeight=2.0, OutputInterval=0.1, NumberOfOutputs=20)
times = rain.TimestepValues
pftest.check(len(times) == 21 and abs(times[-1] - 2.0) < 1e-9, "time steps %s" % (times,))

drops = fetch(rain, 0, 1.0)
pftest.check(drops.GetNumberOfPoints() > 500, "drops: %d" % drops.GetNumberOfPoints())
for name in ("velocity", "diameter", "streak_length"):
    pftest.point_array(drops, name)
d = pftest.point_array(drops, "diameter")
pftest.check(d.min() >= 0.2e-3 and d.max() <= 6e-3, "diameters %g..%g m" % (d.min(), d.max()))
v = pftest.point_array(drops, "velocity")
speed = np.linalg.norm(v, axis=1)
streak = pftest.point_array(drops, "streak_length")
pftest.check(np.allclose(streak, speed / 60.0, rtol=1e-4), "streak_length = speed x ExposureTime (1/60 s)")
# Terminal speeds (Atlas et al. 1973) of the diameters drawn.
terminal = np.maximum(9.65 - 10.3 * np.exp(-0.6 * d * 1e3), 0.1)
pftest.check(np.allclose(-v[:, 2], terminal, rtol=1e-4), "drops fall at the terminal speed of their diameter")
pts = pftest.points(drops)
pftest.check(pts[:, 2].max() <= 2.0 + 0.3 + 1e-3, "drops start at the precipitation height")

water = fetch(rain, 1, 2.0)
n = water.GetNumberOfPoints()
pftest.check(n > 50, "water particles: %d" % n)
for name in ("velocity", "density", "id"):
    pftest.point_array(water, name)
fd = water.GetFieldData()
pftest.check(abs(fd.GetArray("particle_spacing").GetValue(0) - 0.03) < 1e-12, "particle_spacing field data")
fallen, volume = info(rain, "FallenVolume"), info(rain, "WaterVolume")
pftest.check(abs(volume - n * 0.03 ** 3) < 1e-12, "WaterVolume = particles x d^3")
# ConserveVolume: within one particle's volume of the rain that fell on the whole terrain.
pftest.check(0 <= fallen - volume < 0.03 ** 3, "fallen %g m^3, water %g m^3" % (fallen, volume))
ids = pftest.point_array(water, "id")
pftest.check(len(np.unique(ids)) == n, "ids are unique")

splashes = fetch(rain, 2, 2.0)
pftest.check(splashes.GetNumberOfPoints() > 10, "splashes: %d" % splashes.GetNumberOfPoints())
for name in ("age", "normal", "slope", "impact_angle", "on_water"):
    pftest.point_array(splashes, name)
age = pftest.point_array(splashes, "age")
pftest.check(age.min() >= 0 and age.max() <= 0.1 + 1e-9, "splash ages within SplashLifetime")

# Back in time: the output already made; the same time again gives the same water.
first = pftest.points(fetch(rain, 1, 1.0)).copy()
fetch(rain, 1, 2.0)
again = pftest.points(fetch(rain, 1, 1.0))
pftest.check(first.shape == again.shape and np.array_equal(first, again), "going back gives the same state")

# A surface as the terrain (the terrain source's warped surface), rasterised.
on_surface = Rain(Terrain=OutputPort(terrain, 1), RainfallRate=2000, DropsPerRealDrop=0.01, ParticleSpacing=0.03,
                  Cells=[8, 8], PrecipitationHeight=2.0, ImpactResolution=[64, 64], OutputInterval=0.1,
                  NumberOfOutputs=20)
surface_water = fetch(on_surface, 1, 2.0)
pftest.check(abs(surface_water.GetNumberOfPoints() - n) <= 0.1 * n,
             "a surface terrain gives the same water: %d vs %d" % (surface_water.GetNumberOfPoints(), n))

# A new user's first rain on a plane a metre square: at 100 mm/h each of the 64 x 64 cells gathers a
# hundredth of a particle in 10 s, yet the rain that fell is in the water within one particle.
plane = Plane(Origin=[0, 0, 0], Point1=[1, 0, 0], Point2=[0, 1, 0], XResolution=10, YResolution=10)
light = Rain(Terrain=plane, RainfallRate=100, PrecipitationBounds=[0, 1, 0, 1], PrecipitationHeight=2,
             OutputInterval=1.0, NumberOfOutputs=10)
fetch(light, 1, 10.0)
fallen, volume = info(light, "FallenVolume"), info(light, "WaterVolume")
pftest.check(fallen > 2e-4 and 0 <= fallen - volume < 0.05 ** 3,
             "100 mm/h for 10 s: fallen %g m^3, water %g m^3" % (fallen, volume))
Delete(light)

# A time past the end (infinity too) is the last output, not the first; NaN is refused by name.
pftest.check(np.array_equal(pftest.points(fetch(rain, 1, float("inf"))), pftest.points(fetch(rain, 1, times[-1]))),
             "t = inf gives the last output")
messages = pftest.Messages(rain.GetClientSideObject())
rain.UpdatePipeline(float("nan"))
pftest.check(any("Rain" in e and "not a number" in e for e in messages.errors), "NaN time: %r" % (messages.errors,))

# Without runoff: drops and splashes only, any time at once.
dry = Rain(Terrain=terrain, Runoff=0, RainfallRate=2000, DropsPerRealDrop=0.01, Cells=[8, 8], PrecipitationHeight=2.0,
           OutputInterval=0.1, NumberOfOutputs=1000)
pftest.check(fetch(dry, 1, 90.0).GetNumberOfPoints() == 0, "no water without runoff")
pftest.check(fetch(dry, 0, 90.0).GetNumberOfPoints() > 500, "drops at t = 90 s without stepping")

# Errors name the property.
for prop, value, word in (("PrecipitationHeight", 0.05, "PrecipitationHeight"), ("Cells", [0, 8], "Cells"),
                          ("RainfallRate", -1.0, "RainfallRate"), ("ParticleSpacing", 0.0, "ParticleSpacing")):
    bad = Rain(Terrain=terrain, Cells=[8, 8], PrecipitationHeight=2.0, DropsPerRealDrop=0.01)
    bad.SetPropertyWithName(prop, value)
    messages = pftest.Messages(bad.GetClientSideObject())
    bad.UpdatePipeline(0.0)
    pftest.check(any(word in e for e in messages.errors), "%s = %r: errors %r" % (prop, value, messages.errors))
    Delete(bad)
# An ImpactResolution whose ground and runoff exceed the memory budget is refused before anything
# is allocated, naming the property and the bytes (8192 x 8192 reached 6 GB and a bare bad_alloc).
os.environ["PARAFLUID_MEMORY_BUDGET_MB"] = "2000"
huge = Rain(Terrain=OutputPort(terrain, 1), ImpactResolution=[8192, 8192], PrecipitationHeight=2.0,
            DropsPerRealDrop=0.01)
messages = pftest.Messages(huge.GetClientSideObject())
huge.UpdatePipeline(0.0)
del os.environ["PARAFLUID_MEMORY_BUDGET_MB"]
text = "\n".join(messages.errors)
pftest.check("ImpactResolution" in text and "GB" in text and "bad_alloc" not in text,
             "ImpactResolution over the budget: %r" % text)
huge.ImpactResolution = [64, 64]
huge.UpdatePipeline(0.0)
pftest.check(huge.GetDataInformation().GetNumberOfPoints() > 0, "Rain runs after lowering ImpactResolution")
print("rain filter: %d drops, %d particles, %d splashes" % (drops.GetNumberOfPoints(), n, splashes.GetNumberOfPoints()))
