"""SPH Step is time-aware: forward steps continue from the cached state, an output already made is
kept and copied, going back to one not made restarts, and all give exactly what a fresh run gives."""
import numpy as np
from paraview.simple import *
import pftest

pftest.load(globals())
block = ParticleBlock(Spacing=0.02, BlockBounds=[0, 0.2, 0, 0.1, 0, 0.3], DomainBounds=[0, 0.6, 0, 0.1, 0, 0.4])
sph = SPHStep(Input=block, AdaptiveTimeStep=0, TimeStep=2e-4, OutputInterval=0.002, NumberOfOutputs=6)


def steps_taken(proxy):
    proxy.UpdatePropertyInformation()
    return proxy.GetPropertyValue("StepsTakenLastUpdate")


times = list(sph.TimestepValues)

at2 = pftest.points(pftest.fetch(sph, times[2]))
pftest.check(steps_taken(sph) == 20, "t2 from t0 took %d steps" % steps_taken(sph))
at5 = pftest.points(pftest.fetch(sph, times[5]))
pftest.check(steps_taken(sph) == 30, "t5 after t2 should continue (30 steps), took %d" % steps_taken(sph))
again2 = pftest.points(pftest.fetch(sph, times[2]))
pftest.check(steps_taken(sph) == 0, "an output already made is copied, not stepped again (took %d steps)" %
             steps_taken(sph))
pftest.check(np.array_equal(at2, again2), "the kept output differs from the first")
# Back to a time not made yet: the run restarts from t0 and gives what a fresh run gives.
at1 = pftest.points(pftest.fetch(sph, times[1]))
pftest.check(steps_taken(sph) == 10, "going back to a time not made must restart from t0 (took %d steps)" %
             steps_taken(sph))
fresh1 = SPHStep(Input=block, AdaptiveTimeStep=0, TimeStep=2e-4, OutputInterval=0.002, NumberOfOutputs=6)
pftest.check(np.array_equal(pftest.points(pftest.fetch(fresh1, times[1])), at1), "restarted run differs from a fresh one")
Delete(fresh1)

fresh = SPHStep(Input=block, AdaptiveTimeStep=0, TimeStep=2e-4, OutputInterval=0.002, NumberOfOutputs=6)
pftest.check(np.array_equal(pftest.points(pftest.fetch(fresh, times[5])), at5), "cached stepping differs from a fresh run")

# A property change invalidates the cache.
sph.Viscosity = 1.0
pftest.fetch(sph, times[5])
pftest.check(steps_taken(sph) == 50, "a new Viscosity must restart the run")

# Particle shifting (δ-SPH, off by default) is a property like the others: switching it on
# restarts the run, moves the particles differently and keeps them finite and inside the box.
pftest.check(sph.ParticleShifting == 0, "ParticleShifting must be off by default")
unshifted = pftest.points(pftest.fetch(sph, times[5]))
sph.ParticleShifting = 1
shifted = pftest.points(pftest.fetch(sph, times[5]))
pftest.check(steps_taken(sph) == 50, "a new ParticleShifting must restart the run (took %d steps)" % steps_taken(sph))
moved = np.abs(shifted - unshifted).max()
print("largest move by shifting: %g m" % moved)
pftest.check(moved > 1e-7, "ParticleShifting changed no particle (largest difference %g m)" % moved)
pftest.check(np.all(np.isfinite(shifted)), "non-finite positions with ParticleShifting")
pftest.check(shifted[:, 0].min() >= 0 and shifted[:, 0].max() <= 0.6 and shifted[:, 2].min() >= 0,
             "a shifted particle left the box")
sph.ParticleShifting = 0

# The pressure push's high pass (δ-SPH, on by default) likewise: off, the run restarts and the
# particles under pressure move differently.
pftest.check(sph.PushHighPass == 1, "PushHighPass must be on by default")
sph.PushHighPass = 0
plain = pftest.points(pftest.fetch(sph, times[5]))
pftest.check(steps_taken(sph) == 50, "a new PushHighPass must restart the run (took %d steps)" % steps_taken(sph))
pftest.check(np.abs(plain - unshifted).max() > 0, "PushHighPass changed no particle")
pftest.check(np.all(np.isfinite(plain)), "non-finite positions without PushHighPass")
sph.PushHighPass = 1

# Output keeps the input's order: the particle with id k is point k.
data = pftest.fetch(sph, times[5])
pftest.check(np.array_equal(pftest.point_array(data, "id"), np.arange(data.GetNumberOfPoints())), "order not kept")
pftest.check(data.GetFieldData().GetArray("time").GetValue(0) == times[5], "output time field data")
pftest.check(np.all(np.isfinite(pftest.points(data))), "non-finite positions")

# Adaptive stepping (the default) still lands exactly on every output time.
adaptive = SPHStep(Input=block, OutputInterval=0.004, NumberOfOutputs=3)
for k, t in enumerate(adaptive.TimestepValues):
    d = pftest.fetch(adaptive, t)
    pftest.check(d.GetFieldData().GetArray("time").GetValue(0) == t, "adaptive output %d is not at t = %g" % (k, t))
pftest.check(steps_taken(adaptive) > 0, "adaptive run took no steps")
# A time past the end (infinity too) is the last output, one before the start the first; NaN is
# refused with a message.
last = adaptive.TimestepValues[-1]
for asked, expected in ((float("inf"), last), (1e30, last), (float("-inf"), 0.0), (-5.0, 0.0)):
    d = pftest.fetch(adaptive, asked)
    got = d.GetFieldData().GetArray("time").GetValue(0)
    pftest.check(got == expected, "asked for t = %r, got the output at %g instead of %g" % (asked, got, expected))
messages = pftest.Messages(adaptive.GetClientSideObject())
adaptive.UpdatePipeline(float("nan"))
pftest.check(any("not a number" in e for e in messages.errors), "NaN time: errors %r" % (messages.errors,))
print("sph time: ok")
