"""Writes the fuzz corpus of the H5MD and Gadget-style layouts beside the H5Part one: valid files,
malformed ones (wrong shapes and types, missing or mistyped attributes, counts that disagree,
a snapshot whose files disagree) and truncations and bit flips of the valid ones, with
layouts.json saying what opening each with ParaFluid HDF5 Particles must give (the expectations
of make_corpus.py: "data" with the total particle count, "error" with words, "any").

Run by /usr/bin/python3 (h5py): python3 make_layout_corpus.py <folder>.
"""
import json
import os
import random
import sys

import h5py
import numpy as np

folder = sys.argv[1]
os.makedirs(folder, exist_ok=True)
manifest = []
N = 32


def case(name, extension, expect, writer=None, **expectations):
    path = os.path.join(folder, name + extension)
    if writer is not None:
        with h5py.File(path, "w") as f:
            writer(f)
    entry = {"file": os.path.basename(path), "expect": expect, "reader": "particles"}
    entry.update(expectations)
    manifest.append(entry)
    return path


def h5md(f, frames=3, n=N, position=None, time=None):
    f.create_group("h5md").attrs["version"] = np.array([1, 1])
    g = f.create_group("particles/all")
    p = g.create_group("position")
    p["value"] = position if position is not None else np.random.default_rng(1).random((frames, n, 3))
    p["time"] = time if time is not None else np.arange(frames, dtype="f8")
    p["step"] = np.arange(frames)
    return g


def swift(f, n=N, coordinates=None, count=None, files=1, total=None):
    h = f.create_group("Header")
    h.attrs["NumPart_ThisFile"] = np.array([n if count is None else count, 0, 0, 0, 0, 0], dtype="u4")
    h.attrs["NumPart_Total"] = np.array([n if total is None else total, 0, 0, 0, 0, 0], dtype="u4")
    h.attrs["NumPart_Total_HighWord"] = np.zeros(6, dtype="u4")
    h.attrs["MassTable"] = np.zeros(6)
    h.attrs["Time"] = 0.5
    h.attrs["BoxSize"] = 10.0
    h.attrs["NumFilesPerSnapshot"] = files
    f.create_group("Units").attrs["Unit length in cgs (U_L)"] = 3.0857e24
    g = f.create_group("PartType0")
    c = g.create_dataset("Coordinates", data=np.arange(3 * n, dtype="f8").reshape(n, 3) if coordinates is None else coordinates)
    c.attrs["Conversion factor to CGS (not including cosmological corrections)"] = 3.0857e24
    c.attrs["U_L exponent"] = 1.0
    g["Velocities"] = np.ones((n, 3), "f4")
    g["ParticleIDs"] = np.arange(n, dtype="u8")
    g["Masses"] = np.ones(n, "f4")
    return g


def openpmd(f, encoding="groupBased", fmt="/data/%T/", n=N, units=(1e-6, 1e-6, 1e-6), axes="xyz"):
    f.attrs["openPMD"] = np.string_("1.1.0")
    f.attrs["basePath"] = np.string_("/data/%T/")
    f.attrs["particlesPath"] = np.string_("particles/")
    f.attrs["iterationEncoding"] = np.string_(encoding)
    f.attrs["iterationFormat"] = np.string_(fmt)
    g = f.create_group("data/10")
    g.attrs["time"] = 1.0
    g.attrs["timeUnitSI"] = 1e-15
    pos = g.create_group("particles/e/position")
    pos.attrs["unitDimension"] = np.array([1.0, 0, 0, 0, 0, 0, 0])
    for axis, unit in zip(axes, units):
        pos[axis] = np.arange(n, dtype="f4")
        pos[axis].attrs["unitSI"] = unit
    g["particles/e/weighting"] = np.ones(n)


def vtkhdf(f, kind="PolyData", points=N, rows=N, steps=False):
    root = f.create_group("VTKHDF")
    root.attrs["Version"] = np.array([2, 0])
    root.attrs.create("Type", np.string_(kind), dtype=h5py.string_dtype("ascii", len(kind)))
    root["NumberOfPoints"] = np.array([points])
    root["Points"] = np.zeros((rows, 3), "f4")
    root["PointData/speed"] = np.ones(rows)
    if steps:
        s = root.create_group("Steps")
        s["Values"] = np.array([0.0])


valid = []
valid.append(case("h5md_valid", ".h5md", "data", lambda f: h5md(f).__setitem__("velocity", np.ones((N, 3))), points=N))
valid.append(case("swift_valid", ".hdf5", "data", swift, points=N))
valid.append(case("openpmd_valid", ".h5", "data", openpmd, points=N))
valid.append(case("vtkhdf_valid", ".hdf5", "data", vtkhdf, points=N))

# openPMD
case("openpmd_no_iterations", ".h5", "error",
     lambda f: f.attrs.__setitem__("openPMD", np.string_("1.1.0")) or f.attrs.__setitem__("basePath", np.string_("/data/%T/")),
     error=["no iterations"])
case("openpmd_no_components", ".h5", "error", lambda f: openpmd(f, axes=""), error=["no x, y or z"])
case("openpmd_mixed_units", ".h5", "error", lambda f: openpmd(f, units=(1e-6, 1.0, 1e-6)), error=["different unitSI"])
case("openpmd_filebased_no_pattern", ".h5", "error", lambda f: openpmd(f, encoding="fileBased", fmt="data.h5"),
     error=["%T"])
case("openpmd_unit_text", ".h5", "error",
     lambda f: openpmd(f) or f["data/10/particles/e/position/x"].attrs.__setitem__("unitSI", "micron"),
     error=["position/x", "unitSI", "not a number"])

