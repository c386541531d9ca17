"""ParaFluid HDF5 Particles reads the layouts particle codes write, found from the file's content:
 - H5MD 1.1 as LAMMPS' and other producers' documented variants write it (h5py, to the
   specification: Debian's lammps has no dump h5md): time-dependent elements (value with a frame
   axis, step/time per frame or as a fixed interval), time-independent datasets and scalars, two
   particle groups as two blocks, the box as domain bounds and periodicity;
 - the same particles written as H5Part and as H5MD read identically;
 - a SWIFT-style snapshot: one block per particle type, gas first, values in SI from the
   per-dataset CGS factors and exponents, the unit in each array's information, MassTable as a
   constant mass, BoxSize, Time and Redshift as field data;
 - a Gadget snapshot split over two files read as one; a missing file, counts that disagree with
   the header, and a file of no known layout are errors that name what is wrong;
 - OpenDataFile picks this reader for .h5md and .hdf5 files, and DetectedLayout says which layout."""
import os

import numpy as np
from paraview.simple import *
from paraview import servermanager
import pftest

pftest.load(globals())
out = pftest.scratch_dir()
N = 12


def blocks(reader, t=None):
    data = pftest.fetch(reader, t)
    return {data.GetMetaData(b).Get(data.NAME()): data.GetBlock(b) for b in range(data.GetNumberOfBlocks())}


def field(block, name):
    array = block.GetFieldData().GetArray(name)
    return [array.GetValue(k) for k in range(array.GetNumberOfTuples())] if array else None


def unit(block, name):
    array = block.GetPointData().GetArray(name) if name != "points" else block.GetPoints().GetData()
    return array.GetInformation().Get(array.UNITS_LABEL())


def errors_of(path):
    reader = ParaFluidHDF5Particles(FileName=path)
    messages = pftest.Messages(reader.GetClientSideObject())
    reader.UpdatePipelineInformation()
    reader.UpdatePipeline()
    Delete(reader)
    return "\n".join(messages.errors)


# --- H5MD -----------------------------------------------------------------------------------------
h5md = os.path.join(out, "lammps.h5md")
pftest.write_h5(h5md, """
h = f.create_group('h5md'); h.attrs['version'] = np.array([1, 1])
h.create_group('author').attrs['name'] = 'ParaFluid test'
c = h.create_group('creator'); c.attrs['name'] = 'LAMMPS'; c.attrs['version'] = '29Sep2021'
rng = np.random.default_rng(7)
positions = rng.random((3, %(N)d, 3)) * 10
g = f.create_group('particles/all')
box = g.create_group('box'); box.attrs['dimension'] = 3
box.attrs['boundary'] = np.array([b'periodic', b'periodic', b'none'])
box['edges'] = np.array([10.0, 20.0, 30.0])
p = g.create_group('position'); p['value'] = positions; p['value'].attrs['unit'] = 'nm'
p['step'] = np.array([0, 100, 200]); p['time'] = np.array([0.0, 0.5, 1.0])
v = g.create_group('velocity'); v['value'] = positions * -2.0; v['step'] = np.array([0, 100, 200])
v['time'] = np.array([0.0, 0.5, 1.0])
i = g.create_group('id'); i['value'] = np.tile(np.arange(%(N)d)[::-1] + 50, (3, 1))
i['step'] = 100; i['time'] = 0.5  # a fixed interval: scalars
g['species'] = (np.arange(%(N)d) %% 3).astype('i4')
g['charge'] = -1.5  # one value for every particle
s = f.create_group('particles/solvent')
q = s.create_group('position'); q['value'] = np.zeros((1, 4, 3)); q['time'] = np.array([0.5]); q['step'] = np.array([100])
""" % {"N": N})
positions = np.random.default_rng(7).random((3, N, 3)) * 10  # what the file holds, made here again

