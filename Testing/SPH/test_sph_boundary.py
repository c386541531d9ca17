"""SPH Step with a Boundary surface and the DFSPH solver, through real ParaView pipelines: water
poured on a sphere never gets inside it; water resting on a mesh floor is at rest density with
BoundaryWall and below it without; optional arrays appear only when asked; a Boundary without
polygons is refused with a clear message; the WallFriction choices slow a collapsing column on the
walls they are set for."""
import numpy as np
from paraview.simple import *
import pftest

pftest.load(globals())
centre, radius = np.array([0.2, 0.05, 0.12]), 0.08
ball = Sphere(Center=list(centre), Radius=radius, ThetaResolution=32, PhiResolution=32)
block = ParticleBlock(Spacing=0.02, BlockBounds=[0.1, 0.3, 0, 0.1, 0.24, 0.4], DomainBounds=[0, 0.4, 0, 0.1, 0, 0.5])
sph = SPHStep(Input=block, Boundary=ball, PressureSolver="DFSPH", OutputInterval=0.05, NumberOfOutputs=6,
              OutputPressure=0, OutputAcceleration=1, OutputNeighbourCount=1)

# The triangulated sphere lies inside the true one; its flat facets come no closer to the centre
# than R cos(pi/32) cos(pi/62) > 0.99 R.
closest = 1.0
for t in sph.TimestepValues[1:]:
    data = pftest.fetch(sph, t)
    distance = np.linalg.norm(pftest.points(data) - centre, axis=1)
    closest = min(closest, distance.min())
    pftest.check(np.all(np.isfinite(pftest.points(data))), "non-finite positions at t = %g" % t)
pftest.check(closest > 0.99 * radius, "a particle got inside the sphere: %.4f m from its centre (radius %.2f)" % (closest, radius))
final = pftest.points(data)
pftest.check(final[:, 2].min() < 0.1, "water should have run down past the sphere (lowest z %.3f)" % final[:, 2].min())

names = pftest.array_names(data)
pftest.check("pressure" not in names, "pressure was switched off but is in the output: %s" % names)
pftest.check("acceleration" in names and "neighbour_count" in names, "optional arrays missing: %s" % names)
counts = pftest.point_array(data, "neighbour_count")
pftest.check(10 <= np.median(counts) <= 40, "median neighbour count %g is implausible at h = 2 spacings" % np.median(counts))

sph.UpdatePropertyInformation()
error = sph.GetPropertyValue("MeanDensityError")
pftest.check(0.0 <= error < 0.005, "DFSPH mean density error %g" % error)

# BoundaryWall (on by default): water resting on a mesh floor sits at rest density in its bottom
# layer; with the mesh only stopping particles, that layer's cut neighbourhood sums to less.
floor = Plane(Origin=[-0.1, -0.1, 0.1], Point1=[0.5, -0.1, 0.1], Point2=[-0.1, 0.2, 0.1])
resting = ParticleBlock(Spacing=0.02, BlockBounds=[0, 0.4, 0, 0.1, 0.1, 0.22], DomainBounds=[0, 0.4, 0, 0.1, 0, 0.5])
def bottom_density(wall):
    step = SPHStep(Input=resting, Boundary=floor, PressureSolver="DFSPH", BoundaryWall=wall, OutputInterval=0.001,
                   NumberOfOutputs=1)
    data = pftest.fetch(step, step.TimestepValues[-1])
    z = pftest.points(data)[:, 2]
    return pftest.point_array(data, "density")[z < 0.12].mean()
with_wall, without = bottom_density(1), bottom_density(0)
print("bottom layer density on a mesh floor: %.1f with BoundaryWall, %.1f without" % (with_wall, without))
pftest.check(abs(with_wall - 1000.0) < 10.0, "BoundaryWall on: bottom layer at %.1f kg/m^3" % with_wall)
pftest.check(without < 950.0, "BoundaryWall off: bottom layer at %.1f kg/m^3" % without)

# A surface without polygons cannot be a boundary.
line = SPHStep(Input=block, Boundary=Line(), NumberOfOutputs=1)
catcher = pftest.ErrorCatcher(line)
line.UpdatePipeline(line.TimestepValues[-1])
pftest.check("polygons" in catcher.text(), "Boundary without polygons: %r" % catcher.text())

# Wall friction: a column collapsing along the floor of a slab (y walls stay free-slip).
def front(**walls):
    column = ParticleBlock(Spacing=0.01, BlockBounds=[0, 0.05, 0, 0.02, 0, 0.1], DomainBounds=[0, 0.5, 0, 0.02, 0, 0.2])
    step = SPHStep(Input=column, PressureSolver="DFSPH", Viscosity=20.0, OutputInterval=0.15, NumberOfOutputs=1,
                   OutputPressure=0, **walls)
    return pftest.points(pftest.fetch(step, step.TimestepValues[-1]))[:, 0].max()

default = SPHStep(Input=block).WallFriction
pftest.check(default == "Free-slip", "walls should default to free-slip, not %r" % default)
free = front()
sticky = front(WallFriction="No-slip (viscous)", FrictionWalls=[0, 0, 0, 0, 1, 0])
sticky_elsewhere = front(WallFriction="No-slip (viscous)", FrictionWalls=[0, 1, 0, 0, 0, 1])
turbulent = front(WallFriction="Turbulent (law of the wall)", FrictionWalls=[1, 1, 0, 0, 1, 1])
print("front after 0.15 s: free-slip %.4f, no-slip floor %.4f, no-slip far walls %.4f, law of the wall %.4f m"
      % (free, sticky, sticky_elsewhere, turbulent))
pftest.check(sticky < free - 0.02, "a no-slip floor should hold the surge back: %.4f against %.4f m" % (sticky, free))
pftest.check(abs(sticky_elsewhere - free) < 1e-6, "no-slip on walls the water never reaches changed the front")
pftest.check(free - 0.01 < turbulent < free, "the law of the wall should brake water a little: %.4f against %.4f m"
             % (turbulent, free))
print("sph boundary: ok")
