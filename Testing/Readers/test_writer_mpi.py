"""The H5Part writer under MPI (pvbatch, 2 and 3 ranks) writes one file with parallel HDF5, each
process its own particles: read in pieces from a two-step file and written back with every time
step, the file holds every particle once with its position, arrays, the steps' times and the root
attributes, compressed or not; a process without particles takes part; no temporary is left."""
import json
import os
import subprocess

from paraview.simple import *
from paraview import servermanager
import pftest

pftest.load(globals())
ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
pftest.check(ranks >= 2, "run with 2 or more MPI ranks (got %d)" % ranks)
# The script runs on process 0; the pipeline (reader, writer) on every process.
folder = pftest.scratch_dir()
source_file = os.path.join(folder, "source_file.h5part")
pftest.write_h5(source_file, """
rng = np.random.default_rng(7)
n = 5000
for k, t in enumerate([0.0, 0.25]):
    s = f.create_group('Step#%d' % k)
    s.attrs['TimeValue'] = t
    P = rng.random((n, 3))
    for name, column in zip('xyz', P.T):
        s[name] = column.astype(np.float32)
    s['id'] = rng.permutation(n).astype(np.int64)
    s['velocity'] = rng.random((n, 3)).astype(np.float32)
    s['density'] = (1000 + rng.random(n)).astype(np.float64)
f.attrs['particle_spacing'] = 0.01
f.attrs['title'] = np.bytes_('column')
""")

CHECK = r"""
import h5py, json, sys, numpy as np
def load(path):
    out = {}
    with h5py.File(path, 'r') as f:
        out['attrs'] = {k: [x.decode() if isinstance(x, bytes) else x for x in np.atleast_1d(v).tolist()]
                        for k, v in f.attrs.items()}
        for g in sorted(k for k in f if k.startswith('Step#')):
            s = f[g]
            order = np.argsort(s['id'][()])
            step = {'time': float(np.atleast_1d(s.attrs.get('time', s.attrs.get('TimeValue', [0])))[0]),
                    'names': sorted(s.keys()), 'n': int(len(s['id']))}
            step['deflate'] = [name for name in s if s[name].compression == 'gzip']
            for name in s:
                step[name] = np.asarray(s[name][()])[order].tolist()
            out[g] = step
    return out
print(json.dumps([load(sys.argv[1]), load(sys.argv[2])]))
"""


def compare(written, level):
    result = subprocess.run(["/usr/bin/python3", "-c", CHECK, source_file, written], check=True, capture_output=True, text=True)
    original, back = json.loads(result.stdout)
    for step in ("Step#0", "Step#1"):
        pftest.check(back[step]["n"] == original[step]["n"], "%s: %d particles written of %d" % (step, back[step]["n"], original[step]["n"]))
        for name in ("x", "y", "z", "id", "velocity", "density"):
            pftest.check(name in back[step]["names"], "%s: no dataset '%s' (has %s)" % (step, name, back[step]["names"]))
            pftest.check(back[step][name] == original[step][name], "%s: '%s' differs from the source_file" % (step, name))
        pftest.check(abs(back[step]["time"] - original[step]["time"]) < 1e-12, "%s: time %g" % (step, back[step]["time"]))
        pftest.check(("x" in back[step]["deflate"]) == (level > 0), "%s: compression %s at level %d" % (step, back[step]["deflate"], level))
    pftest.check(abs(back["attrs"]["particle_spacing"][0] - 0.01) < 1e-15 and back["attrs"]["title"] == ["column"],
                 "root attributes: %s" % back["attrs"])


reader = ParaFluidHDF5Particles(FileName=source_file)
for level in (0, 1):
    target = os.path.join(folder, "written_%d.h5part" % level)
    SaveData(target, proxy=reader, WriteAllTimeSteps=1, CompressionLevel=level)
    compare(target, level)

# Every particle on process 0: the other processes have none and still take part.
lopsided = ProgrammableSource(OutputDataSetType="vtkPolyData", Script="""
import numpy as np
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
from vtkmodules.util.numpy_support import numpy_to_vtk
info = self.GetOutputInformation(0)
if info.Get(sddp.UPDATE_PIECE_NUMBER()) == 0:
    out = self.GetPolyDataOutput()
    P = np.arange(3000 * 3, dtype=np.float32).reshape(-1, 3)
    points = vtkPoints()
    points.SetData(numpy_to_vtk(P, deep=True))
    out.SetPoints(points)
    ids = numpy_to_vtk(np.arange(3000, dtype=np.int64)[::-1].copy(), deep=True)
    ids.SetName("id")
    out.GetPointData().AddArray(ids)
""")
alone = os.path.join(folder, "alone.h5part")
SaveData(alone, proxy=lopsided, CompressionLevel=1)
result = subprocess.run(["/usr/bin/python3", "-c", CHECK, alone, alone], check=True, capture_output=True, text=True)
back = json.loads(result.stdout)[0]["Step#0"]
pftest.check(back["n"] == 3000 and back["id"] == list(range(3000)), "process 0 alone: %d particles written of 3000" % back["n"])
pftest.check(back["x"] == [3.0 * i for i in reversed(range(3000))], "process 0 alone: positions differ")
left = [name for name in os.listdir(folder) if ".tmp-" in name]
pftest.check(not left, "temporaries left: %s" % left)
print("writer under MPI (%d ranks): two steps of 5000 particles in one file, compressed and not; "
      "3000 particles of process 0 alone" % ranks)
