"""The Screen-Space Fluid representation in ParaView (rendered under Xvfb): chosen like any
representation; Toon Fluid and Brush Stroke Fluid on the same ball (bands, warnings for a
missing or wrong velocity array, zero and NaN particles); zero particles, one particle, a non-point input (drawn as its points, with a
warning), two fluids in one view, a window resize, the camera inside the fluid, all without an
error; colouring by an array changes the picture; the depth of the fluid hides and is hidden by
opaque geometry."""

import numpy as np
from paraview.simple import *
from vtkmodules.util.numpy_support import vtk_to_numpy
import pftest

pftest.load(globals())
# Errors and warnings reach ParaView's output window; collect what our renders say there.
messages = pftest.OutputWindowMessages().take


def particles(script):
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = (
        "import numpy as np\n"
        "from vtkmodules.vtkCommonCore import vtkPoints\n"
        "from vtkmodules.util.numpy_support import numpy_to_vtk\n"
        "out = self.GetPolyDataOutput()\n"
        + script
        + "\npts = vtkPoints()\npts.SetData(numpy_to_vtk(np.ascontiguousarray(P, dtype=np.float32), deep=True))\n"
        "out.SetPoints(pts)\n"
        "s = numpy_to_vtk(np.ascontiguousarray(P[:, 2], dtype=np.float64), deep=True)\ns.SetName('height')\n"
        "out.GetPointData().AddArray(s)\n")
    return source


BALL = ("g = (np.arange(20) - 9.5) * 0.05\n"
        "X, Y, Z = np.meshgrid(g, g, g, indexing='ij')\n"
        "P = np.stack([X.ravel(), Y.ravel(), Z.ravel()], 1)\n"
        "P = P[np.linalg.norm(P, axis=1) < 0.45]\n")

view = CreateRenderView()
view.ViewSize = [320, 240]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.2, 0.2, 0.2]  # grey: transparent fluid over it still differs from it
view.CameraPosition = [0.0, -3.0, 0.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]


def pixels():
    Render(view)
    window = view.GetRenderWindow()
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    out = grab.GetOutput()
    w, h, _ = out.GetDimensions()
    return vtk_to_numpy(out.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3].astype(float)


def fluid_pixels(image):
    return int((np.abs(image - 51.0).max(axis=2) > 3).sum())


