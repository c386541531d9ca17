"""The Gerstner Ocean representation displaces a flat plane exactly as the Gerstner Ocean source
displaces its grid: both drawn white on black from the same grazing camera at the same time must
give the same image (up to a few silhouette pixels) and the same depth buffer. And the first try a
new user makes: Show(Plane()) as Gerstner Ocean, Reset Camera: the view's bounds hold the waves'
height, so the water is drawn, and a warning says the plane is far narrower than the waves."""
import numpy as np
from paraview.simple import *
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
from vtkmodules.util.numpy_support import vtk_to_numpy
import pftest

pftest.load(globals())

SIZE = [480, 320]
TIME = 3.3
view = None


def new_view():
    global view
    view = CreateRenderView()
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.Background = [0.0, 0.0, 0.0]
    view.UseColorPaletteForBackground = 0


def set_time(t):
    # The time keeper drives every view's time (and resets it when sources come and go).
    GetTimeKeeper().Time = t
    view.ViewTime = t


def capture(kind):
    Render(view)
    grab = vtkWindowToImageFilter()
    grab.SetInput(view.GetRenderWindow())
    grab.ReadFrontBufferOff()
    if kind == "depth":
        grab.SetInputBufferTypeToZBuffer()
    grab.Update()
    image = grab.GetOutput()
    array = vtk_to_numpy(image.GetPointData().GetScalars()).astype(np.float64)
    array = array.reshape(SIZE[1], SIZE[0], -1)
    if kind == "depth":
        # Depth buffer to distance along the view direction [m], with this render's clipping range
        # (it follows the visible bounds, which differ between the two).
        # Cleared depth (1, the far plane) stays NaN: the orientation-axes corner clears depth under
        # its viewport even when the axes are hidden.
        near, far = view.GetActiveCamera().GetClippingRange()
        array = np.where(array < 1.0, near * far / (far - array * (far - near)), np.nan)
    return array