reader = OpenDataFile(h5md)
pftest.check(reader.GetXMLName() == "H5ParaFluidParticlesReader", "OpenDataFile picks %s for .h5md" % reader.GetXMLName())
reader.UpdatePipelineInformation()
layout = reader.GetProperty("DetectedLayout").GetElement(0)
pftest.check(layout == "H5MD 1.1 (LAMMPS)", "DetectedLayout %r" % layout)
pftest.check(list(reader.TimestepValues) == [0.0, 0.5, 1.0], "times %s" % list(reader.TimestepValues))
for frame, t in enumerate([0.0, 0.5, 1.0]):
    got = blocks(reader, t)
    pftest.check(sorted(got) == ["all", "solvent"], "one block per particle group: %s" % sorted(got))
    every = got["all"]
    pftest.check(np.allclose(pftest.points(every), positions[frame]), "positions of frame %d" % frame)
    pftest.check(np.allclose(pftest.point_array(every, "velocity"), -2.0 * positions[frame]), "velocity of frame %d" % frame)
    pftest.check(list(pftest.point_array(every, "id")) == list(range(50 + N - 1, 49, -1)), "time-dependent ids")
    pftest.check(list(pftest.point_array(every, "species")) == [k % 3 for k in range(N)], "time-independent species")
    pftest.check(np.all(pftest.point_array(every, "charge") == -1.5), "a scalar element is every particle's value")
    pftest.check(field(every, "time") == [t], "time field %s" % field(every, "time"))
    pftest.check(field(every, "domain_bounds") == [0, 10, 0, 20, 0, 30], "box edges %s" % field(every, "domain_bounds"))
    pftest.check(field(every, "domain_periodic") == [1, 1, 0], "boundary %s" % field(every, "domain_periodic"))
    pftest.check(unit(every, "points") == "nm", "the position's unit: %r" % unit(every, "points"))
    pftest.check(got["solvent"].GetNumberOfPoints() == 4, "the second group's single frame at every time")
reader.PointArrays = ["species"]
selected = blocks(reader, 0.5)["all"]
pftest.check(pftest.array_names(selected) == ["id", "species"], "only the selected arrays: %s" % pftest.array_names(selected))
print("H5MD: 2 groups, 3 frames, box and units read")

# --- the same particles as H5Part and as H5MD ------------------------------------------------------
same_h5part, same_h5md = os.path.join(out, "same.h5part"), os.path.join(out, "same.h5md")
make = "rng = np.random.default_rng(3); P = rng.random((%d, 3)); V = rng.random((%d, 3)); I = np.arange(%d)[::-1]" % (N, N, N)
pftest.write_h5(same_h5part, make + """
g = f.create_group('Step#0'); g.attrs['time'] = 0.0
g['x'] = P[:, 0]; g['y'] = P[:, 1]; g['z'] = P[:, 2]; g['velocity'] = V; g['id'] = I
""")
pftest.write_h5(same_h5md, make + """
f.create_group('h5md').attrs['version'] = np.array([1, 0])
g = f.create_group('particles/fluid')
g['position'] = P; g['velocity'] = V; g['id'] = I
""")
a = pftest.fetch(ParaFluidHDF5Particles(FileName=same_h5part))
b = blocks(ParaFluidHDF5Particles(FileName=same_h5md))["fluid"]
for name in ("velocity", "id"):
    pftest.check(np.array_equal(pftest.point_array(a, name), pftest.point_array(b, name)), "%s differs between layouts" % name)
pftest.check(np.array_equal(pftest.points(a), pftest.points(b)), "positions differ between layouts")
print("H5Part and H5MD: the same particles")

