"""The Ray-Marched Fluid representation in ParaView (rendered under Xvfb with llvmpipe):
 - accuracy: on a lattice ball the ray-marched surface's depth lies within 0.1 d of the sphere
   holding the particles' volume and within 0.05 d of Particle Surface's marching-cubes mesh of
   the same field (rendered by the Surface representation from the same camera);
 - empty-space skipping (the occupancy grid, and with it the start/stop splats) changes no pixel
   by more than 1/255 against the brute-force march, from afar and close up, and cuts the mean
   samples per pixel by at least 5x on a dam-break block with 5 % spray droplets (counted by the
   Steps display mode); the splats never add samples;
 - refraction: a slab over stripes shifts the stripe edges by what Snell's law gives for its
   thickness (within 1 pixel); Beer-Lambert: a slab's transmittance is exp(-sigma L) within 2 %;
 - depth compositing with an opaque box, every display mode, reduced resolution, colouring by an
   array, and zero / one / NaN particles, without an error."""
import builtins  # paraview.simple's star import shadows min, max and abs
import math

import numpy as np
from paraview.simple import *
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
import pftest

pftest.load(globals())
messages = pftest.OutputWindowMessages().take


def particles(body):
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = pftest.particle_script(body)
    return source


W, H = 320, 240
view = CreateRenderView()
view.ViewSize = [W, H]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]


def grab(depth=False):
    Render(view)
    g = vtkWindowToImageFilter()
    g.SetInput(view.GetRenderWindow())
    g.ReadFrontBufferOff()
    if depth:
        g.SetInputBufferTypeToZBuffer()
    g.Update()
    out = g.GetOutput()
    w, h, _ = out.GetDimensions()
    a = vtk_to_numpy(out.GetPointData().GetScalars())
    return a.reshape(h, w) if depth else a.reshape(h, w, -1)[:, :, :3].astype(float)


def look(position, focal, up, scale):
    Render(view)
    view.CameraPosition = position
    view.CameraFocalPoint = focal
    view.CameraViewUp = up
    view.CameraParallelProjection = 1
    view.CameraParallelScale = scale


def eye_distance(depth):
    """Window depth -> distance along the view [world units] (parallel projection: linear)."""
    near, far = view.GetActiveCamera().GetClippingRange()
    return near + depth * (far - near)


def fluid(source, mode="Opaque Surface", spacing=0.0):
    shown = Show(source, view)
    shown.SetRepresentationType("Ray-Marched Fluid")
    shown.ColorArrayName = [None, ""]
    shown.RayMarchDisplayMode = mode
    shown.RayMarchParticleSpacing = spacing
    return shown


# --- Accuracy: the same surface as Particle Surface; the sphere of a spherical particle set -------
d = 0.04
SCALE = 0.6
pixel = 2.0 * SCALE / H
X, Z = np.meshgrid((np.arange(W) + 0.5 - W / 2) * pixel, (np.arange(H) + 0.5 - H / 2) * pixel)
rho2 = X ** 2 + Z ** 2

lattice = particles("""
g = (np.arange(24) - 11.5) * 0.04
P = np.stack(np.meshgrid(g, g, g, indexing='ij'), -1).reshape(-1, 3)
P = P[np.linalg.norm(P, axis=1) <= 0.45]
arrays["height"] = P[:, 2]
""")
# Concentric shells of Fibonacci points d apart: a particle set that is a sphere (a lattice ball's
# own boundary steps by up to half a spacing, whatever draws it).
shells = particles("""
d = 0.04
rings = []
for k in range(11):
    r = (k + 0.5) * d
    n = int(round(4.0 * np.pi * r * r / (d * d))) or 1
    i = np.arange(n) + 0.5
    z = 1.0 - 2.0 * i / n
    a = np.pi * (1.0 + 5.0 ** 0.5) * i
    s = np.sqrt(1.0 - z * z)
    rings.append(r * np.stack([s * np.cos(a), s * np.sin(a), z], 1))
P = np.concatenate(rings)
""")


def ball_depth(source):
    shown = fluid(source, spacing=d)
    look([0.0, -3.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0], SCALE)
    depth = eye_distance(grab(depth=True))
    Hide(source, view)
    return depth


def radial_error(source, depth):
    """Distance of each hit from the sphere of the particles' volume [d], over pixels within 60
    degrees of facing the eye."""
    radius = (3.0 * pftest.fetch(source).GetNumberOfPoints() * d ** 3 / (4.0 * math.pi)) ** (1.0 / 3.0)
    facing = rho2 < (radius * math.sin(math.radians(60))) ** 2
    return (np.sqrt(rho2 + (depth - 3.0) ** 2) - radius)[facing] / d, facing


