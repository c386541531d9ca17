"""Particle Surface (Marching Cubes) and Carpet Surface through real ParaView pipelines: a block of
particles gives a closed, manifold surface enclosing the particles' volume with interpolated
arrays; an empty input gives an empty surface; a missing spacing is refused clearly; the carpet
lies flat on a flat sheet, over a terrain surface reports the depth, falls once the particles have
gone, and restarts when time goes back."""
import numpy as np
from paraview.simple import *
from paraview import servermanager
from vtkmodules.vtkFiltersCore import vtkFeatureEdges, vtkMassProperties, vtkTriangleFilter
import pftest

pftest.load(globals())
d = 0.01
block = ParticleBlock(Spacing=d, BlockBounds=[0, 0.4, 0, 0.2, 0, 0.2], DomainBounds=[0, 0.8, 0, 0.2, 0, 0.6])
surface = ParticleSurfaceMarchingCubes(Input=block, CellSize=0.5, Smoothing=10)
surface.ArraysToInterpolate = ["density", "velocity"]
mesh = pftest.fetch(surface)
n = pftest.fetch(block).GetNumberOfPoints()

edges = vtkFeatureEdges()
edges.SetInputData(mesh)
edges.BoundaryEdgesOn()
edges.NonManifoldEdgesOn()
edges.FeatureEdgesOff()
edges.ManifoldEdgesOff()
edges.Update()
pftest.check(mesh.GetNumberOfCells() > 1000, "too few triangles: %d" % mesh.GetNumberOfCells())
pftest.check(edges.GetOutput().GetNumberOfCells() == 0,
             "%d boundary or non-manifold edges: the surface is not watertight" % edges.GetOutput().GetNumberOfCells())
mass = vtkMassProperties()
mass.SetInputData(mesh)
mass.Update()
expected = n * d ** 3
pftest.check(abs(mass.GetVolume() / expected - 1) < 0.05,
             "enclosed volume %.5g m^3, particles' volume %.5g m^3" % (mass.GetVolume(), expected))
names = pftest.array_names(mesh)
pftest.check("Normals" in names and "density" in names and "velocity" in names, "arrays: %s" % names)
density = pftest.point_array(mesh, "density")
pftest.check(np.allclose(density, 1000.0, rtol=1e-5), "interpolated rest density: %s" % density[:5])
normals = pftest.point_array(mesh, "Normals")
centre = np.array([0.2, 0.1, 0.1])
outward = np.einsum("ij,ij->i", normals, pftest.points(mesh) - centre)
pftest.check(np.mean(outward > 0) > 0.99, "normals should point out of the block")

# No particles: an empty surface and no error.
empty = Threshold(Input=block, Scalars=["POINTS", "density"], LowerThreshold=-2, UpperThreshold=-1)
empty_surface = ParticleSurfaceMarchingCubes(Input=empty, ParticleSpacing=d)
catcher = pftest.ErrorCatcher(empty_surface)
out = pftest.fetch(empty_surface)
pftest.check(out.GetNumberOfPoints() == 0 and not catcher.messages, "empty input: %d points, errors %r" % (out.GetNumberOfPoints(), catcher.text()))

# Points without a particle_spacing and no ParticleSpacing: refused with a message naming the property.
bare = PointSource(NumberOfPoints=50, Radius=0.1)
bare_surface = ParticleSurfaceMarchingCubes(Input=bare)
catcher = pftest.ErrorCatcher(bare_surface)
bare_surface.UpdatePipeline()
pftest.check("ParticleSpacing" in catcher.text(), "missing spacing: %r" % catcher.text())

# Carpet over a flat sheet (one layer at z = 0.005) above a terrain surface at z = -0.02.
sheet = ParticleBlock(Spacing=0.01, BlockBounds=[0.2, 0.6, 0.2, 0.6, 0.0, 0.01], DomainBounds=[0, 0.8, 0, 0.8, 0, 0.5])
ground = Plane(Origin=[0, 0, -0.02], Point1=[0.8, 0, -0.02], Point2=[0, 0.8, -0.02], XResolution=16, YResolution=16)
carpet = CarpetSurface(Input=sheet, Terrain=ground, Resolution=64)
flat = pftest.fetch(carpet)
z = pftest.points(flat)[:, 2]
pftest.check(flat.GetNumberOfCells() > 0 and np.allclose(z, 0.005, atol=1e-6), "carpet heights %s" % np.unique(z)[:5])
depth = pftest.point_array(flat, "depth")
pftest.check(np.allclose(depth, 0.025, atol=1e-5), "depth over the terrain: %s" % np.unique(depth)[:5])
# Raised above the sheet, the terrain hides it.
ground.Origin, ground.Point1, ground.Point2 = [0, 0, 0.01], [0.8, 0, 0.01], [0, 0.8, 0.01]
pftest.check(pftest.fetch(carpet).GetNumberOfCells() == 0, "a carpet under the terrain should not show")

# Over time: a sheet at z = 0.3 (t = 0), then particles over the left half only (t = 0.1). The
# right half falls h = 0.3 - g t^2 / 2 onto the flat floor of domain_bounds (z = 0); going back
# to t = 0 starts again from the full sheet.
path = pftest.scratch_dir() + "/sheet.h5part"
pftest.write_h5(path, """
f.attrs['particle_spacing'] = 0.01
f.attrs['domain_bounds'] = np.array([0.0, 1.0, 0.0, 1.0, 0.0, 1.0])
xs, ys = np.meshgrid(np.arange(0.005, 1.0, 0.01), np.arange(0.005, 1.0, 0.01))
for s, (t, keep) in enumerate([(0.0, xs < 2.0), (0.1, xs < 0.5)]):
    g = f.create_group('Step#%d' % s)
    g.attrs['TimeValue'] = t
    g['x'] = xs[keep]; g['y'] = ys[keep]; g['z'] = np.full(keep.sum(), 0.3)
""")
series = ParaFluidHDF5Particles(FileName=path)
falling = CarpetSurface(Input=series, Resolution=20)
def heights(t):
    data = pftest.fetch(falling, t)
    p = pftest.points(data)
    return p[:, 0], p[:, 2]
x, z = heights(0.0)
pftest.check(np.allclose(z, 0.3), "first frame: %s" % np.unique(z))
x, z = heights(0.1)
fallen = 0.3 - 0.5 * 9.81 * 0.1 ** 2
right = x > 0.55
pftest.check(np.allclose(z[x < 0.45], 0.3) and np.allclose(z[right], fallen, atol=1e-5),
             "after 0.1 s the right half should be at %.5f: %s" % (fallen, np.unique(z[right])[:4]))
x, z = heights(0.0)
pftest.check(np.allclose(z, 0.3) and x.max() > 0.9, "going back in time restarts the carpet")
print("particle surface: ok")
