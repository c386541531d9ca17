"""docs/three_ways.png: the same dam break drawn the three ways ParaFluid draws particle water:
Ray-Marched Fluid, Screen-Space Fluid, and Particle Surface's mesh in the Surface representation
(all transparent or default-shaded, over the same coloured ground and sky).

  PARAFLUID_PLUGIN=build/lib/paraview-5.11/plugins/ParaFluid/ParaFluid.so \\
    scripts/with-xvfb.sh pvpython scripts/three_ways_picture.py [docs/three_ways.png]"""
import os
import sys

from paraview.simple import *
import numpy as np
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Testing", "Python"))
import pftest

pftest.load(globals())
target = sys.argv[1] if len(sys.argv) > 1 else "docs/three_ways.png"
SIZE = [480, 360]
particles = ProgrammableSource(OutputDataSetType="vtkPolyData")
particles.Script = pftest.particle_script(pftest.DAM_BREAK_SCENE)


def panel(name, build):
    view = CreateRenderView()
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.25, 0.3, 0.4]
    view.Background2 = [0.75, 0.85, 0.95]
    view.BackgroundColorMode = "Gradient"
    plane = Plane(Origin=[-0.6, -0.6, 0.0], Point1=[2.0, -0.6, 0.0], Point2=[-0.6, 1.4, 0.0], XResolution=52,
                  YResolution=40)
    ground = Show(Calculator(Input=plane, ResultArrayName="stripes", Function="sin(12*coordsX)*cos(12*coordsY)"), view)
    ColorBy(ground, ("POINTS", "stripes"))
    GetColorTransferFunction("stripes").ApplyPreset("Rainbow Uniform", True)
    ground.SetScalarBarVisibility(view, False)
    build(view)
    Render(view)
    view.CameraPosition = [2.6, -2.2, 1.6]
    view.CameraFocalPoint = [0.65, 0.3, 0.3]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0
    png = os.path.join(pftest.scratch_dir(), name)
    SaveScreenshot(png, view, ImageResolution=SIZE)
    Delete(view)
    return png


def ray_marched(view):
    shown = Show(particles, view)
    shown.SetRepresentationType("Ray-Marched Fluid")
    shown.ColorArrayName = [None, ""]
    shown.RayMarchAttenuationDistance = 0.5


def screen_space(view):
    shown = Show(particles, view)
    shown.SetRepresentationType("Screen-Space Fluid")
    shown.ColorArrayName = [None, ""]
    shown.FluidAttenuationDistance = 0.5


def meshed(view):
    shown = Show(ParticleSurfaceMarchingCubes(Input=particles, KernelRadius=2.0), view)
    shown.ColorArrayName = [None, ""]
    shown.DiffuseColor = [0.1, 0.45, 0.75]
    shown.Specular = 0.6
    shown.Opacity = 0.7


panels = []
for name, build in (("ray.png", ray_marched), ("screen.png", screen_space), ("mesh.png", meshed)):
    reader = vtkPNGReader()
    reader.SetFileName(panel(name, build))
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    panels.append(vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3])
joined = np.ascontiguousarray(np.concatenate(panels, axis=1))
out = vtkImageData()
out.SetDimensions(joined.shape[1], joined.shape[0], 1)
out.GetPointData().SetScalars(numpy_to_vtk(joined.reshape(-1, 3), deep=True))
writer = vtkPNGWriter()
writer.SetFileName(target)
writer.SetInputData(out)
writer.Write()
print("wrote", target)
