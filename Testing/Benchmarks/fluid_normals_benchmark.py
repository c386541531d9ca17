"""How flat a flat face looks: the RMS angle between the rendered normals and the face normal on
the top of a resting lattice block that fills half the window, seen from straight above, with
particle radii of 5, 20 and 60 pixels on screen; Screen-Space Fluid (default settings) and
Ray-Marched Fluid (default settings) from the Normals display mode (colour = 0.5 + 0.5 n, eye
space). Pixels within 3 particle spacings of the block's edge (at most a quarter of its width) are left
out (the silhouette).

  PARAFLUID_PLUGIN=build/lib/paraview-5.11/plugins/ParaFluid/ParaFluid.so \\
    scripts/with-xvfb.sh pvpython Testing/Benchmarks/fluid_normals_benchmark.py"""
import builtins  # paraview.simple star-imports min and max over the built-ins
import math
import sys

import numpy as np
from paraview.simple import *
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, "Testing/Python")
import pftest

pftest.load(globals())
W, H = 1200, 800
view = CreateRenderView()
view.ViewSize = [W, H]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]
d = 0.02
print("%-22s %8s %12s %12s %12s %8s" % ("representation", "radius", "rms angle", "95th pct", "rms on fluid", "holes"))
# (Names of proxies made here avoid "block" and "source": paraview.simple rebinds such globals.)
for radius_px in (5, 20, 60):
    # The block fills half the window's width: n spacings across.
    pixels_per_spacing = radius_px / 0.6
    n = int(round(0.5 * W / pixels_per_spacing))
    lattice_block = ProgrammableSource(OutputDataSetType="vtkPolyData")
    lattice_block.Script = pftest.particle_script("""
h = %r
g = lambda a, b: np.arange(a + h / 2, b, h)
P = np.stack(np.meshgrid(g(0.0, %d * h), g(0.0, %d * h), g(0.0, 6 * h), indexing='ij'), -1).reshape(-1, 3)
""" % (d, n, n))
    for kind, mode_property in (("Screen-Space Fluid", "FluidDisplayMode"), ("Ray-Marched Fluid", "RayMarchDisplayMode")):
        shown = Show(lattice_block, view)
        shown.SetRepresentationType(kind)
        shown.ColorArrayName = [None, ""]
        shown.SetPropertyWithName(mode_property, "Normals")
        Render(view)
        centre = 0.5 * n * d
        view.CameraPosition = [centre, centre, 5.0]
        view.CameraFocalPoint = [centre, centre, 0.0]
        view.CameraViewUp = [0.0, 1.0, 0.0]
        view.CameraParallelProjection = 1
        view.CameraParallelScale = 0.5 * H / pixels_per_spacing * d
        Render(view)
        grab = vtkWindowToImageFilter()
        grab.SetInput(view.GetRenderWindow())
        grab.ReadFrontBufferOff()
        grab.Update()
        rgb = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).reshape(H, W, -1)[:, :, :3] / 255.0
        normal = rgb * 2.0 - 1.0
        # Inside the face, 3 spacings from its edges.
        half = 0.5 * n * pixels_per_spacing
        margin = builtins.min(3 * pixels_per_spacing, 0.5 * half)
        y, x = np.mgrid[0:H, 0:W]
        inside = (np.abs(x + 0.5 - W / 2) < half - margin) & (np.abs(y + 0.5 - H / 2) < half - margin)
        cosine = np.clip(normal[..., 2] / np.maximum(np.linalg.norm(normal, axis=-1), 1e-9), -1.0, 1.0)
        angle = np.degrees(np.arccos(cosine))[inside]
        # Holes (no fluid drawn: the black background) count in the rms as the defect they are;
        # the rms over drawn pixels alone is printed beside it.
        hole = (rgb.max(axis=-1) == 0.0)[inside]
        drawn = angle[~hole]
        if len(sys.argv) > 1:
            SaveScreenshot("%s/normals_%s_%d.png" % (sys.argv[1], kind.split("-")[0], radius_px), view)
        print("%-22s %6d px %10.2f deg %10.2f deg %10.2f deg %7.2f %%" % (
            kind, radius_px, math.sqrt((angle ** 2).mean()), np.percentile(angle, 95),
            math.sqrt((drawn ** 2).mean()) if drawn.size else float("nan"), 100.0 * hole.mean()))
        Hide(lattice_block, view)
    Delete(lattice_block)
