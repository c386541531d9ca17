"""Terrain to SPH: a procedural terrain, eroded by droplets, its surface (output 1) as SPH Step's
Boundary; water released over its highest ground runs downhill: its centre of mass descends, it
moves to lower ground, and no particle ever gets under the terrain. The height image (output 0) is
taken as a Boundary too."""
import numpy as np
from paraview.simple import *
import pftest

pftest.load(globals())
check = pftest.check

hills = ProceduralTerrain(Extent=[0.8, 0.4], Resolution=[41, 21], FeatureSize=0.6, HeightScale=0.08,
                          BaseHeight=0.1, Seed=5)
terrain = HydraulicErosion(Input=hills, Drops=300)
image = pftest.fetch(terrain)
nx, ny = 41, 21
h = pftest.point_array(image, "elevation").reshape(ny, nx)
dx = 0.8 / 40


def ground(p):
    """Bilinear terrain height under each particle."""
    fx = np.clip(p[:, 0] / dx, 0, nx - 1.001)
    fy = np.clip(p[:, 1] / dx, 0, ny - 1.001)
    i, j = fx.astype(int), fy.astype(int)
    a, b = fx - i, fy - j
    return (h[j, i] * (1 - a) * (1 - b) + h[j, i + 1] * a * (1 - b) + h[j + 1, i] * (1 - a) * b
            + h[j + 1, i + 1] * a * b)


# Water over the highest ground (away from the walls), its bottom above the terrain beneath it.
jm, im = np.unravel_index(np.argmax(h[4:-4, 4:-4]), h[4:-4, 4:-4].shape)
cx, cy = (im + 4) * dx, (jm + 4) * dx
footprint = h[max(jm + 4 - 4, 0):jm + 4 + 5, max(im + 4 - 4, 0):im + 4 + 5]
bottom = float(footprint.max()) + 0.01
spacing = 0.01
block = ParticleBlock(Spacing=spacing, BlockBounds=[cx - 0.04, cx + 0.04, cy - 0.04, cy + 0.04, bottom, bottom + 0.04],
                      DomainBounds=[0, 0.8, 0, 0.4, float(h.min()) - 0.05, float(h.max()) + 0.2])
sph = SPHStep(Input=block, Boundary=OutputPort(terrain, 1), OutputInterval=0.1, NumberOfOutputs=4)
com, under_ground = [], []
worst = 0.0
for t in sph.TimestepValues:
    p = pftest.points(pftest.fetch(sph, t))
    check(np.all(np.isfinite(p)), "finite positions at t = %g" % t)
    com.append(p[:, 2].mean())
    under_ground.append(ground(p).mean())
    worst = max(worst, float((ground(p) - p[:, 2]).max()))
print("centre of mass z:", ["%.4f" % c for c in com])
print("mean ground under the water:", ["%.4f" % g for g in under_ground])
check(com[-1] < com[0] - 0.02, "the water's centre of mass descends (%.4f -> %.4f)" % (com[0], com[-1]))
check(under_ground[-1] < under_ground[0] - 0.01, "the water moved to lower ground (%.4f -> %.4f)" % (under_ground[0], under_ground[-1]))
check(worst < 0.5 * spacing, "no particle under the terrain (deepest %.4f m below)" % worst)

# The height image itself is a Boundary too (the same surface).
sph_image = SPHStep(Input=block, Boundary=terrain, OutputInterval=0.1, NumberOfOutputs=1)
p = pftest.points(pftest.fetch(sph_image, sph_image.TimestepValues[-1]))
check(np.all(np.isfinite(p)) and float((ground(p) - p[:, 2]).max()) < 0.5 * spacing, "image boundary holds the water")
print("terrain to SPH: OK")
