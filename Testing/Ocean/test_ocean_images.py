"""Image baselines of the Gerstner Ocean representation (rendered under Xvfb, compared with
Testing/Ocean/Baselines by VTK's vtkImageDifference, thresholded error <= 10):
 - ocean_storm_environment.png: a deep storm sea reflecting a cube map environment (six faces the
   test generates: a sky gradient with a sun and cloud bands);
 - ocean_beach_breaking.png: waves running onto a sloping beach given as a floor-elevation array
   on the plane: shorter, steeper, turning to the shore, breaking with foam in the shallows;
 - ocean_night.png: a swell under a dim moon and a dark sky with automatic exposure.
To refresh: PARAFLUID_UPDATE_BASELINE=1 ctest -R ocean_images"""
import math
import os

import numpy as np
from paraview.simple import *
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.util.numpy_support import numpy_to_vtk
import pftest

pftest.load(globals())
out = pftest.scratch_dir()
SIZE = [400, 300]


def write_png(path, rgb):
    image = vtkImageData()
    image.SetDimensions(rgb.shape[1], rgb.shape[0], 1)
    # VTK images start at the bottom row.
    image.GetPointData().SetScalars(numpy_to_vtk(np.ascontiguousarray(rgb[::-1].reshape(-1, 3)), deep=True))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def cube_faces(n=64):
    """Six faces (+X, -X, +Y, -Y, +Z, -Z; face +Y is world up) of a sky: blue gradient with
    horizontal cloud bands, a sun towards world +x +y, dark sea-coloured ground."""
    faces = []
    u = (np.arange(n) + 0.5) / n * 2.0 - 1.0
    a, b = np.meshgrid(u, -u)  # a: right, b: up, in each face's image
    for face in range(6):
        one = np.ones_like(a)
        # Cube-map direction of each texel (OpenGL convention), then world = (x, -z, y).
        d = [(one, -b, -a), (-one, -b, a), (a, one, b), (a, -one, -b), (a, -b, one), (-a, -b, -one)][face]
        x, y, z = d
        length = np.sqrt(x * x + y * y + z * z)
        wx, wy, wz = x / length, -z / length, y / length
        up = np.clip(wz, 0.0, 1.0)
        sky = np.stack([0.35 + 0.2 * (1 - up), 0.55 + 0.2 * (1 - up), 0.9 + 0.05 * (1 - up)], -1)
        clouds = 0.5 + 0.5 * np.sin(18.0 * np.arctan2(wy, wx)) * np.sin(25.0 * up)
        sky = sky * (1 - 0.35 * clouds[..., None] * (up[..., None] > 0.05)) + 0.35 * clouds[..., None] * (up[..., None] > 0.05)
        sun = np.exp(-((wx - 0.6) ** 2 + (wy - 0.6) ** 2 + (wz - 0.53) ** 2) * 200.0)
        sky = np.clip(sky + sun[..., None], 0.0, 1.0)
        ground = np.array([0.05, 0.08, 0.1])
        rgb = np.where((wz < 0.0)[..., None], ground, sky)
        faces.append((255 * rgb).astype(np.uint8))
    paths = []
    for k, face in enumerate(faces):
        path = os.path.join(out, "sky%d.png" % k)
        write_png(path, face)
        paths.append(path)
    return paths


def render(name, setup, camera, time):
    view = CreateRenderView()
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    plane = setup(view)
    Render(view)
    view.CameraPosition, view.CameraFocalPoint = camera
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 45.0
    GetTimeKeeper().Time = time
    view.ViewTime = time
    png = os.path.join(out, name)
    SaveScreenshot(png, view, ImageResolution=SIZE)
    pftest.compare_with_baseline(png, name)
    Delete(view)


def storm(view):
    plane = Plane(Origin=[0.0, 0.0, 0.0], Point1=[300.0, 0.0, 0.0], Point2=[0.0, 300.0, 0.0], XResolution=300, YResolution=300)
    d = Show(plane, view)
    d.SetRepresentationType("Gerstner Ocean")
    d.ColorArrayName = [None, ""]
    d.OceanSeaState = "Storm"
    d.OceanWindDirection = 80.0
    d.OceanWindLean = 0.4
    d.OceanEnvironmentImages = cube_faces()
    d.OceanSunAzimuth = 45.0
    d.OceanSunElevation = 32.0
    return plane


def beach(view):
    plane = Plane(Origin=[0.0, 0.0, 0.0], Point1=[240.0, 0.0, 0.0], Point2=[0.0, 120.0, 0.0], XResolution=480, YResolution=240)
    # Floor from 8 m deep at x = 0 up to 1 m of dry land at x = 240, with a shallow bar.
    floor = Calculator(Input=plane, ResultArrayName="Elevation",
                       Function="-8 + 9 * coordsX / 240 + 0.6 * exp(-((coordsX - 150) / 15)^2)")
    d = Show(floor, view)
    d.SetRepresentationType("Gerstner Ocean")
    d.ColorArrayName = [None, ""]
    d.OceanSeaState = "Custom (wave list)"
    d.OceanWaves = [0.45, 30.0, 20.0, 0.6, 0.0, 0.2, 18.0, -10.0, 0.5, 1.0]
    d.OceanBathymetryArray = "Elevation"
    d.OceanBathymetryResolution = 240
    d.OceanSunAzimuth = 150.0
    d.OceanSunElevation = 40.0
    return floor


def night(view):
    plane = Plane(Origin=[0.0, 0.0, 0.0], Point1=[300.0, 0.0, 0.0], Point2=[0.0, 300.0, 0.0], XResolution=300, YResolution=300)
    d = Show(plane, view)
    d.SetRepresentationType("Gerstner Ocean")
    d.ColorArrayName = [None, ""]
    d.OceanSeaState = "Swell"
    d.OceanSunColor = [0.75, 0.85, 1.0]   # moonlight
    d.OceanSunIntensity = 0.06
    d.OceanSunElevation = 18.0
    d.OceanSunAzimuth = 90.0
    d.OceanHorizonColor = [0.012, 0.016, 0.03]
    d.OceanZenithColor = [0.002, 0.004, 0.012]
    d.OceanAutoExposure = 1
    return plane


render("ocean_storm_environment.png", storm, ([150.0, 20.0, 14.0], [150.0, 150.0, 0.0]), 4.0)
render("ocean_beach_breaking.png", beach, ([30.0, 20.0, 12.0], [200.0, 70.0, 0.0]), 6.0)
render("ocean_night.png", night, ([150.0, 20.0, 10.0], [150.0, 150.0, 0.0]), 2.0)
print("ocean images: ok")
