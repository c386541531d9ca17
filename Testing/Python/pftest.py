"""Shared helpers of the ParaFluid pvpython tests: plugin loading, array access, test files.

Test files are written by /usr/bin/python3 with h5py in a separate process, so that the pvpython
process only ever holds the HDF5 library ParaView links.
"""
import os
import subprocess
import sys
import tempfile

from paraview.simple import LoadPlugin
from paraview import servermanager
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.vtkConstants import VTK_STRING


def plugin_path():
    path = os.environ.get("PARAFLUID_PLUGIN")
    if not path or not os.path.exists(path):
        raise SystemExit("PARAFLUID_PLUGIN must name the built ParaFluid.so (got %r)" % path)
    return path


def load(namespace):
    LoadPlugin(plugin_path(), ns=namespace)


# ProgrammableSource scripts of particle scenes: particle_script(body) runs `body` with numpy
# imported as np; the body sets P (n x 3 positions) and may set `arrays` (point array name ->
# values per particle) and `h` (the spacing, stored as particle_spacing). The output gets the
# points, one vertex cell per particle and an int64 `id`, as the readers give.
_PARTICLE_HEAD = "import numpy as np\narrays = {}\n"
_PARTICLE_TAIL = """
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray
from vtkmodules.util.numpy_support import numpy_to_vtk
out = self.GetPolyDataOutput()
pts = vtkPoints()
pts.SetData(numpy_to_vtk(np.ascontiguousarray(P, dtype=np.float32), deep=True))
out.SetPoints(pts)
verts = vtkCellArray()
verts.SetData(numpy_to_vtk(np.arange(len(P) + 1, dtype=np.int64), deep=True),
              numpy_to_vtk(np.arange(len(P), dtype=np.int64), deep=True))
out.SetVerts(verts)
arrays["id"] = np.arange(len(P), dtype=np.int64)
for name, values in arrays.items():
    array = numpy_to_vtk(np.ascontiguousarray(values if values.dtype == np.int64 else values.astype(np.float32)), deep=True)
    array.SetName(name)
    out.GetPointData().AddArray(array)
if "h" in dir():
    spacing = numpy_to_vtk(np.array([h]), deep=True)
    spacing.SetName("particle_spacing")
    out.GetFieldData().AddArray(spacing)
"""


def particle_script(body):
    return _PARTICLE_HEAD + body + _PARTICLE_TAIL


# A collapsing water column (0.6 x 0.6 x 0.8 m, spacing 0.04 m) whose foot has slid out along +x,
# and a falling drop: P, and the particle counts of the column (c) and the foot (f).
DAM_BREAK_SCENE = """
h = 0.04
g = lambda a, b: np.arange(a + h / 2, b, h)
column = np.stack(np.meshgrid(g(0.0, 0.6), g(0.0, 0.6), g(0.0, 0.8), indexing='ij'), -1).reshape(-1, 3)
foot = np.stack(np.meshgrid(g(0.6, 1.3), g(0.0, 0.6), g(0.0, 0.12), indexing='ij'), -1).reshape(-1, 3)
b = np.arange(-0.16, 0.17, h)
B = np.stack(np.meshgrid(b, b, b, indexing='ij'), -1).reshape(-1, 3)
drop = B[np.linalg.norm(B, axis=1) <= 0.16] + np.array([1.0, 0.3, 0.6])
P = np.concatenate([column, foot, drop])
c, f = len(column), len(foot)
"""


def fetch(proxy, time=None):
    if time is not None:
        proxy.UpdatePipeline(time)
    else:
        proxy.UpdatePipeline()
    return servermanager.Fetch(proxy)


def point_array(data, name):
    array = data.GetPointData().GetArray(name)
    if array is None:
        raise AssertionError("point array %r missing; have %s" % (name, array_names(data)))
    return vtk_to_numpy(array)


def array_names(data):
    pd = data.GetPointData()
    return sorted(pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays()))


def points(data):
    return vtk_to_numpy(data.GetPoints().GetData())