def place_camera():
    Render(view)  # the first render of a view resets its camera; place it afterwards
    view.CameraPosition = [100.0, -15.0, 9.0]
    view.CameraFocalPoint = [100.0, 80.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 40.0
    view.CenterOfRotation = [100.0, 80.0, 0.0]


WAVES = [0.45, 30.0, 20.0, 0.6, 0.0, 0.2, 18.0, -10.0, 0.5, 1.0]
ELEVATION = "-8 + 9 * coordsX / 200 + 0.6 * exp(-((coordsX - 130) / 15)^2)"  # a beach with a bar


def flat_plane():
    return Plane(Origin=[0.0, 0.0, 0.0], Point1=[200.0, 0.0, 0.0], Point2=[0.0, 200.0, 0.0],
                 XResolution=400, YResolution=400)


cases = [("Storm", {"SeaState": "Storm"}), ("Swell", {"SeaState": "Swell"}),
         ("Beach", {"SeaState": "Custom (wave list)", "Waves": WAVES})]
for state, waves in cases:
    new_view()
    set_time(TIME)
    beach = state == "Beach"
    if beach:
        # The same terrain both ways: as a warped surface for the source, as a floor-elevation
        # array on the flat plane for the representation (rasterised onto the same 256^2 grid).
        floor = Calculator(Input=flat_plane(), ResultArrayName="Elevation", Function=ELEVATION)
        terrain = WarpByScalar(Input=floor, Scalars=["POINTS", "Elevation"])
        source = GerstnerOcean(Bathymetry=terrain, WindDirection=60.0, Origin=[0.0, 0.0], Size=[200.0, 200.0],
                               Resolution=[401, 401], **waves)
    else:
        source = GerstnerOcean(WindDirection=60.0, Origin=[0.0, 0.0], Size=[200.0, 200.0], Resolution=[401, 401], **waves)
    shown = Show(source, view)
    shown.ColorArrayName = [None, ""]
    shown.AmbientColor = [1.0, 1.0, 1.0]
    shown.DiffuseColor = [1.0, 1.0, 1.0]
    shown.Ambient = 1.0
    shown.Diffuse = 0.0
    shown.Specular = 0.0
    shown.Interpolation = "Flat"
    place_camera()
    source_rgb, source_depth = capture("rgb"), capture("depth")
    Hide(source, view)

    plane = Calculator(Input=flat_plane(), ResultArrayName="Elevation", Function=ELEVATION) if beach else flat_plane()
    ocean = Show(plane, view)
    ocean.SetRepresentationType("Gerstner Ocean")
    ocean.ColorArrayName = [None, ""]
    ocean.OceanSeaState = waves["SeaState"]
    if beach:
        ocean.OceanWaves = WAVES
        ocean.OceanBathymetryArray = "Elevation"
    ocean.OceanWindDirection = 60.0
    ocean.OceanShadingMode = "Solid colour"
    ocean.OceanSolidColor = [1.0, 1.0, 1.0]
    place_camera()
    ocean_rgb, ocean_depth = capture("rgb"), capture("depth")
    Hide(plane, view)

    water = source_rgb[..., 0] > 127
    pftest.check(0.3 < water.mean() < 0.95, "%s: the sea fills %.0f %% of the image" % (state, 100 * water.mean()))
    differing = np.mean(np.abs(source_rgb[..., 0] - ocean_rgb[..., 0]) > 127)
    both = water & (ocean_rgb[..., 0] > 127) & np.isfinite(source_depth[..., 0]) & np.isfinite(ocean_depth[..., 0])
    depth_error = np.abs(source_depth[..., 0] - ocean_depth[..., 0])[both]
    off = np.mean(depth_error > 0.01)
    print("%s: %.4f %% of pixels differ in colour; depth |difference| median %.2e m, 95th percentile %.2e m, "
          "%.3f %% of water pixels off by more than 1 cm"
          % (state, 100 * differing, np.median(depth_error), np.percentile(depth_error, 95), 100 * off))
    # Thresholds: silhouette pixels where float (GPU) and double (CPU) round differently.
    pftest.check(differing < 0.002, "%s: %.3f %% of pixels differ between source and representation" % (state, 100 * differing))
    # Depth: at grazing angles every crest hides the water behind it, and a sub-pixel difference
    # in where a crest's edge falls swaps crest and background in a pixel (metres apart).
    pftest.check(np.median(depth_error) < 0.002, "%s: median depth difference %g m" % (state, np.median(depth_error)))
    pftest.check(off < 0.02, "%s: %.2f %% of pixels are more than 1 cm apart in depth" % (state, 100 * off))

    if not beach:
        last = (state, plane, ocean_depth, both, np.median(depth_error))

# The comparison can tell waves apart: half a second later the depths have moved far more.
state, plane, ocean_depth, both, agreement = last
Show(plane, view)
set_time(TIME + 0.5)
later = capture("depth")
moved = np.nanmedian(np.abs(later[..., 0] - ocean_depth[..., 0])[both])
pftest.check(moved > 20 * agreement, "%s: 0.5 s later the depth moved by only %g m" % (state, moved))

# First try: ParaView's default 1 m plane, a storm, Reset Camera. The representation's bounds must
# include the waves (else the clipping range, set from a flat plane, cuts them all away), and a
# warning must say why the sea looks like a tilting sheet and what to change.
from vtkmodules.vtkCommonCore import vtkOutputWindow
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING

warnings = []


@calldata_type(VTK_STRING)
def keep(caller, event, text=None):
    warnings.append(str(text))


tag = vtkOutputWindow.GetInstance().AddObserver("WarningEvent", keep)
new_view()
first = Plane()
shown = Show(first, view)
shown.SetRepresentationType("Gerstner Ocean")
shown.OceanSeaState = "Storm"
set_time(TIME)
Render(view)
view.ResetCamera()
Render(view)
vtkOutputWindow.GetInstance().RemoveObserver(tag)
image = capture("color")
drawn = (image.max(axis=2) > 0).mean()
pftest.check(drawn > 0.001, "the ocean on the default plane is drawn after Reset Camera (%.1f %% of pixels)" % (100 * drawn))
said = " ".join(warnings)
pftest.check("shortest wave" in said and "Plane" in said, "a warning says the plane is narrower than the waves: %s" % said[:300])
print("ocean representation: ok")