# --- a SWIFT-style snapshot ----------------------------------------------------------------------
MPC_CM, KM_CM, MSUN10_G = 3.08567758e24, 1e5, 1.98841e43
swift = os.path.join(out, "snap_0007.hdf5")
pftest.write_h5(swift, """
h = f.create_group('Header')
h.attrs['NumPart_ThisFile'] = np.array([%(N)d, 4, 0, 0, 2, 0], dtype='u4')
h.attrs['NumPart_Total'] = np.array([%(N)d, 4, 0, 0, 2, 0], dtype='u4')
h.attrs['NumPart_Total_HighWord'] = np.zeros(6, dtype='u4')
h.attrs['MassTable'] = np.array([0.0, 0.5, 0.0, 0.0, 0.0, 0.0])
h.attrs['Time'] = 0.25; h.attrs['Redshift'] = 3.0; h.attrs['BoxSize'] = np.array([100.0, 100.0, 100.0])
h.attrs['NumFilesPerSnapshot'] = 1
u = f.create_group('Units')
u.attrs['Unit length in cgs (U_L)'] = %(L)r; u.attrs['Unit mass in cgs (U_M)'] = %(M)r
u.attrs['Unit time in cgs (U_t)'] = %(L)r / %(V)r
f.create_group('Code').attrs['Code'] = 'SWIFT'
def units(d, factor, **exponents):
    d.attrs['Conversion factor to CGS (not including cosmological corrections)'] = factor
    for name in ('U_M', 'U_L', 'U_t', 'U_I', 'U_T'):
        d.attrs[name + ' exponent'] = float(exponents.get(name, 0.0))
# Type 4 (stars) first in the file: the blocks still come gas first.
s = f.create_group('PartType4'); s['Coordinates'] = np.full((2, 3), 50.0); s['ParticleIDs'] = np.array([7, 8], 'u8')
s['Masses'] = np.array([1.0, 2.0], 'f4')
g = f.create_group('PartType0')
g['Coordinates'] = np.arange(3 * %(N)d, dtype='f8').reshape(%(N)d, 3); units(g['Coordinates'], %(L)r, U_L=1)
g['Velocities'] = np.ones((%(N)d, 3), 'f4') * 2; units(g['Velocities'], %(V)r, U_L=1, U_t=-1)
g['Masses'] = np.full(%(N)d, 3.0, 'f4'); units(g['Masses'], %(M)r, U_M=1)
g['Densities'] = np.full(%(N)d, 4.0, 'f4'); units(g['Densities'], %(M)r / %(L)r ** 3, U_M=1, U_L=-3)
g['SmoothingLengths'] = np.full(%(N)d, 0.5, 'f4'); units(g['SmoothingLengths'], %(L)r, U_L=1)
g['InternalEnergies'] = np.full(%(N)d, 6.0, 'f4'); units(g['InternalEnergies'], %(V)r ** 2, U_L=2, U_t=-2)
g['ParticleIDs'] = np.arange(%(N)d, dtype='u8') + 1000
d = f.create_group('PartType1'); d['Coordinates'] = np.zeros((4, 3)); d['ParticleIDs'] = np.arange(4, dtype='u8')
""" % {"N": N, "L": MPC_CM, "M": MSUN10_G, "V": KM_CM})
reader = OpenDataFile(swift)
pftest.check(reader.GetXMLName() == "H5ParaFluidParticlesReader", "OpenDataFile picks %s for .hdf5" % reader.GetXMLName())
reader.UpdatePipelineInformation()
pftest.check(reader.GetProperty("DetectedLayout").GetElement(0) == "SWIFT snapshot",
             "DetectedLayout %r" % reader.GetProperty("DetectedLayout").GetElement(0))
data = pftest.fetch(reader)
names = [data.GetMetaData(b).Get(data.NAME()) for b in range(data.GetNumberOfBlocks())]
pftest.check(names == ["PartType0 (gas)", "PartType1 (dark matter)", "PartType4 (stars)"], "blocks %s" % names)
gas, dark = data.GetBlock(0), data.GetBlock(1)
mpc = MPC_CM * 1e-2
pftest.check(np.allclose(pftest.points(gas), np.arange(3 * N).reshape(N, 3) * mpc, rtol=1e-12), "coordinates in metres")
pftest.check(np.allclose(pftest.point_array(gas, "velocity"), 2 * KM_CM * 1e-2), "velocities in m/s")
pftest.check(np.allclose(pftest.point_array(gas, "mass"), 3 * MSUN10_G * 1e-3, rtol=1e-6), "masses in kg")
pftest.check(np.allclose(pftest.point_array(gas, "density"), 4 * MSUN10_G * 1e-3 / mpc ** 3, rtol=1e-6), "density in kg/m^3")
pftest.check(np.allclose(pftest.point_array(gas, "smoothing_length"), 0.5 * mpc, rtol=1e-6), "smoothing length in m")
pftest.check(np.allclose(pftest.point_array(gas, "internal_energy"), 6 * (KM_CM * 1e-2) ** 2, rtol=1e-6), "energy in J/kg")
for name, expected in (("points", "m"), ("velocity", "m s^-1"), ("mass", "kg"), ("density", "kg m^-3"),
                       ("internal_energy", "m^2 s^-2")):
    pftest.check(unit(gas, name) == expected, "unit of %s: %r" % (name, unit(gas, name)))