# (Not "source": paraview.simple rebinds that global name when the view's representations change.)
for name, particle_set in (("lattice ball", lattice), ("shell ball", shells)):
    depth = ball_depth(particle_set)
    pftest.check(messages() == "", "no error rendering the %s" % name)
    error, facing = radial_error(particle_set, depth)
    print("%s against the sphere of the particles' volume (%d px): mean %+.4f d, rms %.4f d, max %.4f d"
          % (name, facing.sum(), error.mean(), np.sqrt((error ** 2).mean()), np.abs(error).max()))
    if particle_set is shells:
        pftest.check(np.abs(error).max() <= 0.1, "the shell ball lies within 0.1 d of the analytic sphere (max %.3f d)"
                     % np.abs(error).max())
    mesh = ParticleSurfaceMarchingCubes(Input=particle_set, ParticleSpacing=d, KernelRadius=2.0, IsoValue=0.5, CellSize=0.25,
                                        Smoothing=0)
    surface = Show(mesh, view)
    surface.ColorArrayName = [None, ""]
    meshed = eye_distance(grab(depth=True))
    Hide(mesh, view)
    gap = (depth - meshed)[facing] / d
    print("%s against Particle Surface's mesh (cell 0.25 d): mean %+.4f d, rms %.4f d, max %.4f d"
          % (name, gap.mean(), np.sqrt((gap ** 2).mean()), np.abs(gap).max()))
    pftest.check(np.abs(gap).max() <= 0.05, "the %s lies within 0.05 d of the marching-cubes mesh (max %.3f d)"
                 % (name, np.abs(gap).max()))
view.CameraParallelProjection = 0

# --- Empty-space skipping: same picture, far fewer samples ---------------------------------------
# A block with 5 % of its particles as spray droplets of 2 x 2 x 2 particles (each with a surface
# of its own) in the air above it. Three ways: brute force (no skipping), the occupancy grid only,
# and the occupancy grid with the start/stop splats (splash and bulk apart; the default).
dam = particles("""
h = 0.025
g = lambda a, b: np.arange(a + h / 2, b, h)
block = np.stack(np.meshgrid(g(0.0, 1.0), g(0.0, 0.5), g(0.0, 0.5), indexing='ij'), -1).reshape(-1, 3)
rng = np.random.default_rng(3)
centres = rng.uniform([0.0, 0.0, 0.7], [2.0, 0.5, 1.5], (len(block) // 20 // 8, 3))
corners = np.stack(np.meshgrid([0, h], [0, h], [0, h], indexing='ij'), -1).reshape(-1, 3)
P = np.concatenate([block, (centres[:, None, :] + corners[None, :, :]).reshape(-1, 3)])
""")
shown = fluid(dam, spacing=0.025)
Render(view)
WAYS = {"brute force": (0, 0), "occupancy grid": (1, 0), "occupancy grid + splats": (1, 1)}


def compare_ways(label):
    images, steps = {}, {}
    for way, (skipping, splats) in WAYS.items():
        shown.RayMarchEmptySpaceSkipping = skipping
        shown.RayMarchStartStopSplats = splats
        shown.RayMarchDisplayMode = "Opaque Surface"
        images[way] = grab()
        shown.RayMarchDisplayMode = "Steps"
        steps[way] = grab()[:, :, 0].mean()  # samples per pixel (red, one level each; 0 where no ray sampled)
    pftest.check(messages() == "", "no error in the skipping comparison (%s)" % label)
    for way in ("occupancy grid", "occupancy grid + splats"):
        difference = np.abs(images[way] - images["brute force"]).max()
        print("%s, %s: mean samples per pixel %.2f (brute force %.2f, %.1fx fewer); largest pixel difference %d"
              % (label, way, steps[way], steps["brute force"], steps["brute force"] / builtins.max(steps[way], 1e-9),
                 difference))
        pftest.check(difference <= 1, "%s (%s) changes no pixel by more than 1/255 (largest %d)" % (way, label, difference))
    pftest.check(images["brute force"][:, :, :3].max() > 0, "the fluid is drawn (%s)" % label)
    return steps


view.CameraPosition = [1.0, -2.6, 1.4]
view.CameraFocalPoint = [1.0, 0.25, 0.5]
view.CameraViewUp = [0.0, 0.0, 1.0]
steps = compare_ways("whole scene")
ratio = steps["brute force"] / builtins.max(steps["occupancy grid + splats"], 1e-9)
pftest.check(ratio >= 5.0, "skipping cuts the mean samples per pixel by at least 5x (%.1fx)" % ratio)
pftest.check(steps["occupancy grid + splats"] <= steps["occupancy grid"] + 1e-9,
             "the splats' start and stop never add samples (%.2f against %.2f)"
             % (steps["occupancy grid + splats"], steps["occupancy grid"]))