def triangle_area(data):
    """The summed area of a triangle mesh's polygons (each a triangle) [m^2]."""
    import numpy as np
    p = points(data)
    tri = vtk_to_numpy(data.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    return 0.5 * np.linalg.norm(np.cross(p[tri[:, 1]] - p[tri[:, 0]], p[tri[:, 2]] - p[tri[:, 0]]), axis=1).sum()


def show_striped(surface, view):
    """Shows `surface` in `view` coloured by sin(12 x) cos(12 y) with the Rainbow Uniform preset over
    -1..1 and no scalar bar: the patterned ground the fluid image tests refract."""
    from paraview.simple import Calculator, ColorBy, GetColorTransferFunction, Show
    stripes = Calculator(Input=surface, ResultArrayName="stripes", Function="sin(12*coordsX)*cos(12*coordsY)")
    display = Show(stripes, view)
    ColorBy(display, ("POINTS", "stripes"))
    lut = GetColorTransferFunction("stripes")
    lut.ApplyPreset("Rainbow Uniform", True)
    lut.RescaleTransferFunction(-1.0, 1.0)
    display.SetScalarBarVisibility(view, False)
    return display


def mesh_seams(data):
    """A triangle mesh's open edges (used by one triangle) and duplicated triangles (the same three
    points, welded by position to 1e-9 m): (open edges, duplicates)."""
    import numpy as np
    p = points(data)
    tri = vtk_to_numpy(data.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    _, weld = np.unique(np.round(p / 1e-9).astype(np.int64), axis=0, return_inverse=True)
    tri = np.sort(weld.reshape(-1)[tri], axis=1)
    duplicates = len(tri) - len(np.unique(tri, axis=0))
    edges = np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [0, 2]]]), axis=1)
    _, uses = np.unique(edges, axis=0, return_counts=True)
    return int((uses == 1).sum()), int(duplicates)


