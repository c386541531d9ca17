"""The README's clouds picture (docs/clouds.png, 1280 x 720): procedural cumulus (Stable Fluids'
start) drawn by the Volumetric Cloud representation over a procedural terrain and a Gerstner ocean
in one view, and smoke rising from a valley (Stable Fluids at t = 3 s, same representation).
Run: PARAFLUID_PLUGIN=build/lib/paraview-5.11/plugins/ParaFluid/ParaFluid.so PYTHONPATH=Testing/Python \\
     scripts/with-xvfb.sh pvpython scripts/clouds_picture.py [out.png]"""
import sys

from paraview.simple import *
import pftest

pftest.load(globals())
png = sys.argv[1] if len(sys.argv) > 1 else "docs/clouds.png"
view = CreateRenderView()
view.ViewSize = [1280, 720]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.BackgroundColorMode = "Gradient"
view.Background2 = [0.25, 0.45, 0.8]
view.Background = [0.72, 0.82, 0.92]

land = ProceduralTerrain(Extent=[2000, 2000], Resolution=[257, 257], FeatureSize=900.0, HeightScale=260.0,
                         Seed=11, BaseHeight=40.0)
ground = Show(OutputPort(land, 1), view)
ground.SetRepresentationType("Surface")
ColorBy(ground, None)
ground.AmbientColor = ground.DiffuseColor = [0.42, 0.47, 0.3]

sea = Plane(Origin=[-2000, -2000, 0], Point1=[4000, -2000, 0], Point2=[-2000, 4000, 0], XResolution=256,
            YResolution=256)
water = Show(sea, view)
water.SetRepresentationType("Gerstner Ocean")

sky = StableFluids(Emitter=0, ProceduralClouds=1, CloudCoverage=0.45, CloudFeatureSize=700.0, CloudSeed=5,
                   Bounds=[-600, 2600, -600, 2600, 350, 950], Resolution=[192, 192, 36], NumberOfOutputs=0)
clouds = Show(sky, view)
clouds.SetRepresentationType("Volumetric Cloud")
clouds.CloudExtinction = 0.06
clouds.CloudLightMode = "Sun"
clouds.CloudSunElevation = 40
clouds.CloudSunAzimuth = -120
clouds.CloudStepSize = 0.35

smoke = StableFluids(Bounds=[900, 1300, 900, 1300, 0, 600], Resolution=[32, 32, 48], TimeStep=0.5, OutputInterval=4.0,
                     NumberOfOutputs=6, EmitterBox=[1060, 1140, 1060, 1140, 0, 200], EmitterSpeed=6.0,
                     BuoyancyHeat=0.3, Vorticity=0.4)
plume = Show(smoke, view)
plume.SetRepresentationType("Volumetric Cloud")
plume.CloudExtinction = 0.15
plume.CloudAlbedo = 0.6
plume.CloudLightMode = "Sun"
plume.CloudSunElevation = 40
plume.CloudSunAzimuth = -120
plume.CloudStepSize = 0.25
view.ViewTime = 24.0

Render(view)
view.CameraPosition = [1000, -1100, 480]
view.CameraFocalPoint = [1000, 1000, 330]
view.CameraViewUp = [0, 0, 1]
view.CameraViewAngle = 55
Render(view)
SaveScreenshot(png, view, ImageResolution=[1280, 720])
print("wrote", png)