# Close up, the fluid reaches past the window's edges: the splats are drawn as quads, not points.
view.CameraPosition = [0.6, -0.45, 0.75]
view.CameraFocalPoint = [0.7, 0.25, 0.4]
compare_ways("close up")
Hide(dam, view)
shown.RayMarchEmptySpaceSkipping = 1
shown.RayMarchStartStopSplats = 1


# --- Refraction and Beer-Lambert on slabs ----------------------------------------------------------
def stripes(z, width, white=False):
    """A ground at height z of unlit stripes `width` wide across x (black and white cells; all
    white when `white`)."""
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = """
import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkCellArray
out = self.GetPolyDataOutput()
z, w, white = %r, %r, %r
xs = np.arange(-1.0, 1.0 + 1e-9, w)
pts, cells = vtkPoints(), vtkCellArray()
rgb = vtkUnsignedCharArray()
rgb.SetName('rgb')
rgb.SetNumberOfComponents(3)
for i in range(len(xs) - 1):
    ids = [pts.InsertNextPoint(x, y, z) for x, y in ((xs[i], -1.0), (xs[i + 1], -1.0), (xs[i + 1], 1.0), (xs[i], 1.0))]
    cells.InsertNextCell(4, ids)
    c = 255 if white or i %% 2 == 0 else 0
    rgb.InsertNextTuple3(c, c, c)
out.SetPoints(pts)
out.SetPolys(cells)
out.GetCellData().SetScalars(rgb)
""" % (z, width, white)
    shown = Show(source, view)
    ColorBy(shown, ("CELLS", "rgb"))
    shown.MapScalars = 0
    shown.Ambient = 1.0
    shown.Diffuse = 0.0
    shown.Specular = 0.0
    return source


def slab(top, spacing):
    return particles("""
h = %r
g = lambda a, b: np.arange(a + h / 2, b, h)
P = np.stack(np.meshgrid(g(-0.6, 0.6), g(-0.6, 0.6), g(0.0, %r), indexing='ij'), -1).reshape(-1, 3)
""" % (spacing, top))


def clear_fluid(source, index, color=(1.0, 1.0, 1.0), attenuation=1.0):
    shown = fluid(source, "Transparent Fluid", spacing=0.02)
    shown.RayMarchRefractiveIndex = index
    shown.RayMarchColor = list(color)
    shown.RayMarchAttenuationDistance = attenuation
    shown.RayMarchSpecular = 0.0
    return shown


def edges(column):
    """Sub-pixel rows where the column crosses half its range, and whether it rises there."""
    level = 0.5 * (column.max() + column.min())
    above = column > level
    rows = np.nonzero(above[1:] != above[:-1])[0]
    return [(r + (level - column[r]) / (column[r + 1] - column[r]), bool(above[r + 1])) for r in rows]


def edge_shifts(before, after):
    """How far each edge of `after` lies from the nearest edge of the same direction in `before`."""
    shifts = []
    span = builtins.max([r for r, _ in before] + [0.0])
    for row, rising in after:
        if row < 20.0 or row > span - 20.0:
            continue  # the matching edge may lie outside the window
        candidates = [r - row for r, up in before if up == rising]
        if candidates:
            shifts.append(-builtins.min(candidates, key=lambda c: c * c))
    # (Edges are found to the pixel: the stripes are unlit and not antialiased.)
    return shifts


