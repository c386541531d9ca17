"""Under MPI (pvbatch, 2 ranks) ParaFluid HDF5 Particles reads on each rank its own contiguous rows
of every block: the pieces together hold every particle exactly once, for an H5MD file of two
particle groups and a Gadget snapshot of two files (a rank's rows spanning both files)."""
import os

import numpy as np
from paraview.simple import *
from paraview import servermanager
import pftest

pftest.load(globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
pftest.check(ranks == 2, "run with 2 MPI ranks (got %d)" % ranks)
out = pftest.scratch_dir()

h5md = os.path.join(out, "pieces.h5md")
pftest.write_h5(h5md, """
f.create_group('h5md').attrs['version'] = np.array([1, 1])
for name, n in (('fluid', 1001), ('wall', 10)):
    g = f.create_group('particles/' + name + '/position')
    g['value'] = np.arange(2 * n * 3, dtype='f8').reshape(2, n, 3); g['time'] = np.array([0.0, 1.0]); g['step'] = np.array([0, 1])
    f['particles/' + name + '/id'] = np.arange(n)
""")
snapshot = [os.path.join(out, "snap_001.%d.hdf5" % k) for k in range(2)]
for k, (this, first) in enumerate(((300, 0), (207, 300))):
    pftest.write_h5(snapshot[k], """
h = f.create_group('Header')
h.attrs['NumPart_ThisFile'] = np.array([%d, 0, 0, 0, 0, 0]); h.attrs['NumPart_Total'] = np.array([507, 0, 0, 0, 0, 0])
h.attrs['NumFilesPerSnapshot'] = 2; h.attrs['Time'] = 0.5
g = f.create_group('PartType0'); g['Coordinates'] = np.zeros((%d, 3)); g['ParticleIDs'] = np.arange(%d, %d)
""" % (this, this, first, first + this))

def named_leaves(data, name=None, found=None):
    """name -> the data sets of that block: Fetch under MPI gives a block per rank, each holding
    the reader's named blocks."""
    found = {} if found is None else found
    if not data.IsA("vtkMultiBlockDataSet"):
        found.setdefault(name, []).append(data)
        return found
    for k in range(data.GetNumberOfBlocks()):
        child = data.GetBlock(k)
        label = data.GetMetaData(k).Get(data.NAME()) if data.HasMetaData(k) else None
        if child is not None:
            named_leaves(child, label or name, found)
    return found


for path, expected in ((h5md, {"fluid": 1001, "wall": 10}), (snapshot[0], {"PartType0 (gas)": 507})):
    reader = ParaFluidHDF5Particles(FileName=path)
    data = pftest.fetch(ProcessIdScalars(Input=reader), 1.0)
    got = {}
    for name, pieces in named_leaves(data).items():
        pieces = [p for p in pieces if p.GetNumberOfPoints()]
        ids = np.concatenate([pftest.point_array(p, "id") for p in pieces])
        owner = np.concatenate([pftest.point_array(p, "ProcessId") for p in pieces])
        n = expected.get(name, -1)
        pftest.check(np.array_equal(np.sort(ids), np.arange(n)), "%s of %s: a particle missing or read twice" % (name, path))
        for rank in range(ranks):
            mine = np.sort(ids[owner == rank])
            pftest.check(abs(len(mine) - n / ranks) <= 1 and (len(mine) == 0 or mine[-1] - mine[0] + 1 == len(mine)),
                         "%s: rank %d read %d particles, not one contiguous half" % (name, rank, len(mine)))
        got[name] = len(ids)
    pftest.check(got == expected, "blocks %s, expected %s" % (got, expected))
print("particle layout pieces: ok")