ball = particles(BALL)
display = Show(ball, view)
display.SetRepresentationType("Screen-Space Fluid")
display.ColorArrayName = [None, ""]
display.FluidDisplayMode = "Opaque Surface"
Render(view)
view.CameraPosition = [0.0, -3.0, 0.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
first = pixels()
covered = fluid_pixels(first)
pftest.check(covered > 2000, "the fluid ball covers the middle of the view (%d pixels)" % covered)
pftest.check(messages() == "", "no error rendering the ball")

# Every display mode and smoothing method renders something, without an error.
for mode in ["Opaque Surface", "Transparent Fluid", "Normals", "Thickness", "Particle Depth"]:
    display.FluidDisplayMode = mode
    for smoothing in ["Narrow-Range Filter", "Bilateral Filter", "Curvature Flow"]:
        display.FluidSmoothing = smoothing
        image = pixels()
        pftest.check(fluid_pixels(image) > 0.8 * covered, "%s / %s draws the ball" % (mode, smoothing))
        text = messages()
        pftest.check(text == "", "%s / %s: no error (%s)" % (mode, smoothing, text[:300]))
display.FluidDisplayMode = "Opaque Surface"
display.FluidSmoothing = "Narrow-Range Filter"

# Colouring by an array changes the colours.
plain = pixels()
ColorBy(display, ("POINTS", "height"))
coloured = pixels()
pftest.check(np.abs(coloured - plain).mean() > 1.0, "colouring by 'height' changes the picture")
display.ColorArrayName = [None, ""]

# Ambient (the light without a direct source) reaches the shading: more of it brightens the ball.
display.FluidAmbient = 0.8
brighter = pixels()
display.FluidAmbient = 0.2
pftest.check(brighter.mean() > plain.mean() + 1.0, "FluidAmbient 0.8 brightens the ball (%.1f -> %.1f)" %
             (plain.mean(), brighter.mean()))

# An opaque box in front of the ball hides it where it stands; the fluid hides a box behind it.
def red_box(center, lengths):
    box = Box(Center=center, XLength=lengths[0], YLength=lengths[1], ZLength=lengths[2])
    shown = Show(box, view)
    shown.ColorArrayName = [None, ""]
    shown.DiffuseColor = [1.0, 0.0, 0.0]
    shown.AmbientColor = [1.0, 0.0, 0.0]
    shown.Ambient = 1.0
    shown.Diffuse = 0.0
    return box


front = red_box([0.0, -1.0, 0.0], [0.3, 0.1, 0.3])
image = pixels()
centre = image[120, 160]
pftest.check(centre[0] > 200 and centre[1] < 30 and centre[2] < 30, "the box in front hides the fluid (centre %s)" % centre)
Hide(front, view)
behind = red_box([0.0, 1.0, 0.0], [2.0, 0.1, 2.0])
image = pixels()
centre = image[120, 160]
pftest.check(not (centre[0] > 200 and centre[1] < 30), "the fluid hides the box behind it (centre %s)" % centre)
corner = image[120, 60]
pftest.check(corner[0] > 200 and corner[1] < 30, "the box shows beside the fluid (corner %s)" % corner)
Hide(behind, view)

# A second fluid in the same view.
second = particles("P = np.array([[0.8, 0.0, 0.0], [0.85, 0.0, 0.0]])")
secondDisplay = Show(second, view)
secondDisplay.SetRepresentationType("Screen-Space Fluid")
secondDisplay.FluidParticleRadius = 0.1
image = pixels()
pftest.check(fluid_pixels(image) > covered, "a second fluid adds to the picture")
pftest.check(messages() == "", "two fluids: no error")
Hide(second, view)

# Window resize, and the camera inside the fluid.
view.ViewSize = [500, 300]
image = pixels()
pftest.check(image.shape[0] == 300 and image.shape[1] == 500 and fluid_pixels(image) > covered, "resize: the fluid still draws")
view.ViewSize = [320, 240]
view.CameraPosition = [0.0, -0.1, 0.0]
pixels()
view.CameraPosition = [0.0, -3.0, 0.0]
pftest.check(messages() == "", "resize and camera inside the fluid: no error")

# Toon Fluid and Brush Stroke Fluid: the same ball, their own properties, no error; the brush
# strokes without a velocity array say so and still paint (fixed strokes only); zero particles
# and a NaN particle in them are harmless.
for kind in ("Toon Fluid", "Brush Stroke Fluid"):
    display.SetRepresentationType(kind)
    image = pixels()
    text = messages()
    pftest.check(fluid_pixels(image) > 0.8 * covered, "%s draws the ball" % kind)
    if kind == "Toon Fluid":
        pftest.check(text == "", "toon: no error (%s)" % text[:300])
        display.ToonBands = 2
        two = pixels()
        display.ToonBands = 8
        eight = pixels()
        pftest.check(np.abs(two - eight).max() > 20, "toon: the number of bands changes the picture")
        pftest.check(len(np.unique(two.reshape(-1, 3), axis=0)) < len(np.unique(eight.reshape(-1, 3), axis=0)),
                     "toon: more bands, more colours")
        pftest.check(messages() == "", "toon bands: no error")
    else:
        pftest.check("velocity" in text and "still" in text, "brush without velocity: a warning (%s)" % text[:300])
        pftest.check(np.abs(image - first).max() > 20, "brush strokes change the picture")
        display.BrushVelocityArray = "height"  # one component: not a velocity
        pixels()
        text = messages()
        pftest.check("'height'" in text, "brush with a 1-component velocity array: a warning (%s)" % text[:300])
for script in ("P = np.zeros((0, 3))", "P = np.array([[0.0, -1.0, 0.0], [np.nan, 0.0, 0.0], [0.1, -1.0, 0.0]])"):
    odd = particles(script)
    oddDisplay = Show(odd, view)
    oddDisplay.SetRepresentationType("Brush Stroke Fluid")
    oddDisplay.BrushParticleRadius = 0.1
    pixels()
    text = messages()
    pftest.check("Error" not in text, "brush strokes on %s: no error (%s)" % (script, text[:300]))
    Hide(odd, view)
display.SetRepresentationType("Screen-Space Fluid")
messages()

# Zero particles, a single particle.
no_particles = particles("P = np.zeros((0, 3))")
emptyDisplay = Show(no_particles, view)
emptyDisplay.SetRepresentationType("Screen-Space Fluid")
pixels()
one = particles("P = np.array([[0.0, -1.0, 0.0]])")
oneDisplay = Show(one, view)
oneDisplay.SetRepresentationType("Screen-Space Fluid")
oneDisplay.FluidParticleRadius = 0.2
image = pixels()
pftest.check(messages() == "", "zero particles and one particle: no error")
Hide(one, view)
Hide(no_particles, view)

# A non-point input draws its points and says so.
Hide(ball, view)
sphere = Sphere(Radius=0.5, ThetaResolution=32, PhiResolution=32)
sphereDisplay = Show(sphere, view)
sphereDisplay.SetRepresentationType("Screen-Space Fluid")
sphereDisplay.FluidParticleRadius = 0.06
image = pixels()
text = messages()
pftest.check("draws the points of its input" in text, "a mesh input gives a warning (%s)" % text[:300])
pftest.check(fluid_pixels(image) > 1000, "a mesh input is drawn as its points")
Hide(sphere, view)

# A flat face stays flat at any zoom: the top of a lattice block seen from straight above, its
# particles 20 and 60 pixels in radius on screen (the smoothing's taps spread out, and the gaps
# where four spheres meet fill in): normals within 3 degrees rms of the face's, and no holes.
view.ViewSize = [800, 700]
view.CameraParallelProjection = 1
# (Names are long: the ProgrammableSource's numpy star import can rebind short globals.)
for radius_px, face_cells in ((20, 16), (60, 6)):
    lattice_step = 0.02
    pixels_per_spacing = radius_px / 0.6
    top = particles("h = %r\ng = lambda a, b: np.arange(a + h / 2, b, h)\n"
                    "P = np.stack(np.meshgrid(g(0, %d * h), g(0, %d * h), g(0, 3 * h), indexing='ij'), -1).reshape(-1, 3)\n"
                    % (lattice_step, face_cells, face_cells))
    shown = Show(top, view)
    shown.SetRepresentationType("Screen-Space Fluid")
    shown.ColorArrayName = [None, ""]
    shown.FluidDisplayMode = "Normals"
    shown.FluidParticleRadius = 0.6 * lattice_step  # the automatic radius of a particle_spacing
    Render(view)
    centre = 0.5 * face_cells * lattice_step
    view.CameraPosition = [centre, centre, 5.0]
    view.CameraFocalPoint = [centre, centre, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelScale = 350.0 / pixels_per_spacing * lattice_step
    normal = pixels() / 255.0 * 2.0 - 1.0
    half = 0.5 * face_cells * pixels_per_spacing
    y, x = np.mgrid[0:700, 0:800]
    inside = (np.abs(x + 0.5 - 400) < 0.5 * half) & (np.abs(y + 0.5 - 350) < 0.5 * half)
    tilt = np.degrees(np.arccos(np.clip(normal[..., 2] / np.linalg.norm(normal, axis=-1), -1.0, 1.0)))[inside]
    rms = float(np.sqrt((tilt ** 2).mean()))
    print("flat face, particles %d px: rms tilt %.2f degrees over %d pixels" % (radius_px, rms, inside.sum()))
    pftest.check(rms <= 3.0, "a flat face looks flat with %d-pixel particles (rms tilt %.2f degrees)" % (radius_px, rms))
    Hide(top, view)

# Silhouettes are smoothed: a lattice block's straight edges, turned 30 degrees on screen (so the
# filters' gap filling along rows and columns does not straighten them), stay straight instead of
# showing each particle's disc (splatted, the discs' outline wanders 0.08 radii rms about the line
# at 20 pixels, 0.09 at 60).
for radius_px, half_cells in ((20, 6), (60, 2)):
    lattice_step = 0.02
    pixels_per_spacing = radius_px / 0.6
    turned = particles("h, m = %r, %d\ng = lambda a, b: np.arange(a + h / 2, b, h)\n"
                       "P = np.stack(np.meshgrid(g(-m * h, m * h), g(-m * h, m * h), g(0, 3 * h), indexing='ij'), -1).reshape(-1, 3)\n"
                       "c, s = np.cos(np.radians(30)), np.sin(np.radians(30))\n"
                       "P = np.stack([c * P[:, 0] - s * P[:, 1], s * P[:, 0] + c * P[:, 1], P[:, 2]], 1)\n"
                       % (lattice_step, half_cells))
    shown = Show(turned, view)
    shown.SetRepresentationType("Screen-Space Fluid")
    shown.ColorArrayName = [None, ""]
    shown.FluidDisplayMode = "Normals"
    shown.FluidParticleRadius = 0.6 * lattice_step
    Render(view)
    view.CameraPosition = [0.0, 0.0, 5.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelScale = 350.0 / pixels_per_spacing * lattice_step
    image = pixels()
    fluid = np.abs(image - 51.0).max(axis=2) > 3
    rows = np.nonzero(fluid.any(axis=1))[0]
    tops = np.array([np.nonzero(fluid[:, c])[0].max() if fluid[:, c].any() else -1 for c in range(800)])
    # The edge from the top corner down to the right: the middle half of the columns between them.
    top_corner = int(np.argmax(tops))
    right_corner = int(np.nonzero(fluid.any(axis=0))[0].max())
    span = np.arange(top_corner + (right_corner - top_corner) // 4, right_corner - (right_corner - top_corner) // 4)
    fit = np.polyfit(span, tops[span], 1)
    wander = float((tops[span] - np.polyval(fit, span)).std())
    print("straight edge turned 30 degrees, particles %d px: outline wanders %.2f px rms (%.3f radii) over %d columns"
          % (radius_px, wander, wander / radius_px, len(span)))
    pftest.check(tops.max() < 690, "the turned block lies inside the view")
    pftest.check(wander <= 0.1 * radius_px, "a straight edge is smooth with %d-pixel particles (%.2f px rms)"
                 % (radius_px, wander))
    Hide(turned, view)
print("test_fluid_representation: all checks passed")
