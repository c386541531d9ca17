"""Frame time of the Volumetric Cloud representation against ParaView's own volume rendering
(the Volume representation: GPU ray cast, its default transfer functions) of the same 128^3 image
(procedural cumulus from Stable Fluids), in the same window, same run, the camera turning 4 degrees
a frame. Prints milliseconds per frame (median of the runs) and the ratios.
Run: PARAFLUID_PLUGIN=build/lib/paraview-5.11/plugins/ParaFluid/ParaFluid.so \\
     scripts/with-xvfb.sh pvpython Testing/Benchmarks/cloud_render_benchmark.py [--size 800 600] [--runs 3]"""
import argparse
import statistics
import sys
import time

from paraview.simple import *
sys.path.insert(0, __import__("os").path.join(__import__("os").path.dirname(__file__), "..", "Python"))
import pftest

pftest.load(globals())
parser = argparse.ArgumentParser()
parser.add_argument("--size", type=int, nargs=2, default=[800, 600])
parser.add_argument("--runs", type=int, default=3)
parser.add_argument("--frames", type=int, default=12)
args = parser.parse_args()

clouds = StableFluids(Emitter=0, ProceduralClouds=1, CloudCoverage=0.5, CloudFeatureSize=3.0, CloudSeed=3,
                      Bounds=[0, 8, 0, 8, 0, 8], Resolution=[128, 128, 128], NumberOfOutputs=0)
clouds.UpdatePipeline(0.0)
view = CreateRenderView()
view.ViewSize = args.size
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.42, 0.6, 0.86]
shown = Show(clouds, view)
Render(view)
view.CameraPosition = [4.0, -12.0, 6.0]
view.CameraFocalPoint = [4.0, 4.0, 4.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 40.0


def frames():
    camera = GetActiveCamera()
    Render(view)  # upload and warm-up
    times = []
    for _ in range(args.frames):
        camera.Azimuth(4.0)
        start = time.perf_counter()
        Render(view)
        times.append(1e3 * (time.perf_counter() - start))
    return statistics.median(times)


ways = {
    "ParaView Volume (GPU ray cast)": dict(Representation="Volume"),
    "Volumetric Cloud, shadows off": dict(Representation="Volumetric Cloud", CloudShadows=0, CloudLightMode="Sun"),
    "Volumetric Cloud, shadows on (sun)": dict(Representation="Volumetric Cloud", CloudShadows=1, CloudLightMode="Sun"),
    "Volumetric Cloud, shadows on (key light)": dict(Representation="Volumetric Cloud", CloudShadows=1,
                                                     CloudLightMode="View's key light"),
}
results = {name: [] for name in ways}
for run in range(args.runs):
    for name, settings in ways.items():
        shown.SetRepresentationType(settings["Representation"])
        if settings["Representation"] == "Volume":
            ColorBy(shown, ("POINTS", "density"))
        for key, value in settings.items():
            if key != "Representation":
                setattr(shown, key, value)
        results[name].append(frames())
print("%d x %d window, 128^3 image, median of %d frames per run" % (args.size[0], args.size[1], args.frames))
base = statistics.median(results["ParaView Volume (GPU ray cast)"])
for name, values in results.items():
    ms = statistics.median(values)
    print("%-42s %8.1f ms/frame  (runs: %s)  %.2fx ParaView Volume" % (name, ms, ", ".join("%.0f" % v for v in values),
                                                                     ms / base))
