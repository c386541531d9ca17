"""Images of rain under Xvfb: baselines in Testing/Rain/Baselines (VTK's vtkImageDifference,
thresholded error <= 10), and what the pictures must show:
 - rain_dark.png, rain_bright.png: the same drops in a dark and a bright environment (cube maps),
   in front of the same grey background, take the environment's light (darker, brighter than
   the background), by precomputed radiance transfer;
 - under a constant environment (six mid-grey cube-map faces) every pixel of every drop has the
   same colour (Radiance display: no alpha);
 - rain_splashes.png: splashes on a 35-degree slope (the sloped sequence, leaning downhill);
 - rain_demo.png: the demo's frame (scripts/rain_scene.py): terrain, rain, splashes, runoff;
 - the streaks drawn on the CPU (RainRasteriser 'CPU', what 'Automatic' picks under llvmpipe, so
   the baselines are its images) and on the GPU (a triangle per drop) are the same picture, a wall
   in front hiding the same drops in both; in a multisampled framebuffer, whose depth cannot be
   read back, the CPU path hands the streaks to the GPU path.
To refresh: PARAFLUID_UPDATE_BASELINE=1 ctest -R rain_images"""
import os
import sys

import numpy as np
from paraview.simple import *
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.util.numpy_support import vtk_to_numpy, numpy_to_vtk
import pftest

pftest.load(globals())
LoadPlugin(pftest.plugin_path())  # into paraview.simple too, for rain_scene
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import rain_scene  # noqa: E402

out = pftest.scratch_dir()
SIZE = [400, 300]


def pixels(png):
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3].astype(float)


def snapshot(view, name, baseline=True):
    Render(view)
    png = os.path.join(out, name)
    SaveScreenshot(png, view, ImageResolution=SIZE)
    if baseline:
        pftest.compare_with_baseline(png, name)
    return pixels(png)


def rain_view(background):
    view = CreateRenderView()
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = background
    view.CameraPosition = [1.0, -2.5, 1.0]
    view.CameraFocalPoint = [1.0, 1.0, 0.8]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 40.0
    return view


flat = ProceduralTerrain(Extent=[2, 2], Resolution=[9, 9], HeightScale=0.0)
rain = Rain(Terrain=flat, Runoff=0, RainfallRate=50, DropsPerRealDrop=0.2, Cells=[16, 16], PrecipitationHeight=2.0,
            OutputInterval=0.1, NumberOfOutputs=10)


def show_rain(view, **settings):
    view.ViewTime = 0.5
    display = Show(OutputPort(rain, 0), view)
    display.SetRepresentationType("Rain")
    display.RainWidthScale = 4.0
    for key, value in settings.items():
        setattr(display, key, value)
    Render(view)
    view.CameraPosition = [1.0, -2.5, 1.0]
    view.CameraFocalPoint = [1.0, 1.0, 0.8]
    return display


def cube_faces(name, rgb):
    """Six uniform square faces of colour `rgb` (0-255) written as PNGs; their paths."""
    paths = []
    for face in range(6):
        image = vtkImageData()
        image.SetDimensions(8, 8, 1)
        image.GetPointData().SetScalars(numpy_to_vtk(np.tile(np.array(rgb, dtype=np.uint8), (64, 1))))
        path = os.path.join(out, "%s%d.png" % (name, face))
        writer = vtkPNGWriter()
        writer.SetFileName(path)
        writer.SetInputData(image)
        writer.Write()
        paths.append(path)
    return paths


# The same drops in a dark and in a bright environment (cube maps), in front of the same grey
# background: the drops take the environment's light.
GREY = [0.5, 0.5, 0.5]
means = {}
for name, rgb in (("dark", [15, 15, 25]), ("bright", [235, 240, 250])):
    view = rain_view(GREY)
    show_rain(view, RainEnvironmentImages=cube_faces(name, rgb))
    image = snapshot(view, "rain_%s.png" % name)
    streak = np.abs(image - 127.5).sum(axis=2) > 6.0
    pftest.check(streak.sum() > 500, "%s: streaks cover %d pixels" % (name, streak.sum()))
    means[name] = image[streak].mean()
    print("%s environment: %d streak pixels, mean level %.1f" % (name, streak.sum(), means[name]))
pftest.check(means["dark"] < 127.5 < means["bright"], "drops take the environment's light: %r" % means)

# The CPU and the GPU paths draw the same streaks; a wall in front of the left of the rain hides
# them in both (the CPU path reads the scene's depth back).
view = rain_view(GREY)
display = show_rain(view, RainEnvironmentImages=cube_faces("bright", [235, 240, 250]))
wall = Box(Center=[0.6, -0.2, 0.8], XLength=0.6, YLength=0.05, ZLength=2.0)
Show(wall, view).DiffuseColor = [0.2, 0.5, 0.2]
images = {}
for rasteriser in ("GPU", "CPU"):
    display.RainRasteriser = rasteriser
    images[rasteriser] = snapshot(view, "rain_%s.png" % rasteriser.lower(), baseline=False)
    display.UpdatePropertyInformation()
    on_cpu = display.GetPropertyValue("RainDrawnOnCpu") == 1
    pftest.check(on_cpu == (rasteriser == "CPU"), "%s rasteriser: drawn on the CPU = %s" % (rasteriser, on_cpu))
