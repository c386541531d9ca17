"""Image baselines of the Ray-Marched Fluid representation (rendered under Xvfb with llvmpipe,
compared with Testing/Fluid/Baselines by VTK's image difference, thresholded error <= 10):
 - ray_marched_ball_opaque.png / ray_marched_ball_transparent.png: a lattice ball, opaque lit
   surface and transparent fluid over a ground coloured by x (refracted and tinted by the true
   path length through the ball);
 - ray_marched_dam_break.png: a collapsing column and a falling drop over the coloured ground;
 - ray_marched_box.png: a ball of fluid through an opaque box (depth compositing).
To refresh: PARAFLUID_UPDATE_BASELINE=1 ctest -R ray_marched_images"""
import os

from paraview.simple import *
import pftest

pftest.load(globals())
out = pftest.scratch_dir()
SIZE = [400, 300]

DAM = pftest.particle_script(pftest.DAM_BREAK_SCENE)
BALL = pftest.particle_script("""
h = 0.04
g = (np.arange(24) - 11.5) * h
P = np.stack(np.meshgrid(g, g, g, indexing='ij'), -1).reshape(-1, 3)
P = P[np.linalg.norm(P, axis=1) <= 0.45] + np.array([0.0, 0.0, 0.5])
""")


def fluid(view, script, mode):
    particles = ProgrammableSource(OutputDataSetType="vtkPolyData")
    particles.Script = script
    display = Show(particles, view)
    display.SetRepresentationType("Ray-Marched Fluid")
    display.ColorArrayName = [None, ""]
    display.RayMarchDisplayMode = mode
    display.RayMarchAttenuationDistance = 0.5


def ground(view):
    plane = Plane(Origin=[-0.6, -0.6, 0.0], Point1=[2.0, -0.6, 0.0], Point2=[-0.6, 1.4, 0.0], XResolution=52,
                  YResolution=40)
    pftest.show_striped(plane, view)


def box(view):
    shown = Show(Box(Center=[0.0, 0.0, 0.5], XLength=1.2, YLength=0.3, ZLength=0.3), view)
    shown.ColorArrayName = [None, ""]
    shown.DiffuseColor = [0.8, 0.3, 0.2]


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


BALL_CAMERA = ([1.6, -2.0, 1.4], [0.0, 0.0, 0.45])
render("ray_marched_ball_opaque.png", lambda v: fluid(v, BALL, "Opaque Surface"), *BALL_CAMERA)
render("ray_marched_ball_transparent.png", lambda v: (ground(v), fluid(v, BALL, "Transparent Fluid")), *BALL_CAMERA)
render("ray_marched_dam_break.png", lambda v: (ground(v), fluid(v, DAM, "Transparent Fluid")),
       [2.6, -2.2, 1.6], [0.65, 0.3, 0.3])
render("ray_marched_box.png", lambda v: (box(v), fluid(v, BALL, "Opaque Surface")), *BALL_CAMERA)
