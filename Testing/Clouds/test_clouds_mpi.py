"""Stable Fluids and Volumetric Cloud in a 2-rank pvbatch: one grid in all (the first process
simulates, the others give an empty piece), and the cloud drawn once: the composited picture of
a uniform slab over a white background lets exp(-sigma L) through, as one process draws it."""
import numpy as np
from paraview.simple import *
import pftest

pftest.load(globals())
smoke = StableFluids(Resolution=[16, 16, 16], OutputInterval=0.1, NumberOfOutputs=2)
smoke.UpdatePipeline(0.2)
points = smoke.GetDataInformation().GetNumberOfPoints()
pftest.check(points == 16 ** 3, "one grid over both ranks: %d points" % points)

# A uniform slab 1.6 m thick (16 samples of 0.1 m), no light scattered: transmittance only.
slab = ProgrammableSource(OutputDataSetType="vtkImageData")
slab.Script = """
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
out = self.GetOutput()
out.SetDimensions(16, 16, 16)
out.SetSpacing(0.1, 0.1, 0.1)
out.SetOrigin(0.05, 0.05, 0.05)
d = numpy_to_vtk(np.ones(16 ** 3, dtype=np.float32), deep=1)
d.SetName("density")
out.GetPointData().SetScalars(d)
"""
slab.ScriptRequestInformation = """
from paraview import util
util.SetOutputWholeExtent(self, [0, 15, 0, 15, 0, 15])
"""
view = CreateRenderView()
view.ViewSize = [160, 120]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [1.0, 1.0, 1.0]
shown = Show(slab, view)
shown.SetRepresentationType("Volumetric Cloud")
shown.CloudLightIntensity = 0.0
shown.CloudSkyColor = [0.0, 0.0, 0.0]
shown.CloudMinTransmittance = 0.0
shown.CloudExtinction = 0.75
Render(view)
view.CameraPosition = [0.8, 0.8, 10.0]
view.CameraFocalPoint = [0.8, 0.8, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraParallelProjection = 1
view.CameraParallelScale = 1.2
image = pftest.grab(view)
h, w, _ = image.shape
centre = image[h // 2 - 10:h // 2 + 10, w // 2 - 10:w // 2 + 10].mean() / 255.0
expected = np.exp(-0.75 * 1.6)
print("2 ranks: slab transmittance %.4f, exp(-sigma L) %.4f" % (centre, expected))
pftest.check(abs(centre / expected - 1) <= 0.02, "the slab is drawn once (%.4f against %.4f)" % (centre, expected))
print("clouds mpi: OK")
