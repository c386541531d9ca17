"""Gerstner ocean timings in ParaView (run under Xvfb for the frame times):
 - the Gerstner Ocean source: seconds per frame for 1000 x 1000 vertices and 8 waves (Storm),
   deep water and over a beach; the median of several times;
 - the Gerstner Ocean representation: milliseconds per rendered frame of a 512 x 512 plane,
   against the same plane drawn by the plain Surface representation (the ratio is the cost of the
   displacement and water shading).
Usage: PARAFLUID_PLUGIN=build/lib/paraview-5.11/plugins/ParaFluid/ParaFluid.so \\
       scripts/with-xvfb.sh pvpython Testing/Benchmarks/ocean_benchmark.py [frames] [csv]
Writes the figures to csv (default build/ocean_benchmark.csv)."""
import os
import statistics
import sys
import time

from paraview.simple import *

LoadPlugin(os.environ["PARAFLUID_PLUGIN"], ns=globals())
frames = int(sys.argv[1]) if len(sys.argv) > 1 else 30
rows = []


def timed_source(**extra):
    ocean = GerstnerOcean(SeaState="Storm", Resolution=[1000, 1000], Size=[400.0, 400.0], **extra)
    times = []
    for k in range(6):
        start = time.perf_counter()
        ocean.UpdatePipeline(0.1 * (k + 1))
        times.append(time.perf_counter() - start)
    return statistics.median(times[1:])


deep = timed_source()
beach = Plane(Origin=[0.0, 0.0, -20.0], Point1=[400.0, 0.0, 1.0], Point2=[0.0, 400.0, -20.0], XResolution=64, YResolution=64)
shallow = timed_source(Bathymetry=beach)
print("source, 1M vertices x 8 waves: deep water %.3f s, over a beach %.3f s" % (deep, shallow))
rows += [("source_deep_s", deep), ("source_beach_s", shallow)]

view = CreateRenderView()
view.ViewSize = [1280, 720]
view.OrientationAxesVisibility = 0
plane = Plane(Origin=[0.0, 0.0, 0.0], Point1=[200.0, 0.0, 0.0], Point2=[0.0, 200.0, 0.0], XResolution=511, YResolution=511)
shown = Show(plane, view)
Render(view)
view.CameraPosition = [100.0, -30.0, 25.0]
view.CameraFocalPoint = [100.0, 90.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]


def frame_time(kind):
    shown.SetRepresentationType(kind)
    if kind == "Gerstner Ocean":
        shown.OceanSeaState = "Storm"

    Render(view)
    times = []
    for k in range(frames):
        view.ViewTime = 0.05 * k
        start = time.perf_counter()
        Render(view)
        times.append(time.perf_counter() - start)
    return 1000.0 * statistics.median(times)


surface = frame_time("Surface")
ocean = frame_time("Gerstner Ocean")
print("frame, 512 x 512 plane at 1280 x 720: Surface %.1f ms, Gerstner Ocean %.1f ms, ratio %.2f"
      % (surface, ocean, ocean / surface))
rows += [("surface_frame_ms", surface), ("ocean_frame_ms", ocean), ("ratio", ocean / surface)]
csv = sys.argv[2] if len(sys.argv) > 2 else os.path.join("build", "ocean_benchmark.csv")
with open(csv, "w") as f:
    f.write("measure,value\n")
    for name, value in rows:
        f.write("%s,%g\n" % (name, value))
