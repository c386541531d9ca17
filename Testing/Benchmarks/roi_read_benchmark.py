"""Time to read a region of interest of a cell-indexed SWIFT snapshot against the whole snapshot:
`particles` gas particles (Coordinates, Velocities, Masses, Densities, SmoothingLengths,
ParticleIDs) sorted into cells³ top-level cells with their /Cells index (and the cells' particle
bounds), read by ParaFluid HDF5 Particles from the page cache; the box holds 1 % of the volume at
the box's centre. The median of `repeats` reads each, and the bytes read (rchar).

  PARAFLUID_PLUGIN=<ParaFluid.so> pvpython Testing/Benchmarks/roi_read_benchmark.py [particles] [cells] [repeats]"""
import os
import statistics
import subprocess
import sys
import tempfile
import time

from paraview.simple import *

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Readers"))
import cell_snapshot  # noqa: E402

LoadPlugin(os.environ["PARAFLUID_PLUGIN"], ns=globals())
n = int(sys.argv[1]) if len(sys.argv) > 1 else 10_000_000
cells = int(sys.argv[2]) if len(sys.argv) > 2 else 32
repeats = int(sys.argv[3]) if len(sys.argv) > 3 else 5
path = os.path.join(tempfile.mkdtemp(prefix="parafluid-roi-bench-"), "cells.hdf5")
program = "import h5py, numpy as np\nwith h5py.File(%r, 'w') as f:\n" % path
program += "".join("    " + line + "\n" for line in cell_snapshot.script(n, cells).strip().splitlines())
subprocess.run(["/usr/bin/python3", "-c", program], check=True)


def rchar():
    with open("/proc/self/io") as io:
        return int(next(line for line in io if line.startswith("rchar")).split()[1])


side = 0.01 ** (1.0 / 3.0)
box = [0.5 - side / 2, 0.5 + side / 2] * 3
results = {}
for label, use_box in (("whole snapshot", 0), ("1 % box", 1)):
    reader = ParaFluidHDF5Particles(FileName=path, FileSeries=0, UseSelectionBox=use_box, SelectionBox=box)
    reader.UpdatePipeline()  # into the page cache, and the pipeline's information
    vtk_reader = reader.GetClientSideObject()
    times, read = [], 0
    for _ in range(repeats):
        vtk_reader.Modified()  # the VTK object's own update: the read, without ParaView's data information
        before, start = rchar(), time.perf_counter()
        vtk_reader.Update()
        times.append(time.perf_counter() - start)
        read = rchar() - before
    results[label] = (statistics.median(times), read, vtk_reader.GetOutputDataObject(0).GetNumberOfPoints())
    Delete(reader)
print("%d particles in %d^3 cells; this machine: %d cores" % (n, cells, os.cpu_count()))
print("| read | particles | median time | bytes read |")
print("|---|---|---|---|")
for label, (seconds, read, count) in results.items():
    print("| %s | %d | %.4f s | %.1f MB |" % (label, count, seconds, read / 1e6))
whole, roi = results["whole snapshot"][0], results["1 % box"][0]
print("box / whole: %.1f %% of the time, %.1f %% of the bytes" % (
    100 * roi / whole, 100 * results["1 % box"][1] / results["whole snapshot"][1]))
