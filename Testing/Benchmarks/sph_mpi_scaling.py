"""SPH Step's strong scaling over MPI processes (pvbatch): a δ-SPH dam break (a block 0.5 x 0.5 x 1 m
against a wall of a tank 2 m long) made by Particle Block on process 0, stepped with fixed steps;
prints the seconds per step of the steps after the first output, and particle-steps per second
per process. Run it once per process count, one OpenMP thread per process:

  OMP_NUM_THREADS=1 PARAFLUID_PLUGIN=build/lib/paraview-5.11/plugins/ParaFluid/ParaFluid.so \\
    mpirun -np 2 pvbatch Testing/Benchmarks/sph_mpi_scaling.py [particles] [steps]
"""
import sys
import time

from paraview.simple import *
from paraview import servermanager

LoadPlugin(__import__("os").environ["PARAFLUID_PLUGIN"], ns=globals())
particles = float(sys.argv[1]) if len(sys.argv) > 1 else 200000
steps = int(sys.argv[2]) if len(sys.argv) > 2 else 30
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()

d = 0.5 * (2.0 / particles) ** (1.0 / 3.0)  # [m] the spacing: a x a x 2a of spacing d
block = ParticleBlock(Spacing=d, BlockBounds=[0, 0.5, 0, 0.5, 0, 1.0], DomainBounds=[0, 2.0, 0, 0.5, 0, 1.5])
dt = 0.2 * 2.9 * d / 44.3  # [s] CFL 0.2 of δ-SPH's sound speed at its 2.9-spacing support
sph = SPHStep(Input=block, PressureSolver="δ-SPH", AdaptiveTimeStep=0, TimeStep=dt, OutputInterval=steps * dt,
              NumberOfOutputs=2)
sph.UpdatePipeline(steps * dt)  # the start and the first steps, out of the timing
start = time.perf_counter()
sph.UpdatePipeline(2 * steps * dt)
elapsed = time.perf_counter() - start
sph.UpdatePropertyInformation()
taken = sph.GetPropertyValue("StepsTakenLastUpdate")
n = sph.GetDataInformation().GetNumberOfPoints()
print("processes %d, particles %d, steps %d: %.4f s/step, %.3g particle-steps/s per process" %
      (ranks, n, taken, elapsed / taken, n * taken / elapsed / ranks))
