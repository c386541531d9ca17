"""The reader understands the H5Part variants SPH codes write."""
import os
import numpy as np
from paraview.simple import *
import pftest

pftest.load(globals())
out = pftest.scratch_dir()

# Components x/y/z and vx/vy/vz, a second vector written as velocity-style _x/_y/_z, an N x 3
# dataset, integer ids, a time attribute and scene constants at the root.
a = os.path.join(out, "components.h5part")
pftest.write_h5(a, """
f.attrs['particle_spacing'] = 0.5
f.attrs['rest_density'] = 998.0
f.attrs['code'] = np.string_('testcode')
for s, t in enumerate([0.0, 0.25, 0.75]):
    g = f.create_group('Step#%d' % s)
    g.attrs['TimeValue'] = t
    n = 6
    g['x'] = np.arange(n, dtype='f8') + s
    g['y'] = np.zeros(n, 'f8'); g['z'] = np.ones(n, 'f8')
    g['vx'] = np.full(n, 1.0, 'f4'); g['vy'] = np.full(n, 2.0, 'f4'); g['vz'] = np.full(n, 3.0, 'f4')
    g['force_x'] = np.arange(n, dtype='f4'); g['force_y'] = -np.arange(n, dtype='f4'); g['force_z'] = np.zeros(n, 'f4')
    g['stress'] = np.arange(3 * n, dtype='f4').reshape(n, 3)
    g['density'] = np.full(n, 1000.0, 'f4')
    g['id'] = np.arange(100, 100 + n, dtype='i4')
""")
r = ParaFluidHDF5Particles(FileName=a)
pftest.check(np.allclose(r.TimestepValues, [0.0, 0.25, 0.75]), "time attribute not used: %s" % r.TimestepValues)
d = pftest.fetch(r, 0.25)
pftest.check(pftest.array_names(d) == ["density", "force", "id", "stress", "velocity"], "arrays %s" % pftest.array_names(d))
pftest.check(np.allclose(pftest.points(d)[:, 0], np.arange(6) + 1), "step 1 x")
pftest.check(d.GetPoints().GetDataType() == 11, "double coordinates must stay double")
pftest.check(np.allclose(pftest.point_array(d, "velocity"), [[1, 2, 3]] * 6), "vx/vy/vz not combined")
pftest.check(np.allclose(pftest.point_array(d, "force")[:, 1], -np.arange(6)), "force_x/_y/_z not combined")
pftest.check(pftest.point_array(d, "stress").shape == (6, 3), "N x 3 dataset must stay a vector")
pftest.check(list(pftest.point_array(d, "id")) == list(range(100, 106)), "ids from the file")
pftest.check(d.GetPointData().GetArray("id").GetDataTypeSize() == 8, "id must be int64")
fd = d.GetFieldData()
pftest.check(fd.GetArray("particle_spacing").GetValue(0) == 0.5, "scene constant particle_spacing")
pftest.check(fd.GetAbstractArray("code").GetValue(0) == "testcode", "string attribute")
pftest.check(fd.GetArray("time").GetValue(0) == 0.25, "time field data")

# One N x 3 position dataset, no ids (index ids), step index as time, an OpenDataFile pick.
b = os.path.join(out, "position.h5part")
pftest.write_h5(b, """
for s in range(2):
    g = f.create_group('Step#%d' % s)
    g['position'] = np.random.rand(50, 3).astype('f4')
    g['velocity'] = np.random.rand(50, 3).astype('f4')
""")
r = OpenDataFile(b)
pftest.check(r.GetXMLName() == "H5ParaFluidParticlesReader", "OpenDataFile picked %s" % r.GetXMLName())
pftest.check(list(r.TimestepValues) == [0.0, 1.0], "step index as time")
d = pftest.fetch(r, 1.0)
pftest.check(d.GetNumberOfPoints() == 50 and list(pftest.point_array(d, "id")) == list(range(50)), "index ids")
print("reader layouts: ok")
