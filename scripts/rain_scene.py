"""The rain demo's scene, shared by scripts/demo_rain.py and the image test Python.rain_images:
a 4 m procedural terrain under a cloudburst whose runoff gathers in its hollows, drawn with the Rain
(PRT-lit streaks), Rain Splashes and Screen-Space Fluid representations."""
from paraview import simple
from paraview.simple import OutputPort, Show, ColorBy

SEED = 3


def build(rainfall=1500.0, spacing=0.025, drops_per_real_drop=0.05, interval=1.0 / 30.0, outputs=90):
    """The pipeline: (terrain source, rain filter). A cloudburst (1500 mm/h, thirty times heavy rain)
    so that runoff shows within seconds; the volumes stay physical."""
    terrain = simple.ProceduralTerrain(Extent=[4, 4], Resolution=[129, 129], FeatureSize=3.0, HeightScale=0.7,
                                Seed=SEED)
    rain = simple.Rain(Terrain=terrain, RainfallRate=rainfall, DropsPerRealDrop=drops_per_real_drop,
                ParticleSpacing=spacing, Cells=[16, 16], PrecipitationHeight=3.0, WindVelocity=[0.6, 0.2],
                OutputInterval=interval, NumberOfOutputs=outputs, SplashLifetime=0.1)
    return terrain, rain


def show(terrain, rain, view, time):
    """Shows the scene in `view` at `time`, with a low camera over the terrain."""
    view.ViewTime = time
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.BackgroundColorMode = "Gradient"
    view.Background = [0.32, 0.34, 0.36]   # bottom: wet haze
    view.Background2 = [0.72, 0.76, 0.82]  # top: overcast sky
    ground = Show(OutputPort(terrain, 1), view)
    ColorBy(ground, None)
    ground.DiffuseColor = [0.42, 0.36, 0.27]
    ground.Specular = 0.2
    water = Show(OutputPort(rain, 1), view)
    water.SetRepresentationType("Screen-Space Fluid")
    # Runoff is films a few millimetres thin, resolved by 2.5 cm particles: drawn with spheres of a
    # spacing's radius so that neighbouring particles join into sheets of water.
    water.FluidParticleRadius = 1.0 * rain.ParticleSpacing
    water.FluidDisplayMode = "Opaque Surface"
    water.FluidColor = [0.3, 0.5, 0.75]
    drops = Show(OutputPort(rain, 0), view)
    drops.SetRepresentationType("Rain")
    drops.RainWidthScale = 2.0
    drops.RainFogDistance = 8.0
    splashes = Show(OutputPort(rain, 2), view)
    splashes.SetRepresentationType("Rain Splashes")
    splashes.SplashSize = 0.06
    simple.Render(view)  # the first render resets the camera; place it after
    view.CameraPosition = [0.4, -1.6, 1.5]
    view.CameraFocalPoint = [2.2, 2.0, 0.2]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 45.0
    return ground, water, drops, splashes
