"""Under MPI (pvbatch, 2 ranks) each rank reads its own contiguous slice of the particles, and the
pieces together hold every particle exactly once; the writer gathers the pieces into one file and
SPH Step simulates all particles together."""
import numpy as np
from paraview.simple import *
from paraview import servermanager
import pftest

pftest.load(globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
pftest.check(ranks == 2, "run with 2 MPI ranks (got %d)" % ranks)

import os
data_file = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data", "dam_break.h5part")
reader = ParaFluidHDF5Particles(FileName=data_file)
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

# Writing from 2 ranks: one file holding every particle once, equal to what was read.
import tempfile
out = os.path.join(tempfile.mkdtemp(prefix="parafluid-mpi-"), "copy.h5part")
SaveData(out, proxy=reader)
pftest.check(os.path.exists(out), "the parallel write produced no file")
pftest.check([f for f in os.listdir(os.path.dirname(out)) if ".tmp-" in f] == [], "temporary files left behind")
copy = pftest.fetch(ParaFluidHDF5Particles(FileName=out))
original = pftest.fetch(reader)
order_copy, order_original = np.argsort(pftest.point_array(copy, "id")), np.argsort(pftest.point_array(original, "id"))
pftest.check(copy.GetNumberOfPoints() == n, "the parallel write holds %d particles, not %d" % (copy.GetNumberOfPoints(), n))
pftest.check(np.array_equal(pftest.point_array(copy, "id")[order_copy], np.arange(n)), "ids lost or repeated in the parallel write")
pftest.check(np.array_equal(pftest.points(copy)[order_copy], pftest.points(original)[order_original]), "positions differ after the parallel write")
pftest.check(np.array_equal(pftest.point_array(copy, "velocity")[order_copy], pftest.point_array(original, "velocity")[order_original]), "velocity differs after the parallel write")

# SPH Step: δ-SPH steps the particles where they are (each process its slab), DFSPH on process 0;
# either way every particle is simulated once, with all its neighbours.
for solver, where in (("δ-SPH", {0, 1}), ("DFSPH", {0})):
    sph = SPHStep(Input=reader, PressureSolver=solver, OutputInterval=0.004, NumberOfOutputs=2)
    stepped = pftest.fetch(ProcessIdScalars(Input=sph), sph.TimestepValues[-1])
    pftest.check(stepped.GetNumberOfPoints() == n, "%s: SPH output holds %d particles, not %d" % (solver, stepped.GetNumberOfPoints(), n))
    order = np.argsort(pftest.point_array(stepped, "id"))
    pftest.check(np.array_equal(pftest.point_array(stepped, "id")[order], np.arange(n)), "%s: SPH output lost or repeated particles" % solver)
    pftest.check(set(pftest.point_array(stepped, "ProcessId")) == where, "%s: SPH output on processes %s, not %s" % (solver, set(pftest.point_array(stepped, "ProcessId")), where))
    moved = pftest.points(stepped)[order] - pftest.points(original)[order_original]
    pftest.check(np.abs(moved).max() > 1e-4 and np.all(np.isfinite(moved)), "%s: SPH under MPI did not step" % solver)
print("mpi pieces: ok")
