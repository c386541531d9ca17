"""pvbatch on 2 MPI ranks renders the Screen-Space Fluid (each rank its own particles; ParaView
composites the ranks' images by depth). The same ball split between the ranks by x must look like
the ball held by rank 0 alone; prints how far the two images differ (the seam: each rank smooths
only its own particles' depth)."""
import numpy as np
from paraview.simple import *
from paraview import servermanager
from vtkmodules.util.numpy_support import vtk_to_numpy
import pftest

pftest.load(globals())
controller = servermanager.vtkProcessModule.GetProcessModule().GetGlobalController()
ranks = controller.GetNumberOfProcesses()
rank = controller.GetLocalProcessId()

SCRIPT = """
import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
from vtkmodules.util.numpy_support import numpy_to_vtk
piece = self.GetOutputInformation(0).Get(sddp.UPDATE_PIECE_NUMBER())
g = (np.arange(24) - 11.5) * 0.04
P = np.stack(np.meshgrid(g, g, g, indexing='ij'), -1).reshape(-1, 3)
P = P[np.linalg.norm(P, axis=1) <= 0.45]
if SPLIT:
    P = P[(P[:, 0] < 0.0) == (piece == 0)]
elif piece != 0:
    P = P[:0]
out = self.GetPolyDataOutput()
pts = vtkPoints()
pts.SetData(numpy_to_vtk(np.ascontiguousarray(P, dtype=np.float32), deep=True))
out.SetPoints(pts)
"""


def render(split):
    source = ProgrammableSource(OutputDataSetType="vtkPolyData")
    source.Script = SCRIPT.replace("SPLIT", "True" if split else "False")
    view = CreateRenderView()
    view.ViewSize = [300, 240]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    display = Show(source, view)
    display.SetRepresentationType("Screen-Space Fluid")
    display.ColorArrayName = [None, ""]
    display.FluidParticleRadius = 0.04
    display.FluidDisplayMode = "Opaque Surface"
    Render(view)
    view.CameraPosition = [0.0, -3.0, 0.4]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    Render(view)
    png = pftest.scratch_dir() + "/fluid.png"
    SaveScreenshot(png, view, ImageResolution=[300, 240])
    Delete(view)
    Delete(source)
    return png


def read(png):
    from vtkmodules.vtkIOImage import vtkPNGReader
    reader = vtkPNGReader()
    reader.SetFileName(png)
    reader.Update()
    data = reader.GetOutput()
    w, h, _ = data.GetDimensions()
    return vtk_to_numpy(data.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3].astype(float)


whole = render(split=False)
split = render(split=True)
if rank == 0:
    a, b = read(whole), read(split)
    fluid = a.sum(axis=2) > 0
    left = fluid[:, :150].sum()
    right = fluid[:, 150:].sum()
    diff = np.abs(a - b).max(axis=2)
    print("ranks %d: fluid pixels %d (left %d, right %d); split vs whole: mean |diff| %.2f, %.2f %% of pixels off by > 16, coverage %d vs %d"
          % (ranks, fluid.sum(), left, right, diff.mean(), 100.0 * (diff > 16).mean(), fluid.sum(), (b.sum(axis=2) > 0).sum()))
    pftest.check(ranks == 2, "runs on 2 ranks (got %d)" % ranks)
    pftest.check(left > 2000 and right > 2000, "both halves of the ball are drawn")
    pftest.check(abs(int((b.sum(axis=2) > 0).sum()) - int(fluid.sum())) < 0.02 * fluid.sum(), "the composited ball covers what the whole ball covers")
    pftest.check((diff > 16).mean() < 0.05, "the composited image matches the single-rank one outside the seam")
    print("test_mpi_fluid: all checks passed")
