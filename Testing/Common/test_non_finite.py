"""Every particle filter says what it does with NaN or infinite input: SPH Step refuses it naming
the particle, and so does Foam Particles; the surfaces and flow lines leave such particles out with a warning, and their
output holds only finite values. (A NaN velocity used to crash Fluid Flow Lines.)"""
import builtins

import numpy as np
from paraview.simple import *
import pftest

pftest.load(globals())

SCENE = """
h = 0.05
g = np.arange(0.0, 0.4, h)
P = np.stack(np.meshgrid(g, g, g, indexing='ij'), -1).reshape(-1, 3)
v = np.zeros_like(P); v[:, 0] = 1.0
v[5, 1] = np.nan
v[9, 2] = np.inf
P[17, 0] = np.nan
arrays['velocity'] = v
"""
particles = ProgrammableSource(Script=pftest.particle_script(SCENE))


def finite_output(data, label):
    pftest.check(data is not None and data.GetNumberOfPoints() > 0, "%s gave no output" % label)
    pftest.check(np.all(np.isfinite(pftest.points(data))), "%s output has non-finite points" % label)
    pd = data.GetPointData()
    for i in range(pd.GetNumberOfArrays()):
        values = pftest.point_array(data, pd.GetArrayName(i))
        # An input array carried onto the output keeps what the input said (NaN stays NaN, as
        # VTK colours it); what the filter computes must be finite.
        if values.dtype.kind == "f" and pd.GetArrayName(i) != "velocity":
            pftest.check(np.all(np.isfinite(values)), "%s output array %s is not finite" % (label, pd.GetArrayName(i)))


for label, make, what in (
        ("Fluid Flow Lines", lambda: FluidFlowLines(Input=particles), "velocity"),
        ("Particle Surface", lambda: ParticleSurfaceMarchingCubes(Input=particles), "position"),
        ("Carpet Surface", lambda: CarpetSurface(Input=particles), "position")):
    proxy = make()
    messages = pftest.Messages(proxy.GetClientSideObject())
    data = pftest.fetch(proxy)
    text = " ".join(messages.warnings)
    pftest.check(not messages.errors, "%s refused: %r" % (label, messages.errors))
    pftest.check("left out" in text and "NaN or infinite" in text, "%s: no warning about the dropped particles: %r" % (label, text))
    finite_output(data, label)

sph = SPHStep(Input=particles, DomainBounds=[-1, 1, -1, 1, -1, 1])
messages = pftest.Messages(sph.GetClientSideObject())
sph.UpdatePipeline()
pftest.check(builtins.any("SPH Step" in e and "NaN or infinite" in e for e in messages.errors), "SPH Step: %r" % messages.errors)

# Foam Particles works per piece (no gather) and refuses: a foam class computed beside a NaN
# neighbour would be a guess.
foam = FoamParticles(Input=particles)
messages = pftest.Messages(foam.GetClientSideObject())
foam.UpdatePipeline()
pftest.check(builtins.any("Foam Particles" in e and "NaN or infinite" in e for e in messages.errors), "Foam Particles: %r" % messages.errors)
print("non-finite input: ok")
