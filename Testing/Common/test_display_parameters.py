"""Every numeric display property of the ParaFluid representations at NaN, +-Inf, 0, -1 and 1e30:
rendering never crashes; a NaN or infinite value is ignored with a warning that names the property
(the picture stays exactly as it was: nothing non-finite reaches a shader); finite values outside a
property's range are clamped to it. (This test found the fluid's clipping bounds lagging one update
behind a change of ParticleRadius.)"""
import math

from paraview.simple import *
from paraview import servermanager
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
from vtkmodules.util.numpy_support import vtk_to_numpy
import numpy as np
import pftest

pftest.load(globals())
BAD = [float("nan"), float("inf"), float("-inf"), 0.0, -1.0, 1e30]
view = CreateRenderView()
view.ViewSize = [160, 120]
view.OrientationAxesVisibility = 0
block = ParticleBlock(BlockBounds=[0, 0.2, 0, 0.1, 0, 0.2], Spacing=0.02)
ocean = GerstnerOcean(Resolution=[32, 32], Size=[20, 20])
rain = Rain(Terrain=ProceduralTerrain(Extent=[2, 2], Resolution=[9, 9], HeightScale=0.2), Runoff=0, RainfallRate=50,
            DropsPerRealDrop=0.05, Cells=[8, 8], PrecipitationHeight=2.0, SplashLifetime=0.5)
clouds = StableFluids(Emitter=0, ProceduralClouds=1, Bounds=[0, 4, 0, 4, 0, 1], Resolution=[32, 32, 8],
                      NumberOfOutputs=0)
SCENES = [(clouds, "Volumetric Cloud", "Cloud"), (block, "Screen-Space Fluid", "Fluid"), (block, "Ray-Marched Fluid", "RayMarch"), (block, "Toon Fluid", "Toon"),
          (block, "Brush Stroke Fluid", "Brush"), (ocean, "Gerstner Ocean", "Ocean"),
          (OutputPort(rain, 0), "Rain", "Rain"), (OutputPort(rain, 2), "Rain Splashes", "Splash")]


def image():
    Render(view)
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.ReadFrontBufferOff()
    grab.Update()
    return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).copy()


failures, cases = [], 0
for source, kind, prefix in SCENES:
    display = Show(source, view)
    display.SetRepresentationType(kind)
    view.ResetCamera()
    warnings = []
    for name in display.ListProperties():
        prop = display.GetProperty(name)
        sm = prop.SMProperty
        if not name.startswith(prefix) or not sm.IsA("vtkSMDoubleVectorProperty") or sm.GetInformationOnly():
            continue
        default = list(prop) if sm.GetNumberOfElements() > 1 else [prop.GetData()]
        # The reference: the property set to its default value again (a change of any property
        # re-runs the representation's update, which is not what is tested here), and passes that
        # read the previous frame (refraction, strokes) settled.
        display.SetPropertyWithName(name, default if len(default) > 1 else default[0])
        before, previous = image(), None
        for _ in range(6):
            if previous is not None and np.array_equal(before, previous):
                break
            previous, before = before, image()
        for bad in BAD:
            values = list(default)
            values[0] = bad
            cases += 1
            display.SetPropertyWithName(name, values if len(values) > 1 else values[0])
            after = image()  # must not crash
            if not math.isfinite(bad) and not np.array_equal(before, after):
                failures.append("%s.%s = %r changed the picture (it must be ignored): %d pixels differ" % (kind, name, bad, int(np.count_nonzero(np.any(before != after, axis=-1)))))
            display.SetPropertyWithName(name, default if len(default) > 1 else default[0])
    Hide(source, view)
# Colours and intensities with a domain: a finite value past its end draws what the end draws (the
# setter clamps to the XML's domain), never black or white water from -1 or 1e30.
CLAMPED = [(ocean, "Gerstner Ocean", ["OceanDeepColor", "OceanShallowColor", "OceanSunColor", "OceanHorizonColor",
                                       "OceanZenithColor", "OceanSunIntensity", "OceanExposure"]),
           (clouds, "Volumetric Cloud", ["CloudSunColor", "CloudSkyColor", "CloudLightIntensity", "CloudExtinction"])]


def settled():
    previous, now = None, image()
    for _ in range(6):
        if previous is not None and np.array_equal(previous, now):
            break
        previous, now = now, image()
    return now


for source, kind, names in CLAMPED:
    display = Show(source, view)
    display.SetRepresentationType(kind)
    view.ResetCamera()
    for name in names:
        prop = display.GetProperty(name)
        domain = prop.SMProperty.GetDomain("range")
        default = list(prop) if prop.SMProperty.GetNumberOfElements() > 1 else [prop.GetData()]
        for bad, end in ((1e30, domain.GetMaximum(0)), (-1.0, domain.GetMinimum(0))):
            cases += 1
            display.SetPropertyWithName(name, [end] * len(default) if len(default) > 1 else end)
            at_end = settled()
            display.SetPropertyWithName(name, [bad] * len(default) if len(default) > 1 else bad)
            past = settled()
            if not np.array_equal(at_end, past):
                failures.append("%s.%s = %r does not draw what %r draws: %d pixels differ" % (
                    kind, name, bad, end, int(np.count_nonzero(np.any(at_end != past, axis=-1)))))
        display.SetPropertyWithName(name, default if len(default) > 1 else default[0])
    Hide(source, view)

for failure in failures:
    print(failure)
pftest.check(not failures, "%d of %d display cases failed" % (len(failures), cases))
print("display parameters: %d cases, none crashed" % cases)
