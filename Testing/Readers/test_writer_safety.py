"""Nothing of the user's data is lost, and nothing is left behind, however a write ends:
- SIGTERM and SIGINT in the middle of a write remove the temporary file and leave the old target
  as it was;
- SIGKILL cannot be caught: its temporary stays until the next write to the same target removes it;
- field data too large for an H5Part attribute is reported (it used to vanish without a word),
  long field data (over the 64 kB of compact attribute storage) is kept;
- a 3-component "id" keeps its values as "id_components", and the file stays readable."""
import os
import signal
import subprocess
import sys
import time

import numpy as np
from paraview.simple import *
import pftest

pftest.load(globals())
out = pftest.scratch_dir()
here = os.path.dirname(os.path.abspath(__file__))
pvpython = os.path.join(os.path.dirname(sys.executable), "pvpython")
if not os.path.exists(pvpython):
    pvpython = "pvpython"

target = os.path.join(out, "precious.h5part")
small = ProgrammableSource(Script=pftest.particle_script("P = np.arange(30.0).reshape(10, 3); h = 0.5"))
SaveData(target, proxy=small)
original = open(target, "rb").read()


def temporaries():
    return [f for f in os.listdir(out) if ".tmp-" in f]


def interrupt_write(sig):
    child = subprocess.Popen([pvpython, "--force-offscreen-rendering", os.path.join(here, "writer", "slow_write.py"),
                              target], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.time() + 120
    # Signal once the temporary has grown: the write is under way.
    while time.time() < deadline and child.poll() is None:
        tmp = temporaries()
        if tmp and os.path.getsize(os.path.join(out, tmp[0])) > 1 << 20:
            break
        time.sleep(0.02)
    pftest.check(child.poll() is None, "the slow write ended before it could be interrupted")
    child.send_signal(sig)
    child.wait(timeout=120)
    pftest.check(child.returncode != 0, "signal %d did not end the writer" % sig)
    pftest.check(open(target, "rb").read() == original, "signal %d: the old file was changed" % sig)


for sig in (signal.SIGTERM, signal.SIGINT):
    interrupt_write(sig)
    pftest.check(temporaries() == [], "signal %d left %s behind" % (sig, temporaries()))

interrupt_write(signal.SIGKILL)
pftest.check(len(temporaries()) == 1, "SIGKILL: expected its temporary to stay, found %s" % temporaries())
SaveData(target, proxy=small)  # the next write to the target removes it
pftest.check(temporaries() == [], "the next write left the dead writer's temporary: %s" % temporaries())

# Field data: long arrays kept (dense attribute storage), too long ones reported by name.
fields = ProgrammableSource(Script=pftest.particle_script("""
P = np.arange(30.0).reshape(10, 3); h = 0.5
arrays['id3'] = np.ones((10, 3))
""") + """
from vtkmodules.vtkCommonCore import vtkStringArray
long_array = numpy_to_vtk(np.arange(50000.0), deep=True); long_array.SetName('long_table'); out.GetFieldData().AddArray(long_array)
huge = numpy_to_vtk(np.zeros(2**20 + 1), deep=True); huge.SetName('huge_table'); out.GetFieldData().AddArray(huge)
names = vtkStringArray(); names.SetName('labels'); names.InsertNextValue('first'); names.InsertNextValue('second')
out.GetFieldData().AddArray(names)
out.GetPointData().RemoveArray('id'); out.GetPointData().GetArray('id3').SetName('id')
""")
path = os.path.join(out, "fields.h5part")
writer = CreateWriter(path, fields)
warnings = []


@pftest.calldata_type(pftest.VTK_STRING)
def on_warning(_o, _e, text):
    warnings.append(text)


writer.GetClientSideObject().AddObserver("WarningEvent", on_warning)
writer.UpdatePipeline()
text = " ".join(warnings)
pftest.check("huge_table" in text, "the too-large field array was dropped without a warning: %r" % text)
pftest.check("id_components" in text, "the 3-component id was renamed without a warning: %r" % text)
reader = ParaFluidHDF5Particles(FileName=path)
catcher = pftest.ErrorCatcher(reader)
data = pftest.fetch(reader)
pftest.check(catcher.text() == "", "the written file is refused: %r" % catcher.text())
fd = data.GetFieldData()
pftest.check(fd.GetArray("long_table") is not None and fd.GetArray("long_table").GetNumberOfTuples() == 50000,
             "long field data (400 kB) was not kept")
labels = fd.GetAbstractArray("labels")
pftest.check(labels is not None and labels.GetValue(1) == "second", "string field data was not kept")
pftest.check(np.array_equal(pftest.point_array(data, "id_components"), np.ones((10, 3))), "the 3-component id's values were lost")
pftest.check(np.array_equal(pftest.point_array(data, "id"), np.arange(10)), "ids of a file without a usable id dataset")
# A compression level outside 0..9 is refused by name (it used to be clamped without a word).
bad_level = CreateWriter(os.path.join(out, "level.h5part"), small)
bad_level.CompressionLevel = -1
catcher = pftest.ErrorCatcher(bad_level)
bad_level.UpdatePipeline()
pftest.check("CompressionLevel" in catcher.text(), "CompressionLevel -1: %r" % catcher.text())
# An input that fails at a later time step ends the write with an error and leaves no file (the
# executive's continue-executing loop used to spin forever).
folded = ParticleBlock(BlockBounds=[0, 0.2, 0, 0.2, 0, 0.2], Spacing=0.05, DomainBounds=[0, 0.8, 0, 0.1, 0, 0.6])
# Müller's WCSPH: the folded particles (twice the rest density) stop it at once.
failing = SPHStep(Input=folded, PressureSolver="WCSPH (Müller)", OutputInterval=0.002, NumberOfOutputs=3)
late = os.path.join(out, "late.h5part")
late_writer = CreateWriter(late, failing)
late_writer.WriteAllTimeSteps = 1
catcher = pftest.ErrorCatcher(late_writer)
late_writer.UpdatePipeline()
pftest.check("input failed" in catcher.text() and not os.path.exists(late) and temporaries() == [],
             "writer of an input that fails later: %r" % catcher.text())
print("writer safety: ok")
