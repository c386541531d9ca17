"""The Stable Fluids source in pvpython: its image and arrays, a plume that rises over time, time
awareness (forward continues, back gives the output already made), divergence on request, points of
an input dataset as sources, procedural clouds covering the asked fraction, and errors that name
the property."""
import numpy as np
from paraview.simple import *
from paraview import servermanager
import pftest

pftest.load(globals())


def fetch(proxy, time):
    proxy.UpdatePipeline(time)
    return servermanager.Fetch(proxy)


def centre_of_density(image):
    rho = pftest.point_array(image, "density")
    dims = image.GetDimensions()
    z = image.GetOrigin()[2] + image.GetSpacing()[2] * (np.arange(len(rho)) // (dims[0] * dims[1]))
    return float((rho * z).sum() / rho.sum())


smoke = StableFluids(Bounds=[0, 1, 0, 1, 0, 2], Resolution=[16, 16, 32], TimeStep=0.05, OutputInterval=0.25,
                     NumberOfOutputs=8, EmitterBox=[0.35, 0.65, 0.35, 0.65, 0.0, 0.2])
times = smoke.TimestepValues
pftest.check(len(times) == 9 and abs(times[-1] - 2.0) < 1e-9, "time steps %s" % (times,))

start = fetch(smoke, 0.25)
pftest.check(start.GetDimensions() == (16, 16, 32), "dimensions %s" % (start.GetDimensions(),))
pftest.check(np.allclose(start.GetSpacing(), 1 / 16) and np.allclose(start.GetOrigin(), [1 / 32] * 3),
             "cell centres: spacing %s origin %s" % (start.GetSpacing(), start.GetOrigin()))
for name in ("density", "temperature", "velocity"):
    pftest.point_array(start, name)
pftest.check("divergence" not in pftest.array_names(start), "divergence only on request")
low = centre_of_density(start)

later = fetch(smoke, 2.0)
high = centre_of_density(later)
w = pftest.point_array(later, "velocity")[:, 2]
print("plume: centre of density %.3f m -> %.3f m, updraught %.2f m/s" % (low, high, w.max()))
pftest.check(high > low + 0.3, "the plume rises: centre of density %.3f m -> %.3f m" % (low, high))
pftest.check(w.max() > 0.3, "updraught %.2f m/s" % w.max())

# A time past the end (infinity too) is the last output, not the first; NaN is refused by name.
at_inf = fetch(smoke, float("inf"))
pftest.check(np.array_equal(pftest.point_array(at_inf, "density"), pftest.point_array(later, "density")),
             "t = inf gives the last output")
messages = pftest.Messages(smoke.GetClientSideObject())
smoke.UpdatePipeline(float("nan"))
pftest.check(any("Stable Fluids" in e and "not a number" in e for e in messages.errors), "NaN: %r" % (messages.errors,))

# Back in time: the output already made, the same state.
again = fetch(smoke, 0.25)
pftest.check(np.array_equal(pftest.point_array(again, "density"), pftest.point_array(start, "density")),
             "going back gives the same state")

# Divergence on request: the projection leaves it at the solver's tolerance.
smoke.OutputDivergence = 1
div = pftest.point_array(fetch(smoke, 1.0), "divergence")
speed = np.abs(pftest.point_array(fetch(smoke, 1.0), "velocity")).max()
pftest.check(np.sqrt((div ** 2).mean()) < 1e-3 * speed * 16, "divergence RMS %.2e 1/s" % np.sqrt((div ** 2).mean()))

# Points of a dataset as the only sources: density appears where they are, nowhere else at first.
points = PointSource(Center=[0.25, 0.5, 0.3], Radius=0.0, NumberOfPoints=1)
from_points = StableFluids(Sources=points, Emitter=0, Bounds=[0, 1, 0, 1, 0, 1], Resolution=[16, 16, 16],
                           OutputInterval=0.02, TimeStep=0.02, NumberOfOutputs=2)
image = fetch(from_points, 0.02)
rho = pftest.point_array(image, "density").reshape(16, 16, 16)
k, j, i = np.unravel_index(np.argmax(rho), rho.shape)
pftest.check((i, j) == (4, 8) and rho.max() > 0.5, "density at the point's cell: %s, %.2f" % ((i, j, k), rho.max()))

# A volume as the sources: only the points whose scalar is above 0 inject (a wavelet image
# thresholded into a mask: density appears inside the mask's cells and nowhere else).
mask = Wavelet(WholeExtent=[0, 15, 0, 15, 0, 15])
masked = Calculator(Input=mask, ResultArrayName="inside", Function="RTData > 250")
masked_image = fetch(masked, 0.0)
inside = pftest.point_array(masked_image, "inside")
# (The grid's cell centres on the wavelet's points; no speed, no buoyancy: after one step the
# density is where it was injected.)
from_volume = StableFluids(Sources=masked, Emitter=0, Bounds=[-0.5, 15.5, -0.5, 15.5, -0.5, 15.5],
                           Resolution=[16, 16, 16], OutputInterval=0.02, TimeStep=0.02, NumberOfOutputs=1,
                           EmitterSpeed=0.0, BuoyancyHeat=0.0, BuoyancyDensity=0.0, Vorticity=0.0)
rho = pftest.point_array(fetch(from_volume, 0.02), "density")
pftest.check(0 < inside.sum() < len(inside), "the mask covers part of the volume (%d points)" % inside.sum())
pftest.check(np.array_equal(rho > 0.5, inside > 0.5),
             "density exactly in the masked cells: %d cells with density, %d masked" % ((rho > 0.5).sum(), inside.sum()))

# Procedural clouds: the covered fraction of the sky is near the asked one.
for coverage in (0.2, 0.6):
    sky = StableFluids(Emitter=0, ProceduralClouds=1, CloudCoverage=coverage, CloudFeatureSize=2.0,
                       Bounds=[0, 8, 0, 8, 0, 2], Resolution=[64, 64, 16], NumberOfOutputs=0)
    rho = pftest.point_array(fetch(sky, 0.0), "density").reshape(16, 64, 64)
    covered = float((rho.max(axis=0) > 0.01).mean())
    print("coverage %.2f asked, %.2f covered" % (coverage, covered))
    pftest.check(abs(covered - coverage) < 0.05, "coverage %.2f asked, %.2f covered" % (coverage, covered))
    Delete(sky)

# Bad input: errors that name the property, no output, no crash.
errors = pftest.OutputWindowMessages()
bad = StableFluids(Resolution=[1, 16, 16])
bad.UpdatePipeline(0.0)
text = errors.take()
pftest.check("Resolution" in text, "a resolution of 1 is refused by name: %r" % text)
bad.Resolution = [16, 16, 16]
bad.Bounds = [0, 1, 0, 1, 1, 1]
bad.UpdatePipeline(0.0)
text = errors.take()
pftest.check("Bounds" in text, "empty bounds refused by name: %r" % text)
bad.Bounds = [0, 1, 0, 1, 0, 1]
bad.ProceduralClouds = 1
bad.CloudCoverage = 1.5
bad.UpdatePipeline(0.0)
text = errors.take()
pftest.check("CloudCoverage" in text, "coverage above 1 refused by name: %r" % text)
errors.stop()
print("stable fluids: OK")
