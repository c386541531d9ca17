"""Image baselines of clouds and smoke (rendered under Xvfb, compared with Testing/Clouds/Baselines
by VTK's vtkImageDifference, thresholded error <= 10):
 - cumulus_noon.png: procedural cumulus (Stable Fluids' start) lit by a high white sun from
   behind the camera, under a blue sky;
 - cumulus_sunset.png: the same clouds lit by a low orange sun in front of the camera (silver
   linings, dark bases);
 - smoke_over_terrain.png: smoke rising from an emitter in a valley of a procedural terrain
   (Stable Fluids, t = 2 s), the terrain drawn as a surface in the same view: it hides the smoke
   behind its ridges.
The noon image's march is also checked against a march at 1/16 of its step (sampling noise, RMS).
To refresh: PARAFLUID_UPDATE_BASELINE=1 ctest -R cloud_images"""
import os

import numpy as np

from paraview.simple import *
import pftest

pftest.load(globals())
out = pftest.scratch_dir()
SIZE = [400, 300]


def sky_view(background):
    view = CreateRenderView()
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = background
    return view


def place(view, position, focal):
    Render(view)
    view.CameraPosition = position
    view.CameraFocalPoint = focal
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 40.0


def save_and_compare(view, name):
    png = os.path.join(out, name)
    SaveScreenshot(png, view, ImageResolution=SIZE)
    pftest.compare_with_baseline(png, name)


def check_sampling_noise(view, shown, background):
    """The march at its default step against one at 1/16 of it (the reference), over the cloud's
    pixels: the RMS difference is the march's sampling noise. Strides of four steps through thin
    air that integrated a cloud's edge over the whole stride drew, with the jitter's pattern,
    cross-hatching in the thin cloud between the domes: RMS 6.4 levels; stepping back to the fine
    stride in cloud, with strides of at most two steps: 3.3."""
    marched = pftest.grab(view).astype(float)
    default_step = shown.CloudStepSize
    shown.CloudStepSize = default_step / 16.0
    shown.CloudMaxSteps = 100000
    reference = pftest.grab(view).astype(float)
    shown.CloudStepSize = default_step
    cloud = np.abs(reference - np.array(background) * 255.0).sum(axis=2) > 6.0
    rms = float(np.sqrt(((marched - reference)[cloud] ** 2).mean()))
    print("sampling noise at the default step over %d cloud pixels: RMS %.2f levels" % (cloud.sum(), rms))
    pftest.check(rms <= 4.5, "the march's sampling noise is at most 4.5 levels RMS (%.2f)" % rms)


cumulus = StableFluids(Emitter=0, ProceduralClouds=1, CloudCoverage=0.5, CloudFeatureSize=3.0, CloudSeed=3,
                       Bounds=[0, 8, 0, 8, 0, 2], Resolution=[96, 96, 24], NumberOfOutputs=0)
for name, background, sun in (("cumulus_noon.png", [0.42, 0.6, 0.86], dict(CloudSunElevation=65, CloudSunAzimuth=-100,
                                                                             CloudSunColor=[1.0, 0.98, 0.95])),
                              ("cumulus_sunset.png", [0.85, 0.55, 0.4], dict(CloudSunElevation=6, CloudSunAzimuth=95,
                                                                            CloudSunColor=[1.0, 0.55, 0.25],
                                                                            CloudSkyColor=[0.3, 0.22, 0.3]))):
    view = sky_view(background)
    shown = Show(cumulus, view)
    shown.SetRepresentationType("Volumetric Cloud")
    shown.CloudLightMode = "Sun"
    shown.CloudLightIntensity = 12.0
    for key, value in sun.items():
        setattr(shown, key, value)
    place(view, [4.0, -7.0, 0.3], [4.0, 4.0, 1.6])
    save_and_compare(view, name)
    if name == "cumulus_noon.png":
        check_sampling_noise(view, shown, background)
    Delete(view)

terrain = ProceduralTerrain(Extent=[4, 4], Resolution=[129, 129], FeatureSize=2.0, HeightScale=0.8, Seed=7)
smoke = StableFluids(Bounds=[0, 4, 0, 4, 0, 3], Resolution=[48, 48, 36], TimeStep=0.04, OutputInterval=0.5,
                     NumberOfOutputs=4, EmitterBox=[1.8, 2.2, 1.8, 2.2, 0.0, 0.4], EmitterSpeed=0.8,
                     Vorticity=0.4)
view = sky_view([0.55, 0.7, 0.9])
ground = Show(OutputPort(terrain, 1), view)
ground.SetRepresentationType("Surface")
ColorBy(ground, None)
ground.AmbientColor = ground.DiffuseColor = [0.45, 0.5, 0.35]
plume = Show(smoke, view)
plume.SetRepresentationType("Volumetric Cloud")
plume.CloudExtinction = 6.0
plume.CloudAlbedo = 0.7
plume.CloudLightMode = "Sun"
plume.CloudLightIntensity = 8.0
view.ViewTime = 2.0
place(view, [2.0, -4.5, 2.2], [2.0, 2.0, 1.0])
save_and_compare(view, "smoke_over_terrain.png")
print("cloud images: OK")
