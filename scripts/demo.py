"""The ParaFluid demo pipeline: read a dam-break H5Part file, step it with SPH, save the result and
render it to PNG: the water as Screen-Space Fluid (transparent) in its tank over a tiled floor,
under a sky.

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
reader = ParaFluidHDF5Particles(FileName=args.data)
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
try:
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass
# A sky: the water reflects the view's background gradient (Fresnel) and refracts the ground.
view.BackgroundColorMode = "Gradient"
view.Background = [0.55, 0.62, 0.7]
view.Background2 = [0.2, 0.4, 0.72]
view.ViewTime = final_time
domain = [0, 0.8, 0, 0.1, 0, 0.6]
tank = Box(XLength=domain[1] - domain[0], YLength=domain[3] - domain[2], ZLength=domain[5] - domain[4],
           Center=[(domain[0] + domain[1]) / 2, (domain[2] + domain[3]) / 2, (domain[4] + domain[5]) / 2])
tank_display = Show(tank, view)
tank_display.SetRepresentationType("Outline")
tank_display.AmbientColor = tank_display.DiffuseColor = [0.2, 0.2, 0.2]
# The tank's floor and back wall: tiles the refraction shows through the water.
for origin, point1, point2 in (([-0.1, -0.3, 0.0], [0.9, -0.3, 0.0], [-0.1, 0.1, 0.0]),
                               ([-0.1, 0.1, 0.0], [0.9, 0.1, 0.0], [-0.1, 0.1, 0.6])):
    wall = Plane(Origin=origin, Point1=point1, Point2=point2, XResolution=40, YResolution=24)
    tiles = Calculator(Input=wall, ResultArrayName="tiles", Function="sin(40*coordsX)*sin(40*(coordsY+coordsZ))")
    tiles_display = Show(tiles, view)
    ColorBy(tiles_display, ("POINTS", "tiles"))
    tiles_display.SetScalarBarVisibility(view, False)
tiles_lut = GetColorTransferFunction("tiles")
tiles_lut.RGBPoints = [-1.0, 0.55, 0.45, 0.35, 1.0, 0.9, 0.85, 0.75]
water = Show(sph, view)
water.SetRepresentationType("Screen-Space Fluid")
water.ColorArrayName = [None, ""]
water.FluidDisplayMode = "Transparent Fluid"
water.FluidAttenuationDistance = 0.3
Render(view)  # the first render resets the camera: place it after
view.CameraPosition = [0.42, -1.5, 0.75]
view.CameraFocalPoint = [0.36, 0.05, 0.2]
view.CameraViewUp = [0, 0, 1]
view.CameraViewAngle = 30
Render(view)
SaveScreenshot(args.png, view, ImageResolution=args.size)
print("demo: rendered", os.path.abspath(args.png))
