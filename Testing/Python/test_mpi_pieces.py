"""Under MPI (pvbatch, 2 ranks) each rank reads its own contiguous slice of the particles, and the
pieces together hold every particle exactly once."""
import numpy as np
from paraview.simple import *
from paraview import servermanager
import pftest

pftest.load(globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
pftest.check(ranks == 2, "run with 2 MPI ranks (got %d)" % ranks)

import os
data_file = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data", "dam_break.h5part")
reader = ParaFluidH5PartReader(FileName=data_file)
tagged = ProcessIdScalars(Input=reader)
data = pftest.fetch(tagged)
ids = pftest.point_array(data, "id")
owner = pftest.point_array(data, "ProcessId")
n = 8000
pftest.check(len(ids) == n, "pieces hold %d particles, the file %d" % (len(ids), n))
pftest.check(np.array_equal(np.sort(ids), np.arange(n)), "some particle is missing or read twice")
for rank in range(ranks):
    mine = np.sort(ids[owner == rank])
    pftest.check(len(mine) == n // ranks, "rank %d read %d particles, expected %d" % (rank, len(mine), n // ranks))
    pftest.check(mine[-1] - mine[0] + 1 == len(mine), "rank %d's particles are not one contiguous slice" % rank)
print("mpi pieces: ok")
