"""The ParaFluid demo pipeline: read a dam-break H5Part file, step it with SPH, save the result and
render it to PNG.

  pvpython scripts/demo.py --plugin build/.../ParaFluid.so [--data Data/dam_break.h5part]
      [--outputs 20] [--interval 0.01] [--solver WCSPH|DFSPH] [--result out.h5part] [--png out.png]
"""
import argparse
import os
import sys
import time

from paraview.simple import *

here = os.path.dirname(os.path.abspath(__file__))
parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--plugin", default=os.environ.get("PARAFLUID_PLUGIN"), help="path of ParaFluid.so")
parser.add_argument("--data", default=os.path.join(here, "..", "Data", "dam_break.h5part"))
parser.add_argument("--outputs", type=int, default=20, help="output times to compute")
parser.add_argument("--interval", type=float, default=0.01, help="simulated seconds between outputs")
parser.add_argument("--solver", choices=["WCSPH", "DFSPH"], default="WCSPH", help="pressure solver")
parser.add_argument("--result", default="dam_break_result.h5part", help="where to save the final state")
parser.add_argument("--png", default="dam_break.png")
parser.add_argument("--size", type=int, nargs=2, default=[800, 600])
args = parser.parse_args()
if not args.plugin or not os.path.exists(args.plugin):
    sys.exit("demo: give --plugin (the built ParaFluid.so) or set PARAFLUID_PLUGIN")

LoadPlugin(args.plugin, ns=globals())
reader = ParaFluidH5PartReader(FileName=args.data)
sph = SPHStep(Input=reader, OutputInterval=args.interval, NumberOfOutputs=args.outputs,
              PressureSolver="DFSPH" if args.solver == "DFSPH" else "WCSPH (Müller)")
final_time = sph.TimestepValues[-1] if args.outputs > 0 else sph.TimestepValues
start = time.time()
sph.UpdatePipeline(final_time)
elapsed = time.time() - start
particles = sph.GetDataInformation().GetNumberOfPoints()
sph.UpdatePropertyInformation()
steps = sph.GetPropertyValue("StepsTakenLastUpdate")
print("demo: %d particles, %d SPH steps to t = %.3f s in %.2f s (%.2f M particle-steps/s)"
      % (particles, steps, final_time, elapsed, particles * steps / max(elapsed, 1e-9) / 1e6))

SaveData(args.result, proxy=sph)
print("demo: saved", os.path.abspath(args.result))

view = CreateView("RenderView")
view.ViewSize = args.size
view.OrientationAxesVisibility = 0
view.Background = [1.0, 1.0, 1.0]
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
view.ViewTime = final_time
domain = [0, 0.8, 0, 0.1, 0, 0.6]
info = sph.GetDataInformation().DataInformation
tank = Box(XLength=domain[1] - domain[0], YLength=domain[3] - domain[2], ZLength=domain[5] - domain[4],
           Center=[(domain[0] + domain[1]) / 2, (domain[2] + domain[3]) / 2, (domain[4] + domain[5]) / 2])
tank_display = Show(tank, view)
tank_display.SetRepresentationType("Outline")
tank_display.AmbientColor = tank_display.DiffuseColor = [0.2, 0.2, 0.2]
water = Show(sph, view)
water.SetRepresentationType("Points")
water.RenderPointsAsSpheres = 1
water.PointSize = 6
ColorBy(water, ("POINTS", "velocity", "Magnitude"))
lut = GetColorTransferFunction("velocity")
lut.ApplyPreset("Blues", True)
lut.RescaleTransferFunction(0.0, 2.0)
view.CameraPosition = [0.4, -1.6, 0.3]
view.CameraFocalPoint = [0.4, 0.05, 0.3]
view.CameraViewUp = [0, 0, 1]
view.CameraParallelScale = 0.35
view.CameraParallelProjection = 1
Render(view)
SaveScreenshot(args.png, view, ImageResolution=args.size)
print("demo: rendered", os.path.abspath(args.png))
