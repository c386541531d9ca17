"""Writes a large, incompressible particle file slowly (deflate level 9 on random values), so that
the writer-safety test can signal the process in the middle of the write: pvpython slow_write.py <target>."""
import sys

from paraview.simple import *
import pftest

pftest.load(globals())
body = """
rng = np.random.default_rng(1)
P = rng.random((3000000, 3))
for k in range(5):
    arrays['noise%d' % k] = rng.random(len(P))
"""
source = ProgrammableSource(Script=pftest.particle_script(body))
SaveData(sys.argv[1], proxy=source, CompressionLevel=9)