THICKNESS, THETA, N = 0.2, math.radians(45.0), 1.33
ground = stripes(0.0, 0.1)
water = slab(THICKNESS, 0.02)
look([-2.0 * math.sin(THETA), 0.0, 2.0 * math.cos(THETA)], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 0.5)
bare = grab()[:, :, 0]
clear_fluid(water, N)
bent = grab()[:, :, 0]
pftest.check(messages() == "", "no error rendering the slab")
pixel = 2.0 * 0.5 / H
expected = THICKNESS * (math.tan(THETA) - math.tan(math.asin(math.sin(THETA) / N))) * math.cos(THETA) / pixel
shifts = []
for x in range(W // 2 - 40, W // 2 + 41, 10):
    shifts.extend(edge_shifts(edges(bare[60:180, x]), edges(bent[60:180, x])))
measured = float(np.abs(np.mean(shifts))) if shifts else float("nan")
print("slab %.2f m thick at %.0f degrees: stripe edges move %.2f px (Snell: %.2f px, %d edges)"
      % (THICKNESS, math.degrees(THETA), measured, expected, len(shifts)))
pftest.check(len(shifts) >= 10 and builtins.abs(measured - expected) <= 1.0,
             "refraction moves the stripes by Snell's amount within 1 pixel (%.2f against %.2f)" % (measured, expected))
Hide(water, view)
Hide(ground, view)

# Beer-Lambert: looking straight down through the slab (index 1: no bending, no reflection) at
# a white ground below it.
white = stripes(-0.3, 0.5, white=True)
look([0.0, 0.0, 2.0], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0], 0.5)
COLOR, ATTENUATION = (0.5, 0.7, 0.9), 0.4
clear_fluid(water, 1.0, COLOR, ATTENUATION)
seen = grab()[H // 2 - 20:H // 2 + 20, W // 2 - 20:W // 2 + 20].reshape(-1, 3).mean(axis=0) / 255.0
expected = np.array(COLOR) ** (THICKNESS / ATTENUATION)  # exp(-sigma L), sigma = -ln(colour) / attenuation
print("slab transmittance %s, Beer-Lambert %s" % (np.round(seen, 4), np.round(expected, 4)))
pftest.check(np.all(np.abs(seen / expected - 1.0) <= 0.02), "the slab's transmittance is exp(-sigma L) within 2 %")
Hide(water, view)
Hide(white, view)

# --- Depth compositing, display modes, resolution, colouring, bad input -----------------------------
ball = lattice
shown = fluid(ball, spacing=d)
Render(view)
view.CameraParallelProjection = 0
view.CameraPosition = [0.0, -3.0, 0.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.Background = [0.2, 0.2, 0.2]


def covered(image):
    return int((np.abs(image - 51.0).max(axis=2) > 3).sum())


base = covered(grab())
pftest.check(base > 2000, "the ball covers the middle of the view (%d pixels)" % base)
for mode in ("Opaque Surface", "Transparent Fluid", "Normals", "Steps"):
    shown.RayMarchDisplayMode = mode
    for scale in (1.0, 0.5, 0.25):
        shown.RayMarchResolutionScale = scale
        n = covered(grab())
        text = messages()
        # (Steps also shows the rays that sampled near the ball and missed it.)
        drawn = n > 0.9 * base if mode == "Steps" else builtins.abs(n - base) < 0.1 * base
        pftest.check(text == "" and drawn,
                     "%s at resolution scale %g draws the ball (%d pixels) without an error (%s)" % (mode, scale, n, text[:300]))
shown.RayMarchResolutionScale = 1.0
shown.RayMarchDisplayMode = "Opaque Surface"
plain = grab()
ColorBy(shown, ("POINTS", "height"))
pftest.check(np.abs(grab() - plain).mean() > 1.0, "colouring by 'height' changes the picture")
shown.ColorArrayName = [None, ""]


def red_box(center, lengths):
    box = Box(Center=center, XLength=lengths[0], YLength=lengths[1], ZLength=lengths[2])
    boxed = Show(box, view)
    boxed.ColorArrayName = [None, ""]
    boxed.DiffuseColor = [1.0, 0.0, 0.0]
    boxed.AmbientColor = [1.0, 0.0, 0.0]
    boxed.Ambient = 1.0
    boxed.Diffuse = 0.0
    return box


front = red_box([0.0, -1.0, 0.0], [0.3, 0.1, 0.3])
centre = grab()[H // 2, W // 2]
pftest.check(centre[0] > 200 and centre[1] < 30, "the box in front hides the fluid (centre %s)" % centre)
Hide(front, view)
behind = red_box([0.0, 1.0, 0.0], [2.0, 0.1, 2.0])
centre = grab()[H // 2, W // 2]
pftest.check(centre[0] < 150 or centre[2] > 60, "the fluid hides the box behind it (centre %s)" % centre)
Hide(behind, view)

for name, body in (("zero particles", "P = np.zeros((0, 3))"), ("one particle", "P = np.zeros((1, 3))"),
                   ("NaN particles", "P = np.full((5, 3), np.nan)"),
                   ("a ball with NaN particles", "g = (np.arange(8) - 3.5) * 0.05\n"
                    "P = np.stack(np.meshgrid(g, g, g, indexing='ij'), -1).reshape(-1, 3)\nP[::7] = np.nan")):
    odd = particles(body)
    oddly = fluid(odd)
    for mode in ("Opaque Surface", "Transparent Fluid"):
        oddly.RayMarchDisplayMode = mode
        grab()
        text = messages()
        pftest.check(text == "", "%s, %s: no error (%s)" % (name, mode, text[:300]))
    Hide(odd, view)
print("ray-marched fluid: all checks passed")
