"""The ParaFluid rain demo: a procedural terrain, a cloudburst on it for a few seconds, the runoff as
SPH water; writes a PNG of the PRT-lit rain, the splashes and the water.

  pvpython scripts/demo_rain.py --plugin build/.../ParaFluid.so [--time 3] [--png rain.png] [--size W H]
"""
import argparse
import os
import sys
import time

from paraview.simple import *

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--plugin", default=os.environ.get("PARAFLUID_PLUGIN"), help="path of ParaFluid.so")
parser.add_argument("--time", type=float, default=3.0, help="simulated seconds of rain")
parser.add_argument("--png", default="rain.png")
parser.add_argument("--size", type=int, nargs=2, default=[1280, 720])
args = parser.parse_args()
if not args.plugin or not os.path.exists(args.plugin):
    sys.exit("demo: give --plugin (the built ParaFluid.so) or set PARAFLUID_PLUGIN")
LoadPlugin(args.plugin, ns=globals())
LoadPlugin(args.plugin)  # and into paraview.simple, where rain_scene finds the plugin's proxies
import rain_scene  # noqa: E402 (after the plugin: it names the plugin's proxies)

frames = max(1, int(round(args.time * 30)))
terrain, rain = rain_scene.build(outputs=frames)
end = rain.TimestepValues[-1]
start = time.time()
rain.UpdatePipeline(end)
elapsed = time.time() - start
rain.UpdatePropertyInformation()
fallen, water = rain.GetProperty("FallenVolume").GetData(), rain.GetProperty("WaterVolume").GetData()
print("demo: %d drops, %d water particles after %.2f s of rain, computed in %.1f s; rain fallen %.4f m^3, water %.4f m^3"
      % (rain.GetDataInformation(0).GetNumberOfPoints(), rain.GetDataInformation(1).GetNumberOfPoints(), end, elapsed,
         fallen, water))
view = CreateView("RenderView")
view.ViewSize = args.size
rain_scene.show(terrain, rain, view, end)
Render(view)
SaveScreenshot(args.png, view, ImageResolution=args.size)
print("demo: wrote", os.path.abspath(args.png))
