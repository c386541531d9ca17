"""Under MPI (pvbatch, 2 ranks) ParaFluid HDF5 Particles reads on each rank its own contiguous rows
of every block: the pieces together hold every particle exactly once, for an H5MD file of two
particle groups, a Gadget snapshot of two files (a rank's rows spanning both files), PySPH's output
with ghost particles, and a SWIFT snapshot read through its cell index with a SelectionBox (the
ranks split the selected cells' rows)."""
import os
import sys

import numpy as np
from paraview.simple import *
from paraview import servermanager
import pftest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # pvbatch leaves the script's folder out
import cell_snapshot  # noqa: E402

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

pysph = os.path.join(out, "drop_00000.hdf5")
pftest.write_h5(pysph, """
s = f.create_group('solver_data'); s.attrs['t'] = 1.0; s.attrs['count'] = 3
a = f.create_group('particles/fluid/arrays')
tag = np.zeros(1203, dtype='i4'); tag[1001:] = 2
a['x'] = np.arange(1203.0); a['y'] = np.zeros(1203); a['z'] = np.zeros(1203); a['tag'] = tag
""")
cells = os.path.join(out, "cells.hdf5")
pftest.write_h5(cells, cell_snapshot.script(30000, 8))
box = [0.2, 0.7, 0.1, 0.45, 0.3, 0.9]


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


cases = ((h5md, {"fluid": 1001, "wall": 10}, None), (snapshot[0], {"PartType0 (gas)": 507}, None),
         (pysph, {"fluid": 1001}, None), (cells, {"PartType0 (gas)": None}, box))
for path, expected, selection in cases:
    reader = ParaFluidHDF5Particles(FileName=path)
    if selection:
        reader.UseSelectionBox = 1
        reader.SelectionBox = selection
    data = pftest.fetch(ProcessIdScalars(Input=reader), 1.0)
    got = {}
    for name, pieces in named_leaves(data).items():
        pieces = [p for p in pieces if p.GetNumberOfPoints()]
        ids = np.concatenate([pftest.point_array(p, "id") for p in pieces])
        owner = np.concatenate([pftest.point_array(p, "ProcessId") for p in pieces])
        if selection:
            # Every particle inside the box exactly once, whichever rank read it.
            x = np.concatenate([pftest.points(p) for p in pieces])
            pftest.check(np.all((x >= selection[0::2]) & (x <= selection[1::2])), "%s: a particle outside the box" % path)
            pftest.check(len(np.unique(ids)) == len(ids), "%s: a particle read twice" % path)
            pftest.check(all(np.sum(owner == rank) > 0 for rank in range(ranks)), "%s: a rank read nothing" % path)
            expected[name] = len(ids)
            whole = ParaFluidHDF5Particles(FileName=path)
            everything = named_leaves(pftest.fetch(whole))[name]
            allx = np.concatenate([pftest.points(p) for p in everything if p.GetNumberOfPoints()])
            n_in = int(np.sum(np.all((allx >= selection[0::2]) & (allx <= selection[1::2]), axis=1)))
            pftest.check(len(ids) == n_in, "%s: the box gave %d particles, %d are inside" % (path, len(ids), n_in))
            got[name] = len(ids)
            continue
        n = expected.get(name, -1)
        pftest.check(np.array_equal(np.sort(ids), np.arange(n)), "%s of %s: a particle missing or read twice" % (name, path))
        for rank in range(ranks):
            mine = np.sort(ids[owner == rank])
            # The ranks split the rows; PySPH's ghosts (all in rank 1's rows here) are then left out.
            share = n / ranks if path != pysph else (602 if rank == 0 else 399)
            pftest.check(abs(len(mine) - share) <= 1 and (len(mine) == 0 or mine[-1] - mine[0] + 1 == len(mine)),
                         "%s: rank %d read %d particles, not one contiguous half" % (name, rank, len(mine)))
        got[name] = len(ids)
    pftest.check(got == expected, "blocks %s, expected %s" % (got, expected))
print("particle layout pieces: ok")
