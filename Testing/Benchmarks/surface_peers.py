"""Particle Surface (Marching Cubes) against ParaView's own path on the same particles, in one
pvpython run: (a) SPH Volume Interpolator (vtkSPHInterpolator, quintic kernel) onto an image of
the same cell size, then Contour (vtkFlyingEdges3D); (b) OpenVDB's ParticlesToLevelSet, one
Gaussian pass and volumeToMesh (openvdb_peer.sh, when libopenvdb-dev is installed). Scenes: the jittered ball (R = 25 d, jitter
0.1 d) for time against error at cells 1, 0.5, 0.25 d, and the dam-break block with 5 % splash.

    pvpython Testing/Benchmarks/surface_peers.py [particles_in_dam_break]   (default 1000000)

Prints a table and writes surface_peers.csv in the current directory. Peer (a)'s threads: set
VTK_SMP_BACKEND_IN_USE=STDThread and VTK_SMP_MAX_THREADS=2 for both cores."""
import csv
import os
import re
import subprocess
import resource
import sys
import time

import numpy as np
from paraview.simple import *
from vtkmodules.numpy_interface import dataset_adapter as dsa
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D
from vtkmodules.vtkCommonDataModel import vtkStaticPointLocator
from vtkmodules.vtkFiltersPoints import vtkSPHInterpolator, vtkSPHQuinticKernel

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
import pftest

pftest.load(globals())


def rss_mb():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS"):
                return int(line.split()[1]) / 1024.0
    return 0.0


def polydata(xyz):
    pd = vtkPolyData()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(xyz, dtype=np.float32), deep=1))
    pd.SetPoints(points)
    return pd


def ball(d, seed=7):
    rng = np.random.default_rng(seed)
    i = np.arange(-26, 27)
    g = np.stack(np.meshgrid(i, i, i, indexing="ij"), -1).reshape(-1, 3) * d
    g = g[np.linalg.norm(g, axis=1) <= 25 * d + 1e-12]
    return g + rng.uniform(-0.1 * d, 0.1 * d, g.shape)


def dam_break(n):
    side = int(round((0.95 * n / 2) ** (1 / 3)))
    d = 0.0064 * 100 / side
    a = side * d
    i = (np.arange(side) + 0.5) * d
    k = (np.arange(2 * side) + 0.5) * d
    block = np.stack(np.meshgrid(i, i, k, indexing="ij"), -1).reshape(-1, 3)
    rng = np.random.default_rng(42)
    splash = rng.random((n - len(block), 3)) * [2 * a, a, 2 * a] + [0, 0, 2 * a]
    return np.vstack([block, splash]), d


def ours(xyz, d, cell):
    producer = TrivialProducer()
    producer.GetClientSideObject().SetOutput(polydata(xyz))
    before = rss_mb()
    surface = ParticleSurfaceMarchingCubes(Input=producer, ParticleSpacing=d, CellSize=cell, Smoothing=10)
    t0 = time.perf_counter()
    surface.UpdatePipeline()
    seconds = time.perf_counter() - t0
    mesh = servermanager.Fetch(surface)
    grown = rss_mb() - before
    Delete(surface)
    Delete(producer)
    return mesh, seconds, grown