pftest.check(list(pftest.point_array(gas, "id")) == list(range(1000, 1000 + N)), "ParticleIDs")
pftest.check(np.allclose(pftest.point_array(dark, "mass"), 0.5 * MSUN10_G * 1e-3), "MassTable as a constant mass in kg")
pftest.check(field(gas, "time") == [0.25] and field(gas, "redshift") == [3.0], "Time and Redshift")
pftest.check(np.allclose(field(gas, "domain_bounds"), [0, 100 * mpc] * 3), "BoxSize in metres")
print("SWIFT: types as blocks, SI units")

# --- a Gadget snapshot of two files, and what is wrong with snapshots -------------------------------
def gadget_part(path, this, total, first, files=2):
    pftest.write_h5(path, """
h = f.create_group('Header')
h.attrs['NumPart_ThisFile'] = np.array([%d, 0, 0, 0, 0, 0], dtype='i4')
h.attrs['NumPart_Total'] = np.array([%d, 0, 0, 0, 0, 0], dtype='u4')
h.attrs['NumPart_Total_HighWord'] = np.zeros(6, dtype='u4')
h.attrs['MassTable'] = np.zeros(6); h.attrs['Time'] = 1.0; h.attrs['NumFilesPerSnapshot'] = %d
g = f.create_group('PartType0')
g['Coordinates'] = np.arange(%d, %d, dtype='f4').repeat(3).reshape(-1, 3)
g['Velocities'] = np.zeros((%d, 3), 'f4'); g['ParticleIDs'] = np.arange(%d, %d, dtype='u4')
""" % (this, total, files, first, first + this, this, first, first + this))


gadget0, gadget1 = os.path.join(out, "snap_002.0.hdf5"), os.path.join(out, "snap_002.1.hdf5")
gadget_part(gadget0, 7, 12, 0)
gadget_part(gadget1, 5, 12, 7)
reader = ParaFluidHDF5Particles(FileName=gadget1)
reader.UpdatePipelineInformation()
pftest.check(reader.GetProperty("DetectedLayout").GetElement(0) == "Gadget-style snapshot, 2 files",
             "DetectedLayout %r" % reader.GetProperty("DetectedLayout").GetElement(0))
gas = blocks(reader)["PartType0 (gas)"]
pftest.check(list(pftest.points(gas)[:, 0]) == list(range(12)) and list(pftest.point_array(gas, "id")) == list(range(12)),
             "the two files read as one, in file order")
os.rename(gadget1, gadget1 + ".away")
text = errors_of(gadget0)
pftest.check("snap_002.1.hdf5" in text and "missing" in text, "a missing file of the snapshot: %r" % text)
os.rename(gadget1 + ".away", gadget1)
gadget_part(gadget1, 5, 13, 7)
text = errors_of(gadget0)
pftest.check("snap_002.1.hdf5" in text and "NumPart_Total differs" in text, "files that disagree: %r" % text)
gadget_part(gadget1, 6, 12, 7)
text = errors_of(gadget0)
pftest.check("13 particles of type 0" in text and "NumPart_Total says 12" in text, "counts against the header: %r" % text)
other = os.path.join(out, "other.h5")
pftest.write_h5(other, "f['mesh/cells'] = np.zeros(4)")
text = errors_of(other)
pftest.check(all(word in text for word in ("H5MD", "PartType", "Step#", "other.h5")), "an unknown layout: %r" % text)
bad = os.path.join(out, "flat.h5md")
pftest.write_h5(bad, """
f.create_group('h5md').attrs['version'] = np.array([1, 1])
g = f.create_group('particles/all/position'); g['value'] = np.zeros((2, 5, 2)); g['time'] = np.array([0.0, 1.0])
""")
text = errors_of(bad)
pftest.check("/particles/all/position/value" in text and "N x 3" in text, "2-D positions: %r" % text)
print("Gadget: two files as one; missing files, bad counts, unknown layouts and shapes named")

