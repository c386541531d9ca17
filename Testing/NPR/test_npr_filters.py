"""Fluid Flow Lines and Foam Particles through real ParaView pipelines: flow lines through a
rigid vortex on a particle block follow circles and carry speed and curvature; lines start at the
Seeds input when given; a missing velocity array is refused clearly. Foam Particles flags the
block's convex edges but not its inside, switches only after PersistFrames time steps of SPH Step,
and starts again when time goes back."""
import numpy as np
from paraview.simple import *
import pftest

pftest.load(globals())
d = 0.01
block = ParticleBlock(Spacing=d, BlockBounds=[-0.2, 0.2, -0.2, 0.2, 0, 0.05], DomainBounds=[-0.3, 0.3, -0.3, 0.3, 0, 0.2])
# A rigid vortex about the z axis, 2 rad/s.
vortex = Calculator(Input=block, ResultArrayName="velocity", Function="-2*coordsY*iHat + 2*coordsX*jHat + 0*kHat")
lines = FluidFlowLines(Input=vortex, SeedStride=7, PointsPerLine=16, LineDuration=np.pi / 4, MaxLines=100000)
out = pftest.fetch(lines)
pts = pftest.points(out)
pftest.check(out.GetNumberOfCells() > 100, "too few lines: %d" % out.GetNumberOfCells())
names = pftest.array_names(out)
pftest.check("speed" in names and "curvature" in names, "point arrays: %s" % names)
# Lines well inside the block (radius under 0.15 m, away from its edges) keep their radius to 1 %.
worst = 0.0
checked = 0
for c in range(out.GetNumberOfCells()):
    ids = out.GetCell(c).GetPointIds()
    line = np.array([pts[ids.GetId(k)] for k in range(ids.GetNumberOfIds())])
    r = np.hypot(line[:, 0], line[:, 1])
    if r[0] < 0.03 or r[0] > 0.15:
        continue
    pftest.check(len(line) == 16, "a line inside the block stopped early (%d points)" % len(line))
    worst = max(worst, np.max(np.abs(r / r[0] - 1)))
    checked += 1
pftest.check(checked > 20, "only %d lines inside the block" % checked)
pftest.check(worst < 0.01, "flow lines leave their circle by %.2f %%" % (100 * worst))
speed = pftest.point_array(out, "speed")
radius = np.hypot(pts[:, 0], pts[:, 1])
inner = radius < 0.15
pftest.check(np.allclose(speed[inner], 2 * radius[inner], rtol=0.01), "speed is not omega r")

# Seeds from another source: one line per seed point.
seeds = PointSource(Center=[0.05, 0, 0.02], NumberOfPoints=5, Radius=0.02)
seeded = FluidFlowLines(Input=vortex, Seeds=seeds, LineDuration=0.1)
pftest.check(pftest.fetch(seeded).GetNumberOfCells() == 5, "expected one line per seed")

# No velocity: a clear error naming the array.
plain = FluidFlowLines(Input=block, VelocityArray="nonexistent")
catcher = pftest.ErrorCatcher(plain)
plain.UpdatePipeline()
pftest.check("nonexistent" in catcher.text(), "missing velocity: %r" % catcher.text())

# Foam: a block at rest in SPH Step. Its 12 convex edges are crests; its inside is not.
column = ParticleBlock(Spacing=d, BlockBounds=[0, 0.1, 0, 0.1, 0, 0.1], DomainBounds=[-0.1, 0.2, -0.1, 0.2, 0, 0.3])
sph = SPHStep(Input=column, AdaptiveTimeStep=0, TimeStep=1e-4, OutputInterval=0.0002, NumberOfOutputs=5, Gravity=[0, 0, 0])
foam = FoamParticles(Input=sph, PersistFrames=3)
times = list(sph.TimestepValues)


def foam_at(t):
    data = pftest.fetch(foam, t)
    return pftest.points(data), pftest.point_array(data, "foam"), pftest.point_array(data, "foam_score")


p0, f0, s0 = foam_at(times[0])
x = p0 / d
lo, hi = 0.5, 9.5  # lattice coordinates of the outer layers
outer = (np.abs(x - lo) < 0.3) | (np.abs(x - hi) < 0.3)
on_edge = np.sum(outer, axis=1) >= 2
inside = np.all((x > lo + 2.5) & (x < hi - 2.5), axis=1)
pftest.check(np.all(s0[on_edge] >= 1), "edge particles should be candidates: %d of %d" % (np.sum(s0[on_edge] >= 1), np.sum(on_edge)))
pftest.check(np.all(s0[inside] < 1), "inside particles flagged")
pftest.check(not np.any(f0), "foam at the first step, before PersistFrames")
_, f1, _ = foam_at(times[1])
pftest.check(not np.any(f1), "foam after two steps")
_, f2, _ = foam_at(times[2])
pftest.check(np.all(f2[on_edge] == 1) and not np.any(f2[inside]), "foam on the edges after three steps")
_, again, _ = foam_at(times[2])
pftest.check(np.array_equal(again, f2), "the same time asked again must give the same foam")
_, back, _ = foam_at(times[0])
pftest.check(not np.any(back), "going back in time must start again")
