"""Image baselines of the Screen-Space Fluid representation (rendered under Xvfb with llvmpipe,
compared with Testing/Fluid/Baselines by VTK's image difference, thresholded error <= 10):
 - fluid_opaque.png: a collapsing column and a falling drop of particles, opaque lit surface;
 - fluid_transparent.png: the same as transparent fluid over a ground plane coloured by x, which
   the fluid refracts and tints by its thickness;
 - fluid_normals.png: the normals display mode;
 - fluid_box.png: a ball of fluid through an opaque box (the depth compositing);
 - fluid_clear_water.png: default transparent fluid over the coloured ground: a 2 cm sheet the
   ground shows through almost untinted, beside a 30 cm block tinted by Beer-Lambert, with the
   sky's Fresnel reflection on its top at a grazing angle.
To refresh: PARAFLUID_UPDATE_BASELINE=1 ctest -R fluid_images"""
import os

from paraview.simple import *
import pftest

pftest.load(globals())
out = pftest.scratch_dir()
SIZE = [400, 300]

POINTS = pftest.particle_script(pftest.DAM_BREAK_SCENE)

BALL = pftest.particle_script("""
g = (np.arange(24) - 11.5) * 0.04
P = np.stack(np.meshgrid(g, g, g, indexing='ij'), -1).reshape(-1, 3)
P = P[np.linalg.norm(P, axis=1) <= 0.45]
""")


def fluid(view, script, mode):
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = script
    display = Show(source, view)
    display.SetRepresentationType("Screen-Space Fluid")
    display.ColorArrayName = [None, ""]
    display.FluidParticleRadius = 0.04
    display.FluidDisplayMode = mode
    display.FluidAttenuationDistance = 0.5
    display.FluidRefractionStrength = 0.3
    return display


def ground(view, coloured):
    plane = Plane(Origin=[-0.6, -0.6, 0.0], Point1=[2.0, -0.6, 0.0], Point2=[-0.6, 1.4, 0.0], XResolution=52, YResolution=40)
    display = Show(plane, view)
    if coloured:
        Hide(plane, view)
        display = pftest.show_striped(plane, view)
    else:
        display.ColorArrayName = [None, ""]
        display.DiffuseColor = [0.55, 0.55, 0.5]


def render(name, build, position, focal):
    view = CreateRenderView()
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.25, 0.3, 0.4]
    view.Background2 = [0.75, 0.85, 0.95]
    view.BackgroundColorMode = "Gradient"
    build(view)
    Render(view)
    view.CameraPosition = position
    view.CameraFocalPoint = focal
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    png = os.path.join(out, name)
    SaveScreenshot(png, view, ImageResolution=SIZE)
    pftest.compare_with_baseline(png, name)
    Delete(view)


DAM_CAMERA = ([2.6, -2.2, 1.6], [0.65, 0.3, 0.3])
render("fluid_opaque.png", lambda v: (ground(v, False), fluid(v, POINTS, "Opaque Surface")), *DAM_CAMERA)
render("fluid_transparent.png", lambda v: (ground(v, True), fluid(v, POINTS, "Transparent Fluid")), *DAM_CAMERA)
render("fluid_normals.png", lambda v: fluid(v, POINTS, "Normals"), *DAM_CAMERA)


def ball_in_box(view):
    fluid(view, BALL, "Opaque Surface")
    box = Box(Center=[0.35, 0.0, 0.0], XLength=0.5, YLength=0.5, ZLength=0.5)
    display = Show(box, view)
    display.ColorArrayName = [None, ""]
    display.DiffuseColor = [0.9, 0.5, 0.2]


render("fluid_box.png", ball_in_box, [0.6, -2.4, 1.0], [0.1, 0.0, 0.0])

SHEET_AND_BLOCK = pftest.particle_script("""
h = 0.01
g = lambda a, b: np.arange(a + h / 2, b, h)
sheet = np.stack(np.meshgrid(g(-0.4, 0.4), g(-0.4, 0.4), g(0.0, 0.02), indexing='ij'), -1).reshape(-1, 3)
block = np.stack(np.meshgrid(g(0.5, 1.2), g(-0.4, 0.4), g(0.0, 0.3), indexing='ij'), -1).reshape(-1, 3)
P = np.concatenate([sheet, block])
""")


def clear_water(view):
    ground(view, True)
    particles = ProgrammableSource(OutputDataSetType="vtkPolyData")
    particles.Script = SHEET_AND_BLOCK
    display = Show(particles, view)
    display.SetRepresentationType("Screen-Space Fluid")  # every setting at its default
    display.ColorArrayName = [None, ""]


render("fluid_clear_water.png", clear_water, [0.4, -1.6, 1.0], [0.4, 0.2, 0.0])
print("test_fluid_images: all images match")