def paraview_path(xyz, d, cell):
    """vtkSPHInterpolator (quintic, h = d, cutoff 3 h) onto an image of the given cell, then
    Flying Edges at the level that encloses the particles' volume (shepard-normalised density
    over the rest density, 0.5)."""
    before = rss_mb()
    t0 = time.perf_counter()
    pd = polydata(xyz)
    density = numpy_to_vtk(np.full(len(xyz), 1000.0), deep=1)
    density.SetName("density")
    pd.GetPointData().AddArray(density)
    lo, hi = xyz.min(0) - 3 * d, xyz.max(0) + 3 * d
    spacing = cell * d
    dims = np.ceil((hi - lo) / spacing).astype(int) + 1
    image = vtkImageData()
    image.SetOrigin(*lo)
    image.SetSpacing(spacing, spacing, spacing)
    image.SetDimensions(*dims)
    locator = vtkStaticPointLocator()
    locator.SetDataSet(pd)
    locator.BuildLocator()
    kernel = vtkSPHQuinticKernel()
    kernel.SetSpatialStep(d)
    interpolator = vtkSPHInterpolator()
    interpolator.SetInputData(image)
    interpolator.SetSourceData(pd)
    interpolator.SetKernel(kernel)
    interpolator.SetLocator(locator)
    interpolator.SetDensityArrayName("density")
    interpolator.SetMassArrayName("")
    interpolator.ShepardNormalizationOff()
    interpolator.SetComputeShepardSum(True)
    interpolator.Update()
    volume = interpolator.GetOutput()
    volume.GetPointData().SetActiveScalars(interpolator.GetShepardSumArrayName())
    # The Shepard sum is the kernel-weighted particle volume; its level at half the value deep
    # inside the fluid (its 95th percentile) encloses the particles' volume.
    shepard = dsa.WrapDataObject(volume).PointData[interpolator.GetShepardSumArrayName()]
    level = 0.5 * float(np.percentile(shepard[shepard > 0], 95))
    contour = vtkFlyingEdges3D()
    contour.SetInputData(volume)
    contour.ComputeNormalsOn()
    contour.SetValue(0, level)
    contour.Update()
    seconds = time.perf_counter() - t0
    grown = rss_mb() - before
    return contour.GetOutput(), seconds, grown


def radial_error(mesh, d):
    p = dsa.WrapDataObject(mesh).Points
    return float(np.mean(np.abs(np.linalg.norm(p, axis=1) - 25 * d)) / d)


rows = []
d = 0.01
xyz = ball(d)
for cell in (1.0, 0.5, 0.25):
    mesh, seconds, _ = ours(xyz, d, cell)
    rows.append(("ball", "ParaFluid", cell, len(xyz), seconds, radial_error(mesh, d), ""))
    mesh, seconds, _ = paraview_path(xyz, d, cell)
    rows.append(("ball", "SPHInterpolator+FlyingEdges", cell, len(xyz), seconds, radial_error(mesh, d), ""))

n = int(sys.argv[1]) if len(sys.argv) > 1 else 1000000
xyz, d = dam_break(n)
mesh, seconds, grown = ours(xyz, d, 0.5)
rows.append(("dam break + splash", "ParaFluid", 0.5, len(xyz), seconds, "", "%.0f" % grown))
mesh, seconds, grown = paraview_path(xyz, d, 0.5)
rows.append(("dam break + splash", "SPHInterpolator+FlyingEdges", 0.5, len(xyz), seconds, "", "%.0f" % grown))



def openvdb_rows(n, ball_particles):
    """Peer (b): the OpenVDB program on the same scenes, when libopenvdb-dev is installed."""
    if not os.path.exists("/usr/include/openvdb/openvdb.h"):
        print("OpenVDB peer skipped: install libopenvdb-dev to run it")
        return []
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "openvdb_peer.sh")
    out = subprocess.run(["bash", script, "2", str(n)], check=True, capture_output=True, text=True).stdout
    method = "OpenVDB ParticlesToLevelSet+gaussian+volumeToMesh"
    grown = re.search(r"peak resident size (\d+) MB", out)
    found = []
    for line in out.splitlines():
        f = line.split(",")
        if f[0] == "ball":
            found.append(("ball", method, float(f[1]), ball_particles, float(f[4]), float(f[9]), ""))
        elif f[0].startswith("dam_break_"):
            found.append(("dam break + splash", method, float(f[1]), int(f[0][len("dam_break_"):]), float(f[4]), "",
                          grown.group(1) if grown else ""))
    return found


rows += openvdb_rows(n, len(ball(0.01)))

header = ("scene", "method", "cell_d", "particles", "seconds", "mean_error_d", "rss_growth_mb")
with open("surface_peers.csv", "w", newline="") as f:
    csv.writer(f).writerows([header] + rows)
for row in [header] + rows:
    print("  ".join(str(x) if not isinstance(x, float) else "%.4g" % x for x in row))
