"""A SWIFT-style snapshot with its spatial index (/Cells), as SWIFT's snapshot documentation
describes it: particles sorted by top-level cell (C order, z fastest), per cell their count and
first row (Counts, OffsetsInFile, Files), the cells' centres and size, and optionally the particles'
bounds per cell (MinPositions, MaxPositions). Particles are moved off their cell by up to
`drift` cell-lengths after sorting, as SWIFT's drift between tree rebuilds does. Units: metres,
kilograms, seconds (the CGS factors 100 and 1000)."""


def script(particles, cells, bounds=True, drift=0.3, seed=3, compression=None, extra_arrays=True):
    """The h5py script (for pftest.write_h5, or run with f an open h5py.File) that writes it."""
    return """
rng = np.random.default_rng(%(seed)d)
n, c = %(particles)d, %(cells)d
x = rng.random((n, 3))
cell = np.minimum((x * c).astype(np.int64), c - 1)
index = (cell[:, 0] * c + cell[:, 1]) * c + cell[:, 2]
order = np.argsort(index, kind='stable'); x = x[order]; index = index[order]
x += (rng.random((n, 3)) - 0.5) * 2 * %(drift)r / c
counts = np.bincount(index, minlength=c ** 3)
offsets = np.concatenate([[0], np.cumsum(counts)[:-1]])
h = f.create_group('Header')
h.attrs['NumPart_ThisFile'] = np.array([n, 0, 0, 0, 0, 0]); h.attrs['NumPart_Total'] = np.array([n, 0, 0, 0, 0, 0])
h.attrs['NumPart_Total_HighWord'] = np.zeros(6, dtype='u4'); h.attrs['NumFilesPerSnapshot'] = 1
h.attrs['MassTable'] = np.zeros(6); h.attrs['Time'] = 0.25; h.attrs['BoxSize'] = np.array([1.0, 1.0, 1.0])
u = f.create_group('Units')
u.attrs['Unit length in cgs (U_L)'] = 100.0; u.attrs['Unit mass in cgs (U_M)'] = 1000.0; u.attrs['Unit time in cgs (U_t)'] = 1.0
g = f.create_group('PartType0')
def put(name, values, factor, exponents):
    d = g.create_dataset(name, data=values, chunks=True if %(compression)r else None, compression=%(compression)r)
    d.attrs['Conversion factor to CGS (not including cosmological corrections)'] = factor
    for key, e in exponents.items():
        d.attrs[key + ' exponent'] = e
put('Coordinates', x, 100.0, {'U_L': 1.0})
put('ParticleIDs', rng.permutation(n).astype('u8') * 2 + 1000, 1.0, {})
if %(extra_arrays)r:
    put('Velocities', rng.random((n, 3)).astype('f4'), 100.0, {'U_L': 1.0, 'U_t': -1.0})
    put('Masses', np.full(n, 1e-3, dtype='f4'), 1000.0, {'U_M': 1.0})
    put('Densities', rng.random(n).astype('f4'), 0.001 / 1e-6 / 1000.0, {'U_M': 1.0, 'U_L': -3.0})
    put('SmoothingLengths', np.full(n, 0.01, dtype='f4'), 100.0, {'U_L': 1.0})
cg = f.create_group('Cells')
m = cg.create_group('Meta-data'); m.attrs['dimension'] = np.array([c, c, c]); m.attrs['size'] = np.full(3, 1.0 / c)
m.attrs['nr_cells'] = c ** 3
ijk = np.stack(np.meshgrid(np.arange(c), np.arange(c), np.arange(c), indexing='ij'), -1).reshape(-1, 3)
cg['Centres'] = (ijk + 0.5) / c
cg['Counts/PartType0'] = counts; cg['OffsetsInFile/PartType0'] = offsets; cg['Files/PartType0'] = np.zeros(c ** 3, dtype='i4')
if %(bounds)r:
    lo = np.full((c ** 3, 3), np.inf); hi = np.full((c ** 3, 3), -np.inf)
    np.minimum.at(lo, index, x); np.maximum.at(hi, index, x)
    cg['MinPositions/PartType0'] = lo; cg['MaxPositions/PartType0'] = hi
""" % dict(particles=particles, cells=cells, bounds=bounds, drift=drift, seed=seed, compression=compression,
           extra_arrays=extra_arrays)
