"""Image baselines of the non-photorealistic fluid (rendered under Xvfb with llvmpipe, compared
with Testing/NPR/Baselines by VTK's image difference, thresholded error <= 10), on a collapsing column
whose foot streams out along +x and a falling drop, with velocity and a hydrostatic density:
 - npr_toon.png: Toon Fluid, toon bands and silhouette / depth-step lines;
 - npr_toon_contours.png: the same with depth-contour (expression) lines every 3 radii;
 - npr_brush.png: Brush Stroke Fluid, strokes along the flow and fixed strokes in the still
   column, shaded by density;
 - npr_flow_lines.png: Fluid Flow Lines through a draining vortex, as tubes coloured by speed;
 - npr_foam.png: Foam Particles on a sharp-crested ridge of water (the crest, and the sheet's
   convex edges) as white spheres over the Screen-Space Fluid.
It also checks that the brush strokes stay on the fluid's footprint.
To refresh: PARAFLUID_UPDATE_BASELINE=1 ctest -R npr_images"""
import os

import numpy as np

from paraview.simple import *
import pftest

pftest.load(globals())
out = pftest.scratch_dir()
SIZE = [400, 300]

POINTS = pftest.particle_script(pftest.DAM_BREAK_SCENE + """
V = np.zeros_like(P)
# The column slumps slowly; its foot streams out faster the further it has gone, turning up at the
# front; the drop falls.
V[:c, 0] = 0.3 * P[:c, 0] * (0.8 - P[:c, 2])
V[:c, 2] = -0.2 * P[:c, 2]
V[c:c + f, 0] = 1.0 + 1.5 * (P[c:c + f, 0] - 0.6)
V[c:c + f, 2] = 0.8 * (P[c:c + f, 0] - 0.6) ** 2
V[c + f:, 2] = -2.0
rho = 1000.0 + 9.81 * np.maximum(0.8 - P[:, 2], 0.0) * 4.0
rho[c:] = 1000.0 + 9.81 * np.maximum(0.12 - P[c:, 2], 0.0) * 4.0
arrays = {"velocity": V, "density": rho}
""")


def particles():
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = POINTS
    return source


def render(name, build, camera=([2.6, -2.2, 1.6], [0.65, 0.3, 0.3])):
    view = CreateRenderView()
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.93, 0.9, 0.82]
    view.BackgroundColorMode = "Single Color"
    build(view)
    Render(view)
    view.CameraPosition, view.CameraFocalPoint = camera
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    png = os.path.join(out, name)
    SaveScreenshot(png, view, ImageResolution=SIZE)
    pftest.compare_with_baseline(png, name)
    return view, png


def toon(contours):
    def build(view):
        display = Show(particles(), view)
        display.SetRepresentationType("Toon Fluid")
        display.ColorArrayName = [None, ""]
        display.ToonParticleRadius = 0.04
        display.ToonContourSpacing = contours
    return build


def brush(view):
    display = Show(particles(), view)
    display.SetRepresentationType("Brush Stroke Fluid")
    display.ColorArrayName = [None, ""]
    display.BrushParticleRadius = 0.04
    display.BrushStrokeWidth = 5


VORTEX_CAMERA = ([0.0, -0.75, 0.65], [0.0, 0.0, 0.0])


def flow_lines(view):
    # A pool turning as a rigid vortex (2 rad/s) while it drains towards the centre.
    block = ParticleBlock(Spacing=0.01, BlockBounds=[-0.2, 0.2, -0.2, 0.2, 0, 0.03],
                          DomainBounds=[-0.3, 0.3, -0.3, 0.3, 0, 0.2])
    swirl = Calculator(Input=block, ResultArrayName="velocity",
                       Function="(-2*coordsY - 0.4*coordsX)*iHat + (2*coordsX - 0.4*coordsY)*jHat + 0*kHat")
    lines = FluidFlowLines(Input=swirl, SeedStride=5, PointsPerLine=16, LineDuration=0.5, MaxLines=150)
    tubes = Tube(Input=lines, Radius=0.002, NumberofSides=6)
    display = Show(tubes, view)
    ColorBy(display, ("POINTS", "speed"))
    lut = GetColorTransferFunction("speed")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    lut.RescaleTransferFunction(0.0, 0.6)
    display.SetScalarBarVisibility(view, False)
    water = Show(block, view)
    water.SetRepresentationType("Points")
    water.ColorArrayName = [None, ""]
    water.DiffuseColor = [0.6, 0.72, 0.85]
    water.PointSize = 2


RIDGE = pftest.particle_script("""
h = 0.03
g = lambda a, b: np.arange(a + h / 2, b, h)
P = np.stack(np.meshgrid(g(0.0, 1.5), g(0.0, 0.9), g(0.0, 0.5), indexing='ij'), -1).reshape(-1, 3)
# a sheet of water with a sharp-crested ridge across it
crest = 0.12 + 0.33 * np.maximum(0.0, 1.0 - np.abs(P[:, 0] - 0.75) / 0.3) ** 2
P = P[P[:, 2] < crest]
""")
RIDGE_CAMERA = ([0.2, -1.6, 1.1], [0.75, 0.45, 0.1])


def foam(view):
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = RIDGE
    fluid = Show(source, view)
    fluid.SetRepresentationType("Screen-Space Fluid")
    fluid.ColorArrayName = [None, ""]
    fluid.FluidParticleRadius = 0.03
    fluid.FluidDisplayMode = "Opaque Surface"
    flagged = Threshold(Input=FoamParticles(Input=source, PersistFrames=1, ParticleSpacing=0.03), Scalars=["POINTS", "foam"],
                        LowerThreshold=0.5, UpperThreshold=1.5)
    # Real spheres (Point Gaussian's impostors sit at the centres' depth, behind the fluid's
    # surface), a little larger than the fluid's, so the foam shows through its surface.
    bubbles = Glyph(Input=flagged, GlyphType="Sphere", ScaleArray=["POINTS", "No scale array"],
                    ScaleFactor=0.07, GlyphMode="All Points")
    bubbles.GlyphType.ThetaResolution = 8
    bubbles.GlyphType.PhiResolution = 6
    display = Show(bubbles, view)
    display.ColorArrayName = [None, ""]
    display.DiffuseColor = [1.0, 1.0, 1.0]


def pixels(png):
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    image = reader.GetOutput()
    return vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(int)


_, toon_png = render("npr_toon.png", toon(0.0))
render("npr_toon_contours.png", toon(3.0))
_, brush_png = render("npr_brush.png", brush)
# The strokes stay on the fluid: wherever the toon image (same splats, same smoothing) shows the
# background, so does the brush image; and they cover a good part of the fluid.
toon_rgb, brush_rgb = pixels(toon_png), pixels(brush_png)
background = toon_rgb[0]
outside = np.all(toon_rgb == background, axis=1)
strayed = np.sum(np.any(brush_rgb[outside] != background, axis=1))
pftest.check(strayed == 0, "brush strokes drawn off the fluid on %d pixels" % strayed)
painted = np.sum(np.any(brush_rgb[~outside] != toon_rgb[~outside], axis=1)) / float(np.count_nonzero(~outside))
print("brush strokes cover %.0f %% of the fluid" % (100 * painted))
pftest.check(painted > 0.3, "brush strokes cover only %.0f %% of the fluid" % (100 * painted))
render("npr_flow_lines.png", flow_lines, VORTEX_CAMERA)
render("npr_foam.png", foam, RIDGE_CAMERA)
print("test_npr_images: all images match")
