"""Writes a large, incompressible particle file slowly (deflate level 9 on random values), so that
the writer-safety test can signal the process in the middle of the write: pvpython slow_write.py <target>."""
import signal
import sys

from paraview.simple import *
import pftest

pftest.load(globals())
# The signals' default actions, not the handlers ParaView's logger (loguru) installs: that handler
# prints a symbolised stack trace, which allocates inside the handler and so can deadlock when the
# signal lands in malloc (a CI run once waited 120 s for this writer to end). The writer's guard
# chains to whatever handler was there before it; what is tested here is the file it leaves.
signal.signal(signal.SIGTERM, signal.SIG_DFL)
signal.signal(signal.SIGINT, signal.SIG_DFL)
body = """
rng = np.random.default_rng(1)
P = rng.random((3000000, 3))
for k in range(5):
    arrays['noise%d' % k] = rng.random(len(P))
"""
source = ProgrammableSource(Script=pftest.particle_script(body))
SaveData(sys.argv[1], proxy=source, CompressionLevel=9)
