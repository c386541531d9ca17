"""The Volumetric Cloud representation in ParaView (rendered under Xvfb with llvmpipe):
 - Beer-Lambert: a uniform slab seen through a parallel camera over a white background, with no
   light scattered, lets exp(-sigma L) of the white through, within 1 %;
 - depth compositing: an opaque box in front of the slab hides it, one behind it is dimmed by the
   slab's transmittance;
 - an empty volume draws nothing and runs no march (counted: in the samples display mode a march
   writes every pixel of the box);
 - empty-space skipping: on a volume with one puff in a corner it takes at least 4x fewer samples
   per pixel and changes the picture by at most a few levels;
 - a smoke plume whose fringe runs through the denormal floats draws no NaN (black) pixels;
 - a ball far denser than its grid resolves (extinction 1e6) is lit at its surface, not black;
 - a missing density array is an error that names it, without a crash."""
import builtins  # paraview.simple's star import shadows min, max and abs

import numpy as np
from paraview.simple import *
import pftest

pftest.load(globals())
errors = pftest.OutputWindowMessages()

W, H = 200, 160
view = CreateRenderView()
view.ViewSize = [W, H]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [1.0, 1.0, 1.0]


def grab():
    return pftest.grab(view)


def look_down(scale):
    Render(view)
    view.CameraPosition = [0.8, 0.8, 10.0]
    view.CameraFocalPoint = [0.8, 0.8, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = scale


def density_image(expression, n=16, spacing=0.1):
    """A n^3 image of `density` = expression(x, y, z) at its points (x, y, z in metres)."""
    source = ProgrammableSource(OutputDataSetType="vtkImageData")
    source.Script = f"""
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
out = self.GetOutput()
out.SetDimensions({n}, {n}, {n})
out.SetSpacing({spacing}, {spacing}, {spacing})
out.SetOrigin({spacing / 2}, {spacing / 2}, {spacing / 2})
z, y, x = np.meshgrid(*(np.arange({n}) * {spacing} + {spacing / 2},) * 3, indexing="ij")
d = numpy_to_vtk(np.ascontiguousarray(({expression}).astype(np.float32).ravel()), deep=1)
d.SetName("density")
out.GetPointData().SetScalars(d)
"""
    source.ScriptRequestInformation = f"""
from paraview import util
util.SetOutputWholeExtent(self, [0, {n - 1}, 0, {n - 1}, 0, {n - 1}])
"""
    return source


def show_cloud(source, **settings):
    display = Show(source, view)
    display.SetRepresentationType("Volumetric Cloud")
    for key, value in settings.items():
        setattr(display, key, value)
    return display


# --- Beer-Lambert through a uniform slab (L = 16 x 0.1 m: the samples' voxels) ------------------
slab_volume = density_image("np.ones_like(x)")
dark = dict(CloudLightIntensity=0.0, CloudSkyColor=[0.0, 0.0, 0.0], CloudMinTransmittance=0.0)
cloud = show_cloud(slab_volume, **dark)
look_down(1.2)
L = 1.6
for sigma in (0.25, 0.75, 1.5):
    cloud.CloudExtinction = sigma
    image = grab()
    centre = image[H // 2 - 20:H // 2 + 20, W // 2 - 20:W // 2 + 20].mean() / 255.0
    expected = np.exp(-sigma * L)
    print("slab, sigma %.2f /m: transmittance %.4f, exp(-sigma L) %.4f (%.2f %%)"
          % (sigma, centre, expected, 100 * (centre / expected - 1)))
    pftest.check(builtins.abs(centre / expected - 1) <= 0.01, "slab transmittance within 1 %% (sigma %.2f)" % sigma)
    corner = image[:10, :10].mean()
    pftest.check(corner == 255.0, "outside the slab the background is untouched (%.1f)" % corner)

# --- Depth compositing: a red box in front hides the slab, a green one behind is dimmed -------
cloud.CloudExtinction = 0.75
T = np.exp(-0.75 * L)
front_box = Box(Center=[0.5, 0.8, 3.0], XLength=0.4, YLength=0.4, ZLength=0.4)
behind_box = Box(Center=[1.1, 0.8, -2.0], XLength=0.4, YLength=0.4, ZLength=0.4)
for box, color in ((front_box, [1.0, 0.0, 0.0]), (behind_box, [0.0, 1.0, 0.0])):
    shown = Show(box, view)
    shown.AmbientColor = shown.DiffuseColor = color
    shown.Ambient, shown.Diffuse = 1.0, 0.0
with_cloud = grab()
Hide(slab_volume, view)
without = grab()
Show(slab_volume, view)
px = lambda x: int((x - 0.8) / 1.2 * H / 2 + W / 2)  # world x to pixel column at this scale
front_px = with_cloud[H // 2, px(0.5)]
pftest.check(np.abs(front_px - without[H // 2, px(0.5)]).max() <= 1, "the box in front hides the cloud: %s" % front_px)
behind_px = with_cloud[H // 2, px(1.1), 1] / 255.0
print("box behind the slab: green %.4f, T %.4f" % (behind_px, T))
pftest.check(builtins.abs(behind_px - T) <= 0.02, "the box behind is dimmed by T: %.4f vs %.4f" % (behind_px, T))
Delete(front_box)
Delete(behind_box)

# --- An empty volume: no march (in the samples mode a march writes every pixel of the box) -----
Hide(slab_volume, view)
view.Background = [0.2, 0.6, 0.2]
empty_volume = density_image("np.zeros_like(x)")
empty_cloud = show_cloud(empty_volume, CloudDisplayMode="Samples per pixel")
image = grab()
pftest.check(np.abs(image - np.array([0.2, 0.6, 0.2]) * 255).max() <= 1.0,
             "an empty volume leaves the background as it was (no pass ran)")
# The same volume with one dense voxel does run: the box's pixels are written.
spot_volume = density_image("np.where((x > 0.75) & (x < 0.85) & (y > 0.75) & (y < 0.85) & (z > 0.75) & (z < 0.85), 1.0, 0.0)")
spot_cloud = show_cloud(spot_volume, CloudDisplayMode="Samples per pixel")
Hide(empty_volume, view)
image = grab()
pftest.check(np.abs(image[H // 2, W // 2] - np.array([0.2, 0.6, 0.2]) * 255).max() > 10,
             "a volume with density is marched")
Hide(spot_volume, view)

# --- Empty-space skipping: a puff in one corner of a 64^3 volume -------------------------------
view.Background = [0.0, 0.0, 0.0]
puff_volume = density_image("np.exp(-((x - 0.8) ** 2 + (y - 0.8) ** 2 + (z - 0.8) ** 2) / (2 * 0.12 ** 2))"
              " * ((x - 0.8) ** 2 + (y - 0.8) ** 2 + (z - 0.8) ** 2 < 0.36 ** 2)", n=64, spacing=0.05)
puff_cloud = show_cloud(puff_volume, CloudExtinction=10.0)
Render(view)
view.CameraPosition = [4.0, -3.0, 5.0]
view.CameraFocalPoint = [1.6, 1.6, 1.6]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraParallelProjection = 0
view.ResetCamera()
samples, lit = {}, {}
for skipping in (0, 1):
    puff_cloud.CloudEmptySpaceSkipping = skipping
    puff_cloud.CloudDisplayMode = "Samples per pixel"
    samples[skipping] = grab()[:, :, 0].mean()
    puff_cloud.CloudDisplayMode = "Cloud"
    lit[skipping] = grab()
ratio = samples[0] / builtins.max(samples[1], 1e-9)
difference = np.abs(lit[0] - lit[1])
print("skipping: mean samples per pixel %.2f against %.2f (%.1fx fewer); picture difference mean %.3f, largest %d"
      % (samples[1], samples[0], ratio, difference.mean(), difference.max()))
pftest.check(ratio >= 4.0, "skipping takes at least 4x fewer samples (%.1fx)" % ratio)
pftest.check(difference.mean() < 0.5 and difference.max() <= 8, "skipping keeps the picture")

# --- A smoke plume's fringe: Stable Fluids leaves densities down in the denormal floats at the
# plume's edge, where extinction x density flushes to 0 on llvmpipe while the density is not 0;
# the step's scattering, (1 - exp(-sigma dt)) / sigma, was 0 / 0 there: NaN pixels drawn black in
# a ring round the plume's head. Lit from the camera's side under a bright sky, no pixel of the
# plume is dark (170 were before the fix, the darkest 2/255; after it the darkest is 70/255). ----
smoke_view = CreateRenderView()
smoke_view.ViewSize = [400, 300]
smoke_view.OrientationAxesVisibility = 0
smoke_view.UseColorPaletteForBackground = 0
smoke_view.Background = [1.0, 1.0, 1.0]
smoke = StableFluids(Bounds=[900, 1300, 900, 1300, 0, 600], Resolution=[32, 32, 48], TimeStep=0.5, OutputInterval=4.0,
                     NumberOfOutputs=6, EmitterBox=[1060, 1140, 1060, 1140, 0, 200], EmitterSpeed=6.0,
                     BuoyancyHeat=0.3, Vorticity=0.4)
plume = Show(smoke, smoke_view)
plume.SetRepresentationType("Volumetric Cloud")
for key, value in dict(CloudExtinction=0.15, CloudAlbedo=0.6, CloudLightMode="Sun", CloudStepSize=0.25,
                       CloudSunAzimuth=-90, CloudSunElevation=30, CloudSkyColor=[0.8, 0.85, 0.9]).items():
    setattr(plume, key, value)
smoke_view.ViewTime = 24.0
Render(smoke_view)
smoke_view.CameraPosition = [1000, -1100, 480]
smoke_view.CameraFocalPoint = [1000, 1000, 330]
smoke_view.CameraViewUp = [0, 0, 1]
smoke_view.CameraViewAngle = 30
darkest = pftest.grab(smoke_view).max(axis=2)
print("plume lit from the camera's side: darkest pixel %d, pixels below 20: %d" % (darkest.min(), (darkest < 20).sum()))
pftest.check((darkest < 20).sum() == 0, "no black (NaN) pixels at the plume's fringe")
Delete(smoke_view)

# --- A cloud far denser than its grid resolves is lit at its surface, not drawn black ----------
# A ball of density 1 on a 32^3 grid of 5 cm, the sun from the display's default direction, a
# blue sky behind. At extinction 1e6 every voxel is 5e4 optical depths deep; the light used to be
# read at the voxels' centres and the ball was drawn black (mean 7 of 255, against 124 at the
# default 8). Now it converges to its surface's look: as bright at 1e6 as at 1e4.
sky = [0.4, 0.5, 0.7]
view.Background = sky
ball = density_image("np.clip((0.6 - np.sqrt((x - 0.775) ** 2 + (y - 0.775) ** 2 + (z - 0.775) ** 2)) / 0.1, 0, 1)",
                     n=32, spacing=0.05)
ball_cloud = Show(ball, view)
ball_cloud.SetRepresentationType("Volumetric Cloud")
Render(view)
view.CameraParallelProjection = 0
view.CameraPosition = [0.775, -3.5, 0.775]
view.CameraFocalPoint = [0.775, 0.775, 0.775]
view.CameraViewUp = [0, 0, 1]
background = np.array(sky) * 255
brightness = {}
for extinction in (8.0, 1e4, 1e6):
    ball_cloud.CloudExtinction = extinction
    image = grab()
    inside = np.abs(image - background).sum(axis=2) > 6
    brightness[extinction] = image[inside].mean()
print("dense ball, mean brightness of its pixels: %s" % {k: round(v, 1) for k, v in brightness.items()})
pftest.check(brightness[1e6] > 0.8 * brightness[8.0], "a ball at extinction 1e6 is lit, not black: %r" % brightness)
pftest.check(abs(brightness[1e6] - brightness[1e4]) < 10.0, "denser than resolved, it looks the same: %r" % brightness)
Hide(ball, view)
view.Background = [1.0, 1.0, 1.0]

# --- A missing array: an error naming it, no crash ---------------------------------------------
errors.take()
puff_cloud.CloudDensityArray = "no_such_array"
grab()
text = errors.take()
pftest.check("no_such_array" in text, "a missing density array is named: %r" % text)
errors.stop()
print("volumetric cloud: OK")
