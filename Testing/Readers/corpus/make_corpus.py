"""Writes the reader's fuzz corpus: a few hundred malformed and odd H5Part files, and
manifest.json saying what opening each must give.

Run by /usr/bin/python3 (h5py): python3 make_corpus.py <folder>. Expectations per file:
  expect  "data": read without error; points = the first step's particle count; arrays / field /
          strings: values that must be read exactly; warn: words that must appear in a warning.
          "error": a clean error whose text holds every word of `error`.
          "any": a clean error or data (bit flips and truncations of valid files).
Every case, whatever it expects, must end without a signal, a hang or an allocation beyond the
address-space cap the driver sets.
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
N = 64  # particles of the ordinary files


def case(name, expect, writer=None, **expectations):
    path = os.path.join(folder, name + ".h5part")
    if writer is not None:
        with h5py.File(path, "w") as f:
            writer(f)
    entry = {"file": os.path.basename(path), "expect": expect}
    entry.update(expectations)
    manifest.append(entry)
    return path


def coords(g, n=N, dtype="f4"):
    g["x"] = np.arange(n, dtype=dtype)
    g["y"] = np.arange(n, dtype=dtype) * 2
    g["z"] = np.arange(n, dtype=dtype) * 3


def step(f, k=0, n=N, time=None):
    g = f.create_group("Step#%d" % k)
    coords(g, n)
    if time is not None:
        g.attrs["time"] = time
    return g


# --- valid layouts: the reader must give exactly what the file holds -----------------------------
valid = []
valid.append(case("valid_xyz", "data", lambda f: step(f), points=N,
                  arrays={"id": [0, 1, 2, 3]}))
valid.append(case("valid_position", "data",
                  lambda f: f.create_group("Step#0").create_dataset(
                      "position", data=np.arange(3 * N, dtype="f8").reshape(N, 3)), points=N))


def velocity_file(f):
    g = step(f)
    g["vx"], g["vy"], g["vz"] = np.ones(N, "f4"), 2 * np.ones(N, "f4"), 3 * np.ones(N, "f4")
    g["density"] = np.full(N, 1000.0)
    g["id"] = np.arange(N, dtype="i8")[::-1]
    f.attrs["particle_spacing"] = 0.02
    f.attrs["code"] = np.bytes_("corpus")


valid.append(case("valid_velocity", "data", velocity_file, points=N,
                  arrays={"velocity": [1, 2, 3, 1, 2, 3], "density": [1000, 1000], "id": [N - 1, N - 2]},
                  field={"particle_spacing": [0.02]}, strings={"code": ["corpus"]}))


def three_steps(f):
    for k in range(3):
        step(f, k, n=N + k, time=0.5 * k)


valid.append(case("valid_steps", "data", three_steps, points=N, last_points=N + 2, steps=3))


def chunked_compressed(f):
    g = f.create_group("Step#0")
    for a in "xyz":
        g.create_dataset(a, data=np.linspace(0, 1, 1000, dtype="f4"), chunks=(100,), compression="gzip")


valid.append(case("valid_chunked", "data", chunked_compressed, points=1000))
case("valid_zero_particles", "data", lambda f: step(f, n=0), points=0)

# --- every HDF5 datatype class, as coordinates and as an extra array ------------------------------
numeric = {"i1": [-3, 5], "u1": [250, 3], "i2": [-30000, 7], "u2": [65000, 1], "i4": [-2000000000, 9],
           "u4": [4000000000, 3000000000], "i8": [-(2 ** 40), 11], "u8": [2 ** 62, 5], "f2": [0.5, -2.0],
           ">f4": [1.5, -2.25], ">f8": [1e300, -3.5], "<f8": [2.5, 1e-300], ">i4": [-7, 123456789]}
for code, values in numeric.items():
    label = code.replace(">", "be").replace("<", "le")

    def extra(f, code=code, values=values):
        g = step(f, n=2)
        g["extra"] = np.array(values, dtype=code)

    case("type_extra_" + label, "data", extra, points=2, arrays={"extra": values})

    def coordinate_type(f, code=code, values=values):
        g = f.create_group("Step#0")
        for a in "xyz":
            g[a] = np.array(values, dtype=code)

    case("type_coordinates_" + label, "data", coordinate_type, points=2)

others = {
    "bool": lambda: np.array([True, False]),
    "compound": lambda: np.zeros(2, dtype=[("a", "f4"), ("b", "i4")]),
    "fixed_string": lambda: np.array([b"ab", b"cd"], dtype="S2"),
    "vlen_string": lambda: np.array(["ab", "cde"], dtype=h5py.string_dtype()),
    "opaque": lambda: np.array([b"\x01\x02", b"\x03\x04"], dtype="V2"),
    "complex": lambda: np.array([1 + 2j, 3 - 1j]),
}
for label, make in others.items():
    def extra(f, make=make):
        g = step(f, n=2)
        g.create_dataset("extra", data=make())

    case("class_extra_" + label, "data", extra, points=2, warn=["extra"], absent=["extra"])

    def coordinate_class(f, make=make):
        g = f.create_group("Step#0")
        for a in "xyz":
            g.create_dataset(a, data=make())

    case("class_coordinates_" + label, "error", coordinate_class, error=["coordinates"])


def vlen_sequence(f):
    g = step(f, n=2)
    d = g.create_dataset("extra", (2,), dtype=h5py.vlen_dtype(np.int32))
    d[0] = [1, 2]
    d[1] = [3]


case("class_extra_vlen_sequence", "data", vlen_sequence, points=2, warn=["extra"])


def references(f):
    g = step(f, n=2)
    d = g.create_dataset("extra", (2,), dtype=h5py.ref_dtype)
    d[0] = g.ref
    d[1] = g["x"].ref


def array_type(f):
    g = step(f, n=2)
    g.create_dataset("extra", shape=(2,), dtype=np.dtype("(3,)f4"))


case("class_extra_array_type", "data", array_type, points=2, warn=["extra"])
case("class_extra_reference", "data", references, points=2, warn=["extra"])

# --- shapes --------------------------------------------------------------------------------------


def shape_case(name, make, expect="data", **e):
    def write(f):
        g = step(f, n=4)
        make(g)

    case("shape_" + name, expect, write, **e)


shape_case("extra_3d", lambda g: g.create_dataset("extra", data=np.zeros((4, 2, 2))), points=4, warn=["extra"])
shape_case("extra_scalar", lambda g: g.create_dataset("extra", data=3.0), points=4, warn=["extra"])
shape_case("extra_nx0", lambda g: g.create_dataset("extra", shape=(4, 0), dtype="f4"), points=4, warn=["extra"],
           absent=["extra"])
shape_case("extra_n_by_2e31", lambda g: g.create_dataset("extra", shape=(4, 2 ** 31), dtype="f4",
                                                         chunks=(1, 2 ** 20)), points=4, warn=["extra"])
shape_case("extra_wrong_length", lambda g: g.create_dataset("extra", data=np.zeros(3)), "error",
           error=["extra", "3 values for 4 particles"])
shape_case("extra_nx2", lambda g: g.create_dataset("extra", data=np.arange(8.0).reshape(4, 2)), points=4,
           arrays={"extra": [0, 1, 2, 3]})
shape_case("id_nx3", lambda g: g.create_dataset("id", data=np.ones((4, 3), "i8")), points=4, warn=["id"],
           arrays={"id": [0, 1, 2, 3]})
shape_case("id_float_nan", lambda g: g.create_dataset("id", data=np.array([0, 1, np.nan, 3])), points=4,
           warn=["id"], arrays={"id": [0, 1, 2, 3]})
shape_case("id_float_fraction", lambda g: g.create_dataset("id", data=np.array([0, 1.5, 2, 3])), points=4,
           warn=["id"], arrays={"id": [0, 1, 2, 3]})
shape_case("id_float_whole", lambda g: g.create_dataset("id", data=np.array([7.0, 8, 9, 10])), points=4,
           arrays={"id": [7, 8, 9, 10]})
shape_case("id_wrong_length", lambda g: g.create_dataset("id", data=np.arange(5)), points=4, warn=["id"],
           arrays={"id": [0, 1, 2, 3]})
shape_case("uint32_above_int_max", lambda g: g.create_dataset("count", data=np.array([2 ** 31 + 5, 2 ** 32 - 1, 0, 1],
                                                                                       dtype="u4")),
           points=4, arrays={"count": [2 ** 31 + 5, 2 ** 32 - 1, 0, 1]})


def mixed_velocity(g):
    g["vx"] = np.array([1, 2, 3, 4], dtype="i4")
    g["vy"] = np.array([0.25, 0.5, 0.75, 1.25])
    g["vz"] = np.array([-0.125, 1e-3, 2.5, 3.5])


shape_case("velocity_int_and_float", mixed_velocity, points=4,
           arrays={"velocity": [1, 0.25, -0.125, 2, 0.5, 1e-3]})


def x_2d(f):
    g = f.create_group("Step#0")
    g["x"] = np.zeros((4, 2))
    g["y"] = np.zeros(4)
    g["z"] = np.zeros(4)


case("shape_x_2d", "error", x_2d, error=["x, y, z", "1-D"])

# --- huge declared sizes, never written ----------------------------------------------------------
for power in (28, 32, 36, 40):
    def huge_chunked(f, power=power):
        g = f.create_group("Step#0")
        for a in "xyz":
            g.create_dataset(a, shape=(2 ** power,), dtype="f4", chunks=(2 ** 16,))

    case("huge_chunked_2e%d" % power, "error", huge_chunked, error=["chunks", "written"])

    def huge_extra(f, power=power):
        g = step(f, n=4)
        g.create_dataset("extra", shape=(2 ** power, 3), dtype="f8", chunks=(2 ** 14, 3))

    case("huge_extra_2e%d" % power, "error", huge_extra, error=["extra", "for 4 particles"])

    def huge_contiguous(f, power=power):
        g = f.create_group("Step#0")
        for a in "xyz":
            g.create_dataset(a, shape=(2 ** power,), dtype="f4")

    case("huge_contiguous_2e%d" % power, "error", huge_contiguous, error=["never written"])


def partly_written(f):
    g = f.create_group("Step#0")
    for a in "xyz":
        d = g.create_dataset(a, shape=(4096,), dtype="f4", chunks=(1024,))
        d[:1024] = 1.0


case("huge_partly_written", "error", partly_written, error=["1 of its 4 chunks"])

# --- attributes of every shape and type ----------------------------------------------------------


def attribute_case(name, set_attrs, **e):
    def write(f):
        step(f, n=4)
        set_attrs(f.attrs)

    case("attr_" + name, "data", write, points=4, **e)


for count, width in ((5, 10), (7, 12), (600, 100), (1, 1), (3, 1)):
    words = [("s%d" % k).ljust(width - 1, "z")[: width] for k in range(count)]
    attribute_case("fixed_strings_%dx%d" % (count, width),
                   lambda a, words=words, width=width: a.create("label", np.array(words, dtype="S%d" % width)),
                   strings={"label": words[:3]})
attribute_case("fixed_strings_2d", lambda a: a.create("label", np.array([[b"ab", b"cd"], [b"ef", b"gh"]], dtype="S2")),
               strings={"label": ["ab", "cd", "ef"]})
attribute_case("vlen_strings", lambda a: a.create("label", ["one", "two", "three"], dtype=h5py.string_dtype()),
               strings={"label": ["one", "two", "three"]})
attribute_case("vlen_string_scalar", lambda a: a.__setitem__("label", "hello"), strings={"label": ["hello"]})
attribute_case("numeric_array", lambda a: a.__setitem__("gravity", np.array([0.0, 0.0, -9.81])),
               field={"gravity": [0.0, 0.0, -9.81]})
attribute_case("numeric_2d", lambda a: a.__setitem__("matrix", np.arange(6.0).reshape(2, 3)),
               field={"matrix": [0, 1, 2, 3, 4, 5]})
attribute_case("int8_scalar", lambda a: a.__setitem__("flag", np.int8(-4)), field={"flag": [-4]})
attribute_case("empty", lambda a: a.__setitem__("nothing", h5py.Empty("f")), warn=["nothing"])
attribute_case("compound", lambda a: a.__setitem__("pair", np.zeros(1, dtype=[("a", "f4"), ("b", "i4")])),
               warn=["pair"])
attribute_case("nan_inf", lambda a: a.__setitem__("values", np.array([np.nan, np.inf, -np.inf])),
               field={"values": ["nan", "inf", "-inf"]})
attribute_case("many_attributes", lambda a: [a.__setitem__("a%03d" % k, float(k)) for k in range(300)],
               field={"a299": [299.0]})


def big_attribute_file(path):
    fapl_file = h5py.File(path, "w", libver=("v108", "latest"))
    step(fapl_file, n=4)
    fapl_file.attrs["big"] = np.arange(50000.0)
    fapl_file.attrs["too_big"] = np.zeros(2 ** 20 + 1, dtype="i1")
    fapl_file.close()


big_attribute_file(case("attr_dense_large", "data", None, points=4, field={"big": [0, 1, 2]}, warn=["too_big"]))

# --- NaN and infinity ----------------------------------------------------------------------------


def nan_coordinates(f):
    g = step(f, n=4)
    del g["x"]
    g["x"] = np.array([0.0, np.nan, np.inf, 1.0], dtype="f4")


case("nan_coordinates", "data", nan_coordinates, points=4, warn=["NaN"])
for label, times in {"nan": [0.0, float("nan"), 2.0], "inf_last": [0.0, 1.0, float("inf")],
                     "minus_inf_first": [float("-inf"), 1.0, 2.0], "decreasing": [2.0, 1.0, 0.0],
                     "equal": [1.0, 1.0, 1.0]}.items():
    def timed(f, times=times):
        for k, t in enumerate(times):
            step(f, k, n=N + k, time=t)

    case("time_" + label, "data", timed, points=N, last_points=N + 2, steps=3, warn=["time"])

# --- steps ---------------------------------------------------------------------------------------
case("steps_none", "error", lambda f: f.create_dataset("data", data=np.ones(3)), error=["no H5Part step groups"])
case("steps_dataset_named_step", "error", lambda f: f.create_dataset("Step#0", data=np.ones(3)),
     error=["no H5Part step groups"])
case("steps_bad_names", "data", lambda f: (step(f, 1), f.create_group("Step#x"), f.create_group("Step#")),
     points=N)
case("steps_empty_group", "error", lambda f: f.create_group("Step#0"), error=["empty step"])


def many_steps(f):
    for k in range(200):
        step(f, k, n=2)


case("steps_many", "data", many_steps, points=2, last_points=2, steps=200)

# --- links and virtual datasets ------------------------------------------------------------------


def soft_link(f):
    g = f.create_group("Step#0")
    f.create_group("store")
    coords(f["store"])
    for a in "xyz":
        g[a] = h5py.SoftLink("/store/" + a)


case("link_soft", "data", soft_link, points=N)


def dangling(f):
    g = step(f, n=4)
    g["extra"] = h5py.SoftLink("/nowhere")


case("link_dangling_extra", "data", dangling, points=4, warn=["extra"])


def dangling_coordinates(f):
    g = f.create_group("Step#0")
    for a in "xyz":
        g[a] = h5py.SoftLink("/nowhere/" + a)


case("link_dangling_coordinates", "error", dangling_coordinates, error=["coordinates"])


def external_missing(f):
    g = f.create_group("Step#0")
    for a in "xyz":
        g[a] = h5py.ExternalLink("missing-source.h5", "/" + a)


case("link_external_missing", "error", external_missing, error=["Step#0/x", "link to nothing"])

source = os.path.join(folder, "vds_source.h5")
with h5py.File(source, "w") as f:
    coords(f)


def vds(f, source_name):
    g = f.create_group("Step#0")
    for a in "xyz":
        layout = h5py.VirtualLayout(shape=(N,), dtype="f4")
        layout[:] = h5py.VirtualSource(source_name, a, shape=(N,))
        g.create_virtual_dataset(a, layout)


case("vds_valid", "data", lambda f: vds(f, "vds_source.h5"), points=N)
case("vds_missing_source", "error", lambda f: vds(f, "vds-missing.h5"), error=["vds-missing.h5", "missing"])


def vds_partial(f):
    g = f.create_group("Step#0")
    for a in "xyz":
        layout = h5py.VirtualLayout(shape=(2 * N,), dtype="f4")
        layout[:N] = h5py.VirtualSource("vds_source.h5", a, shape=(N,))
        g.create_virtual_dataset(a, layout)


case("vds_partial", "error", vds_partial, error=["map to a source"])

# --- steps that are not what their names say (issue 65: metadata damage showed step 1 as step 0) -
def group_linked_twice(f):
    step(f, 0, time=0.0)
    f["Step#1"] = f["Step#0"]  # a second name for the same group
    step(f, 2, time=2.0)


def dataset_linked_twice(f):
    step(f, 0, time=0.0)
    g = f.create_group("Step#1")
    g.attrs["time"] = 1.0
    g["x"] = f["Step#0/x"]
    g["y"] = np.arange(N, dtype="f4")
    g["z"] = np.arange(N, dtype="f4")


def numbered_twice(f):
    step(f, 0, time=0.0)
    step(f, 1, time=1.0)
    g = f.create_group("Step#01")
    coords(g, 5)
    g.attrs["time"] = 1.5


case("steps_one_group_twice", "data", group_linked_twice, points=N, steps=3,
     warn=["Step#1 is the same group in the file as Step#0"])
case("steps_one_dataset_twice", "data", dataset_linked_twice, points=N, steps=2,
     warn=["Step#1/x is the same dataset in the file as Step#0/x"])
case("steps_numbered_twice", "data", numbered_twice, points=N, steps=2, last_points=N,
     warn=["Step#01 and Step#1 both number step 1; Step#01 is left out"])

# --- truncations and bit flips of valid files ----------------------------------------------------
rng = random.Random(20261124)
for base in valid:
    data = open(base, "rb").read()
    stem = os.path.basename(base)[:-7]
    for fraction in (0.05, 0.3, 0.6, 0.9, 0.99):
        name = "truncated_%s_%02d" % (stem, int(fraction * 100))
        with open(os.path.join(folder, name + ".h5part"), "wb") as out:
            out.write(data[: int(len(data) * fraction)])
        case(name, "any")
    for k in range(14):
        flipped = bytearray(data)
        for _ in range(rng.choice((1, 1, 2, 8))):
            position = rng.randrange(len(flipped))
            flipped[position] ^= 1 << rng.randrange(8)
        name = "bitflip_%s_%02d" % (stem, k)
        with open(os.path.join(folder, name + ".h5part"), "wb") as out:
            out.write(bytes(flipped))
        case(name, "any")

# --- not HDF5 at all -----------------------------------------------------------------------------
with open(os.path.join(folder, "text.h5part"), "w") as out:
    out.write("not hdf5\n")
case("text", "error", error=["not an HDF5 file"])
open(os.path.join(folder, "zero_bytes.h5part"), "wb").close()
case("zero_bytes", "error", error=["not an HDF5 file"])
os.makedirs(os.path.join(folder, "folder.h5part"), exist_ok=True)
case("folder", "error", error=["not a regular file"])
fifo = os.path.join(folder, "pipe.h5part")
if not os.path.exists(fifo):
    os.mkfifo(fifo)
case("pipe", "error", error=["not a regular file"])
case("missing", "error", error=["missing or unreadable"])

with open(os.path.join(folder, "manifest.json"), "w") as out:
    json.dump(manifest, out, indent=1)
print("corpus: %d cases in %s" % (len(manifest), folder))
