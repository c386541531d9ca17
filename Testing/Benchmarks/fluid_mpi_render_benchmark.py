"""What Screen-Space Fluid costs when the rendering is shared between processes (run under Xvfb:
mpirun -np N pvbatch ...): `particles` particles spread over the processes by x, drawn at
1280 x 720 over a ground plane. Prints the first render after the data changed (it gathers the
particles on process 0) and the median of 10 renders of a turning camera (each sends the other
processes' colour and depth inside the fluid's rectangle to process 0)."""
import sys
import time

from paraview.simple import *
from paraview import servermanager
import os

particles = int(sys.argv[1]) if len(sys.argv) > 1 else 1000000
LoadPlugin(os.environ["PARAFLUID_PLUGIN"], ns=globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
particles_source = ProgrammableSource(OutputDataSetType="vtkPolyData", Script="""
import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
from vtkmodules.util.numpy_support import numpy_to_vtk
info = self.GetOutputInformation(0)
piece = info.Get(sddp.UPDATE_PIECE_NUMBER())
pieces = info.Get(sddp.UPDATE_NUMBER_OF_PIECES())
n = %d
side = round(n ** (1.0 / 3.0))
g = (np.arange(side) + 0.5) / side
P = np.stack(np.meshgrid(g, g, 0.5 * g, indexing='ij'), -1).reshape(-1, 3)
P = P[(P[:, 0] * pieces).astype(int) == piece]
points = vtkPoints()
points.SetData(numpy_to_vtk(np.ascontiguousarray(P, dtype=np.float32), deep=True))
self.GetPolyDataOutput().SetPoints(points)
""" % particles)
view = CreateRenderView()
view.ViewSize = [1280, 720]
view.OrientationAxesVisibility = 0
plane = Plane(Origin=[-1, -1, 0], Point1=[2, -1, 0], Point2=[-1, 2, 0])
Show(plane, view)
display = Show(particles_source, view)
display.SetRepresentationType("Screen-Space Fluid")
view.CameraPosition = [0.5, -2.0, 1.5]
view.CameraFocalPoint = [0.5, 0.5, 0.2]
view.CameraViewUp = [0, 0, 1]
particles_source.UpdatePipeline()
start = time.perf_counter()
Render(view)
first = time.perf_counter() - start
frames = []
camera = GetActiveCamera()
for k in range(10):
    camera.Azimuth(3)
    start = time.perf_counter()
    Render(view)
    frames.append(time.perf_counter() - start)
frames.sort()
print("processes %d, particles %d: first render %.3f s, a frame %.3f s (median of 10)"
      % (ranks, particles, first, frames[5]))