# --- openPMD: groupBased and fileBased ---------------------------------------------------------------
OPENPMD_ITERATION = """
def iteration(f, it, t, n, shift):
    g = f.create_group('data/%d' % it); g.attrs['time'] = t; g.attrs['dt'] = 0.1; g.attrs['timeUnitSI'] = 1e-15
    e = g.create_group('particles/electrons')
    pos = e.create_group('position'); pos.attrs['unitDimension'] = np.array([1.0, 0, 0, 0, 0, 0, 0])
    off = e.create_group('positionOffset'); off.attrs['unitDimension'] = np.array([1.0, 0, 0, 0, 0, 0, 0])
    for a, axis in enumerate('xyz'):
        pos[axis] = np.arange(n, dtype='f4') * (a + 1) + shift; pos[axis].attrs['unitSI'] = 1e-6
        c = off.create_group(axis); c.attrs['value'] = 2.0 if axis == 'x' else 0.0; c.attrs['shape'] = np.array([n], 'u8')
        c.attrs['unitSI'] = 1e-6
    mom = e.create_group('momentum'); mom.attrs['unitDimension'] = np.array([1.0, 1, -1, 0, 0, 0, 0])
    for axis in 'xyz':
        mom[axis] = np.full(n, 3.0); mom[axis].attrs['unitSI'] = 2e-22
    e['weighting'] = np.full(n, 5.0); e['weighting'].attrs['unitSI'] = 1.0
    q = e.create_group('charge'); q.attrs['value'] = -1.0; q.attrs['shape'] = np.array([n], 'u8'); q.attrs['unitSI'] = 1.602e-19
    q.attrs['unitDimension'] = np.array([0.0, 0, 1, 1, 0, 0, 0])
    e['id'] = np.arange(n, dtype='u8') + 7 * it
def header(f, encoding, fmt):
    f.attrs['openPMD'] = np.string_('1.1.0'); f.attrs['openPMDextension'] = np.uint32(0)
    f.attrs['basePath'] = np.string_('/data/%T/'); f.attrs['particlesPath'] = np.string_('particles/')
    f.attrs['meshesPath'] = np.string_('meshes/'); f.attrs['iterationEncoding'] = np.string_(encoding)
    f.attrs['iterationFormat'] = np.string_(fmt)
"""
grouped = os.path.join(out, "pic_grouped.h5")
pftest.write_h5(grouped, OPENPMD_ITERATION + """
header(f, 'groupBased', '/data/%T/')
iteration(f, 100, 10.0, 6, 0.0)
iteration(f, 200, 20.0, 6, 1.0)
""")
reader = OpenDataFile(grouped)
pftest.check(reader.GetXMLName() == "H5ParaFluidParticlesReader", "OpenDataFile picks %s for openPMD .h5" % reader.GetXMLName())
reader.UpdatePipelineInformation()
pftest.check(reader.GetProperty("DetectedLayout").GetElement(0) == "openPMD 1.1.0",
             "DetectedLayout %r" % reader.GetProperty("DetectedLayout").GetElement(0))
pftest.check(np.allclose(reader.TimestepValues, [1e-14, 2e-14]), "iteration times in s: %s" % list(reader.TimestepValues))
electrons = blocks(reader, 2e-14)["electrons"]
expected = np.stack([np.arange(6) * (a + 1) + 1.0 for a in range(3)], axis=1) * 1e-6
expected[:, 0] += 2e-6  # positionOffset's constant x
pftest.check(np.allclose(pftest.points(electrons), expected, rtol=1e-6, atol=1e-12), "position + positionOffset in m")
pftest.check(unit(electrons, "points") == "m", "position unit %r" % unit(electrons, "points"))
pftest.check(np.allclose(pftest.point_array(electrons, "momentum"), 6e-22) and unit(electrons, "momentum") == "kg m s^-1",
             "momentum in SI with its unit (%r)" % unit(electrons, "momentum"))