gpu, cpu = images["GPU"], images["CPU"]
drawn = np.abs(gpu - 127.5).sum(axis=2) > 6.0
difference = np.abs(gpu - cpu)
print("CPU against GPU streaks: %d streak pixels, mean difference %.3f levels, 99.9th percentile %.1f, largest %.0f"
      % (drawn.sum(), difference.mean(), np.percentile(difference, 99.9), difference.max()))
pftest.check(drawn.sum() > 500, "GPU path: %d streak pixels" % drawn.sum())
pftest.check(difference.mean() < 0.25 and np.percentile(difference, 99.9) <= 4.0,
             "the CPU streaks differ from the GPU's: mean %.3f, 99.9th percentile %.1f levels"
             % (difference.mean(), np.percentile(difference, 99.9)))
wall_pixels = np.all(np.abs(gpu - np.array([0.2, 0.5, 0.2]) * 255.0) < 60.0, axis=2)
pftest.check(wall_pixels.sum() > 1000, "the wall covers %d pixels" % wall_pixels.sum())
pftest.check(difference[wall_pixels].max() <= 1.0, "behind the wall the CPU path differs by %.0f levels"
             % difference[wall_pixels].max())

# Multisampled: the depth of the scene cannot be read back, so the streaks go to the GPU path.
view = rain_view(GREY)
view.GetRenderWindow().SetMultiSamples(4)
display = show_rain(view, RainEnvironmentImages=cube_faces("bright", [235, 240, 250]))
images = {}
for rasteriser in ("GPU", "CPU"):
    display.RainRasteriser = rasteriser
    images[rasteriser] = snapshot(view, "rain_multisampled_%s.png" % rasteriser.lower(), baseline=False)
    display.UpdatePropertyInformation()
    pftest.check(display.GetPropertyValue("RainDrawnOnCpu") == 0,
                 "multisampled, %s rasteriser: drawn on the CPU" % rasteriser)
drawn = np.abs(images["GPU"] - 127.5).sum(axis=2) > 6.0
pftest.check(drawn.sum() > 500 and np.array_equal(images["GPU"], images["CPU"]),
             "multisampled: %d streak pixels; the CPU request drew another picture than the GPU path" % drawn.sum())

# A constant environment (mid grey, so no colour is clipped): every pixel of every drop the same.
view = rain_view([0.0, 0.0, 0.0])
show_rain(view, RainDisplayMode="Radiance", RainEnvironmentImages=cube_faces("grey", [128, 128, 128]))
image = snapshot(view, "rain_constant.png", baseline=False)
drop = image.sum(axis=2) > 0
colours = np.unique(image[drop].reshape(-1, 3), axis=0)
pftest.check(drop.sum() > 500, "constant environment: %d drop pixels" % drop.sum())
pftest.check(len(colours) == 1, "constant environment: drop pixels of %d colours: %s" % (len(colours), colours[:5]))
print("constant environment: %d drop pixels, all %s" % (drop.sum(), colours[0]))

# Splashes on a 35-degree slope.
slope = Plane(Origin=[0, 0, 0], Point1=[2, 0, -1.4], Point2=[0, 2, 0], XResolution=8, YResolution=8)
splashing = Rain(Terrain=slope, Runoff=0, RainfallRate=50, DropsPerRealDrop=0.05, Cells=[16, 16],
                 PrecipitationHeight=2.0, ImpactResolution=[32, 32], SplashLifetime=0.2, OutputInterval=0.1,
                 NumberOfOutputs=10)
view = rain_view([0.55, 0.6, 0.68])
view.ViewTime = 0.5
ground = Show(slope, view)
ground.DiffuseColor = [0.35, 0.3, 0.25]
splashes = Show(OutputPort(splashing, 2), view)
splashes.SetRepresentationType("Rain Splashes")
splashes.SplashSize = 0.15
splashes.SplashLifetime = 0.2
Render(view)
view.CameraPosition = [1.0, -1.8, 1.2]
view.CameraFocalPoint = [1.0, 1.0, -0.7]
splashing.UpdatePipeline(0.5)
slopes = pftest.point_array(servermanager.Fetch(splashing, idx=2), "slope")
pftest.check(np.all(np.abs(slopes - 35.0) < 0.5), "splash slopes %g..%g deg" % (slopes.min(), slopes.max()))
snapshot(view, "rain_splashes.png")

# The demo's frame.
terrain, storm = rain_scene.build(outputs=45)
view = CreateRenderView()
view.ViewSize = SIZE
rain_scene.show(terrain, storm, view, storm.TimestepValues[-1])
snapshot(view, "rain_demo.png")
print("rain images: done")
