"""Frame time of the Rain representation against ParaView's Point Gaussian on the same drops, same
window, same run (target: Rain <= 1.5 x Point Gaussian at 1M drops, 1280 x 720, llvmpipe), with the
streaks drawn by the GPU path (a triangle per drop) and by the CPU path (RainRasteriser = 'CPU', what
'Automatic' picks under llvmpipe).

  PARAFLUID_PLUGIN=build/lib/paraview-5.11/plugins/ParaFluid/ParaFluid.so PYTHONPATH=Testing/Python \
    scripts/with-xvfb.sh pvpython Testing/Benchmarks/rain_render_benchmark.py [drops (millions), default 1]
"""
import sys
import time

from paraview.simple import *
import pftest

pftest.load(globals())
millions = float(sys.argv[1]) if len(sys.argv) > 1 else 1.0
terrain = ProceduralTerrain(Extent=[40, 40], Resolution=[65, 65], HeightScale=2.0)
rain = Rain(Terrain=terrain, Runoff=0, RainfallRate=20, Cells=[64, 64], PrecipitationHeight=20.0)
probe = 1e-3
rain.DropsPerRealDrop = probe
rain.UpdatePipeline(1.0)
real = rain.GetDataInformation(0).GetNumberOfPoints() / probe  # real drops in the air
rain.DropsPerRealDrop = min(1.0, millions * 1e6 / max(real, 1))
rain.UpdatePipeline(1.0)
drops = rain.GetDataInformation(0).GetNumberOfPoints()

view = CreateRenderView()
view.ViewSize = [int(v) for v in (sys.argv[2:4] if len(sys.argv) > 3 else (1280, 720))]
view.OrientationAxesVisibility = 0
view.ViewTime = 1.0
display = Show(OutputPort(rain, 0), view)
Render(view)
view.CameraPosition = [20.0, -25.0, 8.0]
view.CameraFocalPoint = [20.0, 20.0, 8.0]
view.CameraViewUp = [0.0, 0.0, 1.0]


def frame_time(kind, setup):
    display.SetRepresentationType(kind)
    setup()
    Render(view)  # uploads, compiles
    Render(view)
    times = []
    for _ in range(5):
        view.CameraPosition = [20.0, -25.0 + 0.01 * len(times), 8.0]  # a new frame each time
        start = time.time()
        Render(view)
        times.append(time.time() - start)
    times.sort()
    return times[len(times) // 2]


def gaussian():
    display.GaussianRadius = 0.002


def streaks(rasteriser):
    def setup():
        display.RainWidthScale = 1.0
        display.RainRasteriser = rasteriser
    return setup


gauss = frame_time("Point Gaussian", gaussian)
for rasteriser in ("GPU", "CPU"):
    rain_time = frame_time("Rain", streaks(rasteriser))
    print("%d drops at %d x %d: Point Gaussian %.1f ms, Rain (%s) %.1f ms, ratio %.2f [target <= 1.5]"
          % (drops, view.ViewSize[0], view.ViewSize[1], 1e3 * gauss, rasteriser, 1e3 * rain_time, rain_time / gauss))