def outside_mpi_environment():
    """This process's environment without its MPI job's variables: for a child that starts its own
    MPI job (a pvserver, a serial pvpython) from inside one, or from an MPI singleton."""
    return {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_", "OPAL_", "PRTE_"))}


class pvserver:
    """`with pvserver(ranks) as port:` a pvserver of `ranks` MPI processes (offscreen rendering) on a
    free local port, in its own MPI job outside this process's (pvpython is an MPI singleton);
    stopped on leaving. Its output is read away so that a full pipe never stops it."""

    def __init__(self, ranks=2):
        self.ranks = ranks

    def __enter__(self):
        import shutil
        import socket
        import threading
        with socket.socket() as probe:
            probe.bind(("localhost", 0))
            port = probe.getsockname()[1]
        self.server = subprocess.Popen(
            [shutil.which("mpirun"), "--allow-run-as-root", "--oversubscribe", "-np", str(self.ranks),
             "-x", "OMP_NUM_THREADS", "-x", "OMP_WAIT_POLICY", shutil.which("stdbuf"), "-oL",
             shutil.which("pvserver"), "--server-port=%d" % port, "--force-offscreen-rendering"],
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=outside_mpi_environment())
        for line in self.server.stdout:
            if "Accepting connection" in line:
                break
        if self.server.poll() is not None:
            self.__exit__(None, None, None)
            check(False, "pvserver did not start")
        threading.Thread(target=lambda: self.server.stdout.read(), daemon=True).start()
        return port

    def __exit__(self, *args):
        self.server.terminate()
        try:
            self.server.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self.server.kill()
        return False


def image_difference(png, reference):
    """VTK's vtkImageDifference of two PNG files of one size: (thresholded error, the filter)."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.vtkImagingCore import vtkImageDifference

    def read(path):
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        return reader.GetOutput()

    test, base = read(png), read(reference)
    check(test.GetDimensions() == base.GetDimensions(),
          "%s: image size %s != %s" % (png, test.GetDimensions(), base.GetDimensions()))
    diff = vtkImageDifference()
    diff.SetInputData(test)
    diff.SetImageData(base)
    diff.Update()
    return diff.GetThresholdedError(), diff


def scratch_dir():
    return tempfile.mkdtemp(prefix="parafluid-test-")


def write_h5(path, script):
    """Runs `script` with h5py imported and `f` an open, writable h5py.File at `path`."""
    program = "import h5py, numpy as np\nwith h5py.File(%r, 'w') as f:\n" % path
    program += "".join("    " + line + "\n" for line in script.strip().splitlines())
    subprocess.run(["/usr/bin/python3", "-c", program], check=True)


class ErrorCatcher:
    """Collects vtkErrorMacro messages of a proxy's VTK object instead of printing them."""

    def __init__(self, proxy):
        self.messages = []
        self.object = proxy.GetClientSideObject()
        self.tag = self.object.AddObserver("ErrorEvent", self._on_error)

    @calldata_type(VTK_STRING)
    def _on_error(self, caller, event, data=None):
        self.messages.append(str(data))

    def text(self):
        return "\n".join(self.messages)


class Messages:
    """Collects the errors and warnings of a VTK object (a proxy's client-side object)."""

    def __init__(self, obj):
        self.errors, self.warnings = [], []
        obj.AddObserver("ErrorEvent", self._on_error)
        obj.AddObserver("WarningEvent", self._on_warning)

    @calldata_type(VTK_STRING)
    def _on_error(self, caller, event, data=None):
        self.errors.append(str(data))

    @calldata_type(VTK_STRING)
    def _on_warning(self, caller, event, data=None):
        self.warnings.append(str(data))


class OutputWindowMessages:
    """Collects the errors and warnings that reach VTK's output window (what a render says) until
    the interpreter exits; take() returns them as one text and starts afresh."""

    def __init__(self):
        import atexit
        from vtkmodules.vtkCommonCore import vtkOutputWindow
        self.collected = []
        window = vtkOutputWindow.GetInstance()
        self.tags = [window.AddObserver(event, self._collect) for event in ("ErrorEvent", "WarningEvent")]
        atexit.register(self.stop)

    @calldata_type(VTK_STRING)
    def _collect(self, caller, event, text=None):
        self.collected.append("%s: %s" % (event, text))

    def take(self):
        text = "\n".join(self.collected)
        del self.collected[:]
        return text

    def stop(self):
        # A Python observer must not outlive the interpreter's shutdown.
        from vtkmodules.vtkCommonCore import vtkOutputWindow
        for tag in self.tags:
            vtkOutputWindow.GetInstance().RemoveObserver(tag)
        self.tags = []


def grab(view):
    """The view rendered now, as an (height, width, 3) float array of 0..255 (back buffer)."""
    from paraview.simple import Render
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

    Render(view)
    grabber = vtkWindowToImageFilter()
    grabber.SetInput(view.GetRenderWindow())
    grabber.ReadFrontBufferOff()
    grabber.Update()
    out = grabber.GetOutput()
    w, h, _ = out.GetDimensions()
    return vtk_to_numpy(out.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3].astype(float)


def check(condition, message):
    if not condition:
        print("FAILED: " + message, file=sys.stderr)
        raise SystemExit(1)


def compare_with_baseline(png, name, threshold=10.0):
    """Compares the image `png` with Baselines/<name> beside the test script by VTK's vtkImageDifference.
    Threshold: the thresholded error (VTK's regression-test measure; 10 is its default), which
    tolerates anti-aliasing and driver noise but not things in other places or other colours.
    Alternative baselines, as VTK's own tests keep them: Baselines/<stem>_1.png, _2.png, ... for a
    render that differs on another processor; the image must match one of them.
    With PARAFLUID_UPDATE_BASELINE set, the image becomes the new baseline instead."""
    import shutil
    from vtkmodules.vtkIOImage import vtkPNGWriter

    # Baselines live with the concern's tests: Testing/<Concern>/Baselines beside the calling script.
    caller = sys._getframe(1).f_code.co_filename
    baseline = os.path.join(os.path.dirname(os.path.abspath(caller)), "Baselines", name)
    if os.environ.get("PARAFLUID_UPDATE_BASELINE"):
        shutil.copyfile(png, baseline)
        print("baseline updated:", baseline)
    baselines = [baseline]
    stem, extension = os.path.splitext(baseline)
    while os.path.exists("%s_%d%s" % (stem, len(baselines), extension)):
        baselines.append("%s_%d%s" % (stem, len(baselines), extension))

    best = None
    for candidate in baselines:
        error, diff = image_difference(png, candidate)
        if best is None or error < best[0]:
            best = (error, diff, candidate)
    error, diff, closest = best
    print("%s: thresholded error %.3f (threshold %.1f)%s" %
          (name, error, threshold, "" if closest == baseline else " against " + os.path.basename(closest)))
    if error > threshold:
        writer = vtkPNGWriter()
        writer.SetFileName(os.path.splitext(png)[0] + "-difference.png")
        writer.SetInputConnection(diff.GetOutputPort())
        writer.Write()
        print("test image and difference kept in", os.path.dirname(png))
    check(error <= threshold, "%s: render differs from the baseline" % name)
