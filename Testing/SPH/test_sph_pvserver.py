"""A 2-process pvserver with pvpython connected: read an H5Part file -> SPH Step (distributed over
the server's processes) -> Particle Surface -> save gives what the builtin session gives (the same
ids, every particle within 1e-5 m after 20 fixed steps, the surface's area within 0.5 %), and
going forward and back in time on the server gives the same outputs again."""
import os
import tempfile

import numpy as np
from paraview.simple import *
from paraview import servermanager
import pftest

folder = tempfile.mkdtemp(prefix="parafluid-pvserver-")
scene = os.path.join(folder, "column.h5part")
pftest.write_h5(scene, """
h = 0.02
g = lambda a, b: np.arange(a + h / 2, b, h)
P = np.stack(np.meshgrid(g(0, 0.2), g(0, 0.1), g(0, 0.3), indexing='ij'), -1).reshape(-1, 3)
s = f.create_group('Step#0')
s.attrs['TimeValue'] = 0.0
for name, column in zip('xyz', P.T):
    s[name] = column.astype(np.float32)
s['id'] = np.arange(len(P), dtype=np.int64)
f.attrs['particle_spacing'] = h
f.attrs['domain_bounds'] = np.array([0, 0.6, 0, 0.1, 0, 0.4])
""")


def pipeline(path, saved):
    """Reader -> SPH Step (20 fixed steps to the first output) -> Particle Surface, written to
    `saved`; returns the particles' ids and positions by id, and the surface's area."""
    reader = ParaFluidHDF5Particles(FileName=path)
    sph = SPHStep(Input=reader, AdaptiveTimeStep=0, TimeStep=2e-4, OutputInterval=0.004, NumberOfOutputs=3)
    data = pftest.fetch(sph, 0.004)
    ids = pftest.point_array(data, "id").astype(np.int64)
    order = np.argsort(ids)
    surface = ParticleSurfaceMarchingCubes(Input=sph)
    surface.UpdatePipeline(0.004)
    SaveData(saved, proxy=sph)
    area = pftest.triangle_area(pftest.fetch(surface, 0.004))
    later = pftest.points(pftest.fetch(sph, 0.008))
    again = pftest.points(pftest.fetch(sph, 0.004))
    return ids[order], pftest.points(data)[order], area, again[np.argsort(pftest.point_array(pftest.fetch(sph, 0.004), "id"))], later


pftest.load(globals())
builtin = pipeline(scene, os.path.join(folder, "builtin.h5part"))

with pftest.pvserver(2) as port:
    Disconnect()
    Connect("localhost", port)
    pftest.check(servermanager.ActiveConnection.GetNumberOfDataPartitions() == 2, "the server has %d processes" %
                 servermanager.ActiveConnection.GetNumberOfDataPartitions())
    LoadPlugin(pftest.plugin_path(), remote=True, ns=globals())
    remote = pipeline(scene, os.path.join(folder, "server.h5part"))
    pftest.check(np.array_equal(remote[0], builtin[0]), "the server's SPH output has %d ids, the builtin %d (or another set)" %
                 (len(remote[0]), len(builtin[0])))
    departure = np.linalg.norm(remote[1] - builtin[1], axis=1).max()
    pftest.check(departure < 1e-5, "a particle is %.3g m from the builtin session's after 20 steps" % departure)
    pftest.check(abs(remote[2] - builtin[2]) <= 0.005 * builtin[2], "surface area %.5f m^2 on the server, %.5f builtin" %
                 (remote[2], builtin[2]))
    pftest.check(np.array_equal(remote[3], remote[1]), "the server's output at 0.004 s changed when asked again")
    pftest.check(len(remote[4]) == len(builtin[4]), "the server lost particles going forward")
    Disconnect()
pftest.check(os.path.getsize(os.path.join(folder, "server.h5part")) > 0, "the server wrote no file")
print("pvserver session: ok (%d particles, surface %.4f m^2, largest departure %.2g m)" %
      (len(builtin[0]), builtin[2], departure))
