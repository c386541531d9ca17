"""Image baselines of terrain (rendered under Xvfb, compared with Testing/Terrain/Baselines by VTK's
vtkImageDifference, thresholded error <= 10):
 - terrain_eroded.png: a domain-warped fBm terrain eroded by 60k droplets, its surface coloured by
   elevation with the ParaFluid Terrain preset (Plugins/ParaFluid/TerrainElevation.json);
 - terrain_water.png: SPH water released on a procedural slope eroded by droplets, running down
   it (t = 0.2 s), drawn as spheres over the terrain.
To refresh: PARAFLUID_UPDATE_BASELINE=1 ctest -R terrain_images"""
import os

import numpy as np
from paraview.simple import *
import pftest

pftest.load(globals())
out = pftest.scratch_dir()
SIZE = [400, 300]
PRESET = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Plugins", "ParaFluid",
                      "TerrainElevation.json")
ImportPresets(filename=PRESET)


def view_with(camera_position, focal_point):
    view = CreateRenderView()
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.55, 0.7, 0.9]
    view.CameraPosition = camera_position
    view.CameraFocalPoint = focal_point
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 40.0
    return view


def show_terrain(source, view):
    display = Show(OutputPort(source, 1), view)
    display.SetRepresentationType("Surface")
    ColorBy(display, ("POINTS", "elevation"))
    lut = GetColorTransferFunction("elevation")
    lut.ApplyPreset("ParaFluid Terrain", True)
    display.RescaleTransferFunctionToDataRange(False, True)
    display.Interpolation = "Gouraud"
    return display


def snapshot(view, name):
    Render(view)
    png = os.path.join(out, name)
    SaveScreenshot(png, view, ImageResolution=SIZE)
    pftest.compare_with_baseline(png, name)


terrain = ProceduralTerrain(Extent=[2000, 2000], Resolution=[257, 257], FeatureSize=900, HeightScale=260,
                            WarpStrength=250, WarpScale=700, Seed=11)
eroded = HydraulicErosion(Input=terrain, Drops=60000, Seed=1)
view = view_with([200.0, -700.0, 1100.0], [1000.0, 1000.0, -100.0])
show_terrain(eroded, view)
snapshot(view, "terrain_eroded.png")

slope = HydraulicErosion(Input=ProceduralTerrain(Extent=[0.8, 0.4], Resolution=[41, 21], FeatureSize=0.6,
                                                  HeightScale=0.08, BaseHeight=0.1, Seed=5), Drops=300)
heights = pftest.point_array(pftest.fetch(slope), "elevation").reshape(21, 41)
jm, im = np.unravel_index(np.argmax(heights[4:-4, 4:-4]), heights[4:-4, 4:-4].shape)
cx, cy = (im + 4) * 0.02, (jm + 4) * 0.02
bottom = float(heights[jm:jm + 9, im:im + 9].max()) + 0.01
block = ParticleBlock(Spacing=0.01, BlockBounds=[cx - 0.04, cx + 0.04, cy - 0.04, cy + 0.04, bottom, bottom + 0.04],
                      DomainBounds=[0, 0.8, 0, 0.4, float(heights.min()) - 0.05, float(heights.max()) + 0.2])
water = SPHStep(Input=block, Boundary=OutputPort(slope, 1), OutputInterval=0.1, NumberOfOutputs=3)
view = view_with([0.35, -0.3, 0.4], [0.6, 0.2, 0.08])
show_terrain(slope, view)
drops = Show(water, view)
drops.SetRepresentationType("Points")
drops.RenderPointsAsSpheres = 1
drops.PointSize = 7
drops.ColorArrayName = ["POINTS", ""]
drops.AmbientColor = drops.DiffuseColor = [0.1, 0.3, 0.9]
view.ViewTime = water.TimestepValues[-1]
snapshot(view, "terrain_water.png")
print("terrain images: OK")
