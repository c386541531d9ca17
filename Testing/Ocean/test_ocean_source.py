"""Gerstner Ocean source in pvpython: crest speed, presets without folds, a terrain surface and an
image as bathymetry, bad bathymetry reported by name."""
import math

import numpy as np
from paraview.simple import *
import pftest

pftest.load(globals())

# One deep-water wave along x on a thin strip: the crest moves at sqrt(g / k).
strip = GerstnerOcean(SeaState="Custom (wave list)", Waves=[0.4, 20.0, 0.0, 0.6, 0.0],
                      Origin=[0.0, 0.0], Size=[30.0, 1.0], Resolution=[6001, 2])
pftest.check(len(strip.TimestepValues) == 601, "20 s at 30 frames/s: %d time steps" % len(strip.TimestepValues))


def first_crest(time):
    data = pftest.fetch(strip, time)
    xyz = pftest.points(data)[:6001]
    i = int(np.argmax(xyz[:, 2]))
    # Parabola through the three highest samples (heights against displaced x).
    a, b, c = xyz[i - 1, 2], xyz[i, 2], xyz[i + 1, 2]
    f = 0.5 * (a - c) / (a - 2 * b + c)
    return xyz[i, 0] + f * (xyz[i + 1, 0] - xyz[i - 1, 0]) / 2, data


x0, data = first_crest(0.0)
x1, _ = first_crest(1.0)
speed = (x1 - x0) % 20.0
expected = math.sqrt(9.81 * 20.0 / (2 * math.pi))
pftest.check(abs(speed - expected) < 0.005 * expected, "crest speed %.4f m/s, expected %.4f" % (speed, expected))
normals = data.GetPointData().GetNormals()
pftest.check(normals is not None, "the surface has point normals")
pftest.check(np.allclose(np.linalg.norm(pftest.point_array(data, "Normals"), axis=1), 1.0, atol=1e-5), "unit normals")
pftest.check("depth" not in pftest.array_names(data), "deep water has no depth array")
pftest.check(data.GetNumberOfCells() == 6000, "quads: %d" % data.GetNumberOfCells())

for state in ["Calm", "Swell", "Storm"]:
    sea = GerstnerOcean(SeaState=state, WindDirection=30.0, Resolution=[200, 200])
    d = pftest.fetch(sea, 3.3)
    j = pftest.point_array(d, "jacobian")
    pftest.check(j.min() > 0.0, "%s folds: minimum jacobian %g" % (state, j.min()))
    z = pftest.points(d)[:, 2]
    pftest.check(0.05 < z.max() - z.min() < 20.0, "%s wave heights %g m" % (state, z.max() - z.min()))
    Delete(sea)

# A beach as a terrain surface: a plane tilting up from 12 m below sea level to dry land.
beach = Plane(Origin=[0.0, -50.0, -12.0], Point1=[300.0, -50.0, 0.5], Point2=[0.0, 50.0, -12.0],
              XResolution=60, YResolution=10)
shore = GerstnerOcean(Bathymetry=beach, SeaState="Custom (wave list)", Waves=[0.5, 40.0, 0.0, 0.5, 0.0],
                      Origin=[0.0, -20.0], Size=[300.0, 40.0], Resolution=[1201, 9])
breaking_depths = []
for t in np.arange(0.0, 7.0, 0.25):
    d = pftest.fetch(shore, t)
    depth = pftest.point_array(d, "depth")
    foam = pftest.point_array(d, "foam")
    breaking_depths += list(depth[foam > 0.0])
pftest.check(len(breaking_depths) > 0, "a 1 m wave breaks on the beach")
pftest.check(max(breaking_depths) < 2.0, "breaking only in shallow water (deepest %g m)" % max(breaking_depths))
depth = pftest.point_array(d, "depth")
pftest.check(abs(depth.max() - 12.0) < 0.1 and depth.min() == 0.0, "depth from 12 m to dry land: %g..%g" % (depth.min(), depth.max()))

# A 2D height-field image: elevation = RTData, sea level above all of it.
image = Wavelet(WholeExtent=[0, 40, 0, 40, 0, 0])
over_image = GerstnerOcean(Bathymetry=image, SeaLevel=300.0, Origin=[0.0, 0.0], Size=[40.0, 40.0], Resolution=[41, 41])
d = pftest.fetch(over_image, 0.0)
image_data = pftest.fetch(image)
rt = pftest.point_array(image_data, "RTData")
depth = pftest.point_array(d, "depth")
pftest.check(abs(depth.min() - (300.0 - rt.max())) < 1e-3 and abs(depth.max() - (300.0 - rt.min())) < 1e-3,
             "depth from the image: %g..%g" % (depth.min(), depth.max()))

# Bad bathymetry: a 3D image, a line.
for bad, words in [(Wavelet(), "2D"), (Line(), "polygons")]:
    ocean = GerstnerOcean(Bathymetry=bad)
    catcher = pftest.ErrorCatcher(ocean)
    ocean.UpdatePipeline(0.0)
    pftest.check(words in catcher.text(), "bad bathymetry message: %r" % catcher.text())
print("ocean source: ok")