pftest.check(np.allclose(pftest.point_array(electrons, "charge"), -1.602e-19) and unit(electrons, "charge") == "s A",
             "a constant record as every particle's value (%r)" % unit(electrons, "charge"))
pftest.check(np.allclose(pftest.point_array(electrons, "weighting"), 5.0), "a scalar record")
pftest.check(list(pftest.point_array(electrons, "id")) == list(range(1400, 1406)), "ids of iteration 200")
for k, it in enumerate((100, 200, 300)):
    pftest.write_h5(os.path.join(out, "series_%06d.h5" % it), OPENPMD_ITERATION + """
header(f, 'fileBased', 'series_%%06T.h5')
iteration(f, %d, %r, %d, 0.0)
""" % (it, 10.0 * (k + 1), 4 + k))
reader = ParaFluidHDF5Particles(FileName=os.path.join(out, "series_000200.h5"))
reader.UpdatePipelineInformation()
pftest.check(np.allclose(reader.TimestepValues, [1e-14, 2e-14, 3e-14]), "a file per iteration: %s" % list(reader.TimestepValues))
pftest.check([blocks(reader, t)["electrons"].GetNumberOfPoints() for t in reader.TimestepValues] == [4, 5, 6],
             "each time from its own file")
print("openPMD: groupBased and fileBased, SI units, constant records")

# --- VTKHDF PolyData, as VTK 9.3 writes it ---------------------------------------------------------
vtkhdf = os.path.join(out, "cloud.vtkhdf.hdf5")
pftest.write_h5(vtkhdf, """
root = f.create_group('VTKHDF'); root.attrs['Version'] = np.array([2, 0])
root.attrs.create('Type', np.string_('PolyData'), dtype=h5py.string_dtype('ascii', len('PolyData')))
# two steps, of 2 partitions (3 + 2 points) and 1 partition (4 points), one after the other
root['NumberOfPoints'] = np.array([3, 2, 4])
root['Points'] = np.arange(27, dtype='f4').reshape(9, 3)
pd = root.create_group('PointData'); pd['temperature'] = np.arange(9, dtype='f8') * 10; pd['id'] = np.arange(9) + 100
for kind in ('Vertices', 'Lines', 'Polygons', 'Strips'):
    g = root.create_group(kind); g['NumberOfCells'] = np.zeros(3, 'i8'); g['NumberOfConnectivityIds'] = np.zeros(3, 'i8')
    g['Offsets'] = np.zeros(3, 'i8'); g['Connectivity'] = np.zeros(0, 'i8')
steps = root.create_group('Steps'); steps.attrs['NSteps'] = 2
steps['Values'] = np.array([0.5, 1.5]); steps['PartOffsets'] = np.array([0, 2]); steps['NumberOfParts'] = np.array([2, 1])
steps['PointOffsets'] = np.array([0, 5]); steps.create_group('PointDataOffsets')
steps['PointDataOffsets/temperature'] = np.array([0, 5]); steps['PointDataOffsets/id'] = np.array([0, 5])
""")
reader = ParaFluidHDF5Particles(FileName=vtkhdf)
reader.UpdatePipelineInformation()
pftest.check(reader.GetProperty("DetectedLayout").GetElement(0) == "VTKHDF PolyData 2.0",
             "DetectedLayout %r" % reader.GetProperty("DetectedLayout").GetElement(0))
pftest.check(list(reader.TimestepValues) == [0.5, 1.5], "VTKHDF steps %s" % list(reader.TimestepValues))
first, second = blocks(reader, 0.5)["particles"], blocks(reader, 1.5)["particles"]
pftest.check(np.array_equal(pftest.points(first), np.arange(15).reshape(5, 3)), "step 0: both partitions' points")
pftest.check(np.array_equal(pftest.points(second), np.arange(15, 27).reshape(4, 3)), "step 1's points")
pftest.check(list(pftest.point_array(second, "temperature")) == [50, 60, 70, 80], "step 1's point data")
pftest.check(list(pftest.point_array(second, "id")) == [105, 106, 107, 108], "ids from PointData/id")
print("VTKHDF: steps and partitions")
