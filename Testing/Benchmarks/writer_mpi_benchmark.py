"""Time of the H5Part writer under pvbatch with N processes (mpirun -np N pvbatch ...): a file of
`particles` particles (positions, id, velocity, density) is read in pieces, then written back to
one file (every process its slice through parallel HDF5), uncompressed and at deflate level 1.
Prints seconds per write (median of 3), with the read of the pieces done before timing."""
import os
import subprocess
import sys
import tempfile
import time

from paraview.simple import *
from paraview import servermanager

particles = int(sys.argv[1]) if len(sys.argv) > 1 else 2000000
LoadPlugin(os.environ["PARAFLUID_PLUGIN"], ns=globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
folder = tempfile.mkdtemp(prefix="parafluid-writer-")
source = os.path.join(folder, "source.h5part")
subprocess.run(["/usr/bin/python3", "-c", """
import h5py, numpy as np, sys
n = int(sys.argv[2])
rng = np.random.default_rng(1)
with h5py.File(sys.argv[1], 'w') as f:
    s = f.create_group('Step#0')
    s.attrs['TimeValue'] = 0.0
    for name in 'xyz':
        s[name] = rng.random(n, dtype=np.float32)
    s['id'] = np.arange(n, dtype=np.int64)
    s['velocity'] = rng.random((n, 3), dtype=np.float32)
    s['density'] = rng.random(n, dtype=np.float32)
""", source, str(particles)], check=True)
reader = ParaFluidHDF5Particles(FileName=source)
reader.UpdatePipeline()
for level in (0, 1):
    seconds = []
    for repeat in range(3):
        target = os.path.join(folder, "out_%d.h5part" % level)
        start = time.perf_counter()
        SaveData(target, proxy=reader, CompressionLevel=level)
        seconds.append(time.perf_counter() - start)
    seconds.sort()
    size = os.path.getsize(target) / 1e6
    print("processes %d, particles %d, deflate %d: %.3f s per write (%.0f MB, %.0f MB/s)"
          % (ranks, particles, level, seconds[1], size, size / seconds[1]))