# VTKHDF
case("vtkhdf_unstructured", ".hdf5", "error", lambda f: vtkhdf(f, kind="UnstructuredGrid"), error=["not PolyData"])
case("vtkhdf_points_short", ".hdf5", "error", lambda f: vtkhdf(f, points=N + 9), error=["/VTKHDF/Points"])
case("vtkhdf_steps_without_offsets", ".hdf5", "error", lambda f: vtkhdf(f, steps=True), error=["PartOffsets"])

# H5MD
case("h5md_position_2d", ".h5md", "error", lambda f: h5md(f, position=np.zeros((2, N, 2))), error=["N x 3"])
case("h5md_position_strings", ".h5md", "error",
     lambda f: h5md(f, position=np.array([[[b"a"] * 3] * 4] * 2)), error=["position/value", "strings"])
case("h5md_no_position", ".h5md", "error",
     lambda f: f.create_group("h5md").attrs.__setitem__("version", np.array([1, 1])) or f.create_group("particles/all"),
     error=["no /particles/<group>/position"])
case("h5md_nan_time", ".h5md", "error", lambda f: h5md(f, time=np.array([0.0, np.nan, 2.0])), error=["NaN"])
case("h5md_version_text", ".h5md", "data",
     lambda f: h5md(f) and f["h5md"].attrs.__setitem__("version", "one point one"), points=N)


def unwritten_position(f):
    f.create_group("h5md").attrs["version"] = np.array([1, 1])
    p = f.create_group("particles/all/position")
    p.create_dataset("value", shape=(2, N, 3), dtype="f8")  # declared, never written
    p["time"] = np.array([0.0, 1.0])


case("h5md_unwritten_position", ".h5md", "error", unwritten_position, error=["position/value"])


def velocity_rows(f):
    h5md(f)["velocity"] = np.ones((N + 5, 3))


case("h5md_velocity_rows", ".h5md", "data", velocity_rows, points=N, warn=["velocity", "rows"])


def many_frames(f):
    f.create_group("h5md").attrs["version"] = np.array([1, 1])
    p = f.create_group("particles/all/position")
    p.create_dataset("value", shape=(1 << 40, N, 3), dtype="f4", chunks=(1, N, 3))
    p["time"] = 1.0


case("h5md_frames_2e40", ".h5md", "error", many_frames, error=["position/value", "written"])

# Gadget-style
case("gadget_no_numpart", ".hdf5", "error", lambda f: swift(f) and f["Header"].attrs.__delitem__("NumPart_ThisFile"),
     error=["NumPart_ThisFile"])
case("gadget_numpart_negative", ".hdf5", "error",
     lambda f: swift(f) and f["Header"].attrs.__setitem__("NumPart_ThisFile", np.array([-3, 0, 0, 0, 0, 0])),
     error=["NumPart_ThisFile"])
case("gadget_count_mismatch", ".hdf5", "error", lambda f: swift(f, count=N + 2), error=["holds %d particles" % N])
case("gadget_total_mismatch", ".hdf5", "error", lambda f: swift(f, total=N * 2), error=["NumPart_Total says %d" % (2 * N)])
case("gadget_missing_type", ".hdf5", "error",
     lambda f: swift(f) and f["Header"].attrs.__setitem__("NumPart_ThisFile", np.array([N, 5, 0, 0, 0, 0], "u4")),
     error=["/PartType1"])
case("gadget_coordinates_2col", ".hdf5", "error", lambda f: swift(f, coordinates=np.zeros((N, 2))), error=["Coordinates"])


def unit_text(f):
    swift(f)["Coordinates"].attrs["Conversion factor to CGS (not including cosmological corrections)"] = "a lot"


case("gadget_unit_text", ".hdf5", "data", unit_text, points=N, warn=["/PartType0/Coordinates", "not a number"])
case("gadget_files_1e9", ".hdf5", "error", lambda f: swift(f, files=10 ** 9), error=["NumFilesPerSnapshot"])
case("gadget_split.0", ".hdf5", "error", lambda f: swift(f, files=2), error=["gadget_split.1.hdf5", "missing"])
case("gadget_pair.0", ".hdf5", "error", lambda f: swift(f, files=2, total=2 * N), error=["NumPart_Total differs"])
with h5py.File(os.path.join(folder, "gadget_pair.1.hdf5"), "w") as f:
    swift(f, files=2, total=3 * N)

# truncations and bit flips of the valid files
rng = random.Random(20261202)
for base in valid:
    data = open(base, "rb").read()
    stem, extension = os.path.splitext(os.path.basename(base))
    for fraction in (0.05, 0.3, 0.6, 0.9):
        name = "truncated_%s_%02d" % (stem, int(fraction * 100))
        with open(os.path.join(folder, name + extension), "wb") as out:
            out.write(data[: int(len(data) * fraction)])
        case(name, extension, "any")
    for k in range(10):
        flipped = bytearray(data)
        for _ in range(rng.choice((1, 2, 8))):
            position = rng.randrange(len(flipped))
            flipped[position] ^= 1 << rng.randrange(8)
        name = "bitflip_%s_%02d" % (stem, k)
        with open(os.path.join(folder, name + extension), "wb") as out:
            out.write(bytes(flipped))
        case(name, extension, "any")

with open(os.path.join(folder, "layouts.json"), "w") as out:
    json.dump(manifest, out, indent=1)
print("layout corpus: %d cases in %s" % (len(manifest), folder))
