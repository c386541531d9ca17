"""Time to read a Gadget-style snapshot of gas particles (Coordinates, Velocities, Masses, Density,
SmoothingLength, ParticleIDs): ParaFluid HDF5 Particles against h5py reading the same datasets into
NumPy, from the page cache (each file read once before the timing), uncompressed and with deflate-1.
The median of `repeats` reads each.

  PARAFLUID_PLUGIN=<ParaFluid.so> pvpython Testing/Benchmarks/snapshot_read_benchmark.py [particles] [repeats]"""
import os
import statistics
import subprocess
import sys
import tempfile
import time

from paraview.simple import *

LoadPlugin(os.environ["PARAFLUID_PLUGIN"], ns=globals())
n = int(sys.argv[1]) if len(sys.argv) > 1 else 10_000_000
repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 5
folder = tempfile.mkdtemp(prefix="parafluid-snapshot-bench-")
DATASETS = ("Coordinates", "Velocities", "Masses", "Density", "SmoothingLength", "ParticleIDs")
files = {}
for label, options in (("plain", "{}"), ("deflate-1", "dict(compression='gzip', compression_opts=1, chunks=True)")):
    path = os.path.join(folder, "snap_%s.hdf5" % label.replace("-", ""))
    subprocess.run(["/usr/bin/python3", "-c", f"""
import h5py, numpy as np
rng = np.random.default_rng(5)
n = {n}
with h5py.File({path!r}, 'w') as f:
    h = f.create_group('Header')
    h.attrs['NumPart_ThisFile'] = np.array([n, 0, 0, 0, 0, 0], 'u4'); h.attrs['NumPart_Total'] = h.attrs['NumPart_ThisFile']
    h.attrs['NumPart_Total_HighWord'] = np.zeros(6, 'u4'); h.attrs['MassTable'] = np.zeros(6)
    h.attrs['Time'] = 1.0; h.attrs['BoxSize'] = 100.0; h.attrs['NumFilesPerSnapshot'] = 1
    g = f.create_group('PartType0'); o = {options}
    g.create_dataset('Coordinates', data=(rng.random((n, 3), dtype=np.float32) * 100), **o)
    g.create_dataset('Velocities', data=rng.standard_normal((n, 3), dtype=np.float32), **o)
    for name in ('Masses', 'Density', 'SmoothingLength'):
        g.create_dataset(name, data=rng.random(n, dtype=np.float32), **o)
    g.create_dataset('ParticleIDs', data=np.arange(n, dtype=np.uint64), **o)
"""], check=True)
    files[label] = path

H5PY = """
import h5py, sys, time, statistics
path, repeats = sys.argv[1], int(sys.argv[2])
names = %r
def read():
    with h5py.File(path, 'r') as f:
        return [f['PartType0/' + name][...] for name in names]
read()
times = []
for _ in range(repeats):
    start = time.perf_counter(); arrays = read(); times.append(time.perf_counter() - start)
print(statistics.median(times), sum(a.nbytes for a in arrays))
""" % (DATASETS,)

print("%d gas particles, %s; this machine: %d cores" % (n, ", ".join(DATASETS), os.cpu_count()))
print("| file | ParaFluid HDF5 Particles (the reader's update) | pvpython UpdatePipeline | h5py into NumPy | array data | ParaFluid's rate |")
print("|---|---|---|---|---|---|")
for label, path in files.items():
    reader = ParaFluidHDF5Particles(FileName=path)
    reader.UpdatePipeline()  # into the page cache, and the pipeline's information
    vtk_reader = reader.GetClientSideObject()
    times, pipeline = [], []
    for _ in range(repeats):
        vtk_reader.Modified()  # the VTK object's own update: the read, without ParaView's data information
        start = time.perf_counter()
        vtk_reader.Update()
        times.append(time.perf_counter() - start)
        vtk_reader.Modified()
        reader.MarkModified(reader)
        start = time.perf_counter()
        reader.UpdatePipeline()
        pipeline.append(time.perf_counter() - start)
    ours = statistics.median(times)
    theirs, nbytes = subprocess.run(["/usr/bin/python3", "-c", H5PY, path, str(repeats)], check=True,
                                    capture_output=True, text=True).stdout.split()
    print("| %s | %.3f s | %.3f s | %.3f s | %.0f MB | %.2f GB/s |" % (
        label, ours, statistics.median(pipeline), float(theirs), int(nbytes) / 1e6, int(nbytes) / ours / 1e9))
    Delete(reader)
