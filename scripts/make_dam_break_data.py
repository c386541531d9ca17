"""Writes Data/dam_break.h5part: the demo's water column, made with ParaFluid's own Particle Block
source and H5Part writer. Run: PARAFLUID_PLUGIN=<ParaFluid.so> pvpython scripts/make_dam_break_data.py"""
import os
import sys
from paraview.simple import *

LoadPlugin(os.environ["PARAFLUID_PLUGIN"], ns=globals())
out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "Data", "dam_break.h5part")
# A 0.2 m x 0.1 m x 0.4 m column of water against the left wall of a 0.8 m long tank: 8000 particles.
block = ParticleBlock(Spacing=0.01, BlockBounds=[0, 0.2, 0, 0.1, 0, 0.4], DomainBounds=[0, 0.8, 0, 0.1, 0, 0.6])
SaveData(out, proxy=block, CompressionLevel=6)
print("wrote", os.path.abspath(out))
