"""Every numeric property of every ParaFluid source and filter, at NaN, +Inf, -Inf, 0, -1 and 1e30:
a clean error that names the property, or a documented meaning, never a crash, a hang, NaN output
or silent acceptance.

The documented meaning is the property's domain in the plugin XML (what the GUI allows and its
tooltip states): a value inside the domain must run and give finite output, or be refused by name
(the memory budget, a run too long to finish); a value outside it must be refused by name. The
few properties whose meaning is not a plain range (bounds, vectors, 0 = automatic) are in SPECIAL.
"""
import builtins
import math
import os
import sys

import numpy as np
from paraview.simple import *
from paraview import servermanager
from vtkmodules.util.numpy_support import vtk_to_numpy
import pftest

pftest.load(globals())
BAD = [float("nan"), float("inf"), float("-inf"), 0.0, -1.0, 1e30]

block = ParticleBlock(BlockBounds=[0, 0.1, 0, 0.1, 0, 0.1], Spacing=0.025, DomainBounds=[0, 0.2, 0, 0.2, 0, 0.2])
terrain = Plane(Origin=[-1, -1, -0.5], Point1=[1, -1, -0.5], Point2=[-1, 1, -0.5])
small_terrain = ProceduralTerrain(Resolution=[17, 17], Extent=[100, 100])
rain_terrain = ProceduralTerrain(Resolution=[9, 9], Extent=[2, 2], HeightScale=0.2)
MAKERS = {
    "ParticleBlock": lambda: ParticleBlock(BlockBounds=[0, 0.1, 0, 0.1, 0, 0.1], Spacing=0.025,
                                           DomainBounds=[0, 0.2, 0, 0.2, 0, 0.2]),
    "SPHStep": lambda: SPHStep(Input=block, OutputInterval=0.002, NumberOfOutputs=1),
    "ParticleSurfaceMarchingCubes": lambda: ParticleSurfaceMarchingCubes(Input=block),
    "CarpetSurface": lambda: CarpetSurface(Input=block, Resolution=16),
    "FluidFlowLines": lambda: FluidFlowLines(Input=block),
    "FoamParticles": lambda: FoamParticles(Input=block),
    "GerstnerOcean": lambda: GerstnerOcean(Resolution=[16, 16], BathymetryResolution=16),
    "ProceduralTerrain": lambda: ProceduralTerrain(Resolution=[17, 17]),
    "TerrainFromImage": lambda: TerrainFromImage(Input=small_terrain),
    "HydraulicErosion": lambda: HydraulicErosion(Input=small_terrain, Drops=200, Iterations=20),
    "Rain": lambda: Rain(Terrain=rain_terrain, DropsPerRealDrop=1e-3, Cells=[4, 4], PrecipitationHeight=3.0,
                         RainfallRate=500, ParticleSpacing=0.2, OutputInterval=0.05, NumberOfOutputs=2),
    "StableFluids": lambda: StableFluids(Resolution=[8, 8, 8], TimeStep=0.05, OutputInterval=0.05, NumberOfOutputs=1),
}
# (proxy, property) -> function(values) -> True when the values are valid (must run), False when
# they must be refused. Properties not listed follow their XML domain.
def bounds_valid(b):
    return all(math.isfinite(v) for v in b) and all(b[2 * a] <= b[2 * a + 1] for a in range(3))


SPECIAL = {
    ("StableFluids", "Bounds"): lambda b: bounds_valid(b) and all(b[2 * a] < b[2 * a + 1] for a in range(3)) and all(
        abs(v) <= 1e12 for v in b),
    ("StableFluids", "EmitterBox"): lambda b: all(math.isfinite(v) for v in b),  # an empty box emits nothing
    # a step far below the interval is a run too long to finish: refused by name
    ("StableFluids", "TimeStep"): lambda v: math.isfinite(v[0]) and 1e-6 <= v[0] <= 10 and 0.05 / v[0] <= 1e6,
    ("ParticleBlock", "BlockBounds"): bounds_valid,  # an empty box gives no particles
    ("ParticleBlock", "DomainBounds"): lambda b: bounds_valid(b) and all(b[2 * a] < b[2 * a + 1] for a in range(3)),
    # all zero: taken from the input's domain_bounds field data
    ("SPHStep", "DomainBounds"): lambda b: all(v == 0 for v in b) or (
        bounds_valid(b) and all(b[2 * a] < b[2 * a + 1] for a in range(3))),
    ("SPHStep", "Gravity"): lambda g: all(math.isfinite(v) and abs(v) < 1e6 for v in g),
    # terrain: an origin anywhere a float can place it; NoDataValue any number (NaN is no-data anyway)
    ("ProceduralTerrain", "Origin"): lambda o: all(math.isfinite(v) and abs(v) <= 1e9 for v in o),
    ("TerrainFromImage", "NoDataValue"): lambda v: True,
    ("GerstnerOcean", "Origin"): lambda o: all(math.isfinite(v) and abs(v) < 1e12 for v in o),
    ("GerstnerOcean", "SeaLevel"): lambda v: math.isfinite(v[0]) and abs(v[0]) < 1e12,
    ("GerstnerOcean", "WindDirection"): lambda v: math.isfinite(v[0]) and abs(v[0]) < 1e12,
    # amplitude, wavelength, direction, steepness, phase per wave
    ("GerstnerOcean", "Waves"): lambda w: all(math.isfinite(v) for v in w) and w[1] > 0 and w[0] >= 0 and abs(w[2]) < 1e12 and abs(w[4]) < 1e12 and 0 <= w[3] <= 1,
    # all zero: the terrain's extent; else x1 > x0 and y1 > y0, finite
    ("Rain", "PrecipitationBounds"): lambda b: all(v == 0 for v in b) or (
        all(math.isfinite(v) and abs(v) <= 1e7 for v in b) and b[1] > b[0] and b[3] > b[2]),
    # 0: automatic; else above the ground (the test terrain is below 0.2 m)
    ("Rain", "PrecipitationHeight"): lambda v: math.isfinite(v[0]) and (v[0] == 0 or 0.2 < v[0] <= 1e7),
}
SKIP = {"TimestepValues"}


def domain_valid(prop, values):
    """The XML domain's verdict on `values`; None when the property has no domain."""
    sm = prop.SMProperty
    for name in ("range", "bool", "enum"):
        domain = sm.GetDomain(name)
        if domain is None:
            continue
        if domain.IsA("vtkSMBooleanDomain"):
            return all(v in (0, 1) for v in values)
        if domain.IsA("vtkSMEnumerationDomain"):
            allowed = {domain.GetEntryValue(k) for k in range(domain.GetNumberOfEntries())}
            return all(v in allowed for v in values)
        ok = True
        for k, v in enumerate(values):
            if not math.isfinite(v):
                return False
            e = min(k, domain.GetNumberOfEntries() - 1) if hasattr(domain, "GetNumberOfEntries") else 0
            if domain.GetMinimumExists(e) and v < domain.GetMinimum(e):
                ok = False
            if domain.GetMaximumExists(e) and v > domain.GetMaximum(e):
                ok = False
        return ok
    return None


def output_finite(data):
    if data is None:
        return True
    pts = data.GetPoints() if hasattr(data, "GetPoints") else None
    if pts is not None and pts.GetNumberOfPoints() and not np.all(np.isfinite(pftest.points(data))):
        return False
    pd = data.GetPointData()
    for i in range(pd.GetNumberOfArrays()):
        a = pd.GetArray(i)
        if a is not None and a.GetDataType() in (10, 11) and a.GetNumberOfTuples():
            if not np.all(np.isfinite(pftest.point_array(data, pd.GetArrayName(i)))):
                return False
    return True


failures = []
cases = 0
for xml_name, make in MAKERS.items():
    probe = make()
    names = [n for n in probe.ListProperties()]
    for label in names:
        prop = probe.GetProperty(label)
        sm = prop.SMProperty
        if label in SKIP or not (sm.IsA("vtkSMDoubleVectorProperty") or sm.IsA("vtkSMIntVectorProperty")):
            continue
        if sm.GetInformationOnly() or sm.GetNumberOfElements() == 0:
            continue
        property_name = sm.GetXMLName()
        default = list(prop) if sm.GetNumberOfElements() > 1 else [prop.GetData()]
        for bad in BAD:
            # One element set to the bad value (the max of a pair or a box, the only one else).
            index = 1 if len(default) in (2, 6) else 0
            values = list(default)
            values[index] = bad
            cases += 1
            proxy = make()
            messages = pftest.Messages(proxy.GetClientSideObject())
            try:
                proxy.SetPropertyWithName(label, values if len(values) > 1 else values[0])
            except Exception as exc:  # ParaView refuses it before the filter sees it (NaN to an int)
                Delete(proxy)
                continue
            special = SPECIAL.get((xml_name, property_name))
            valid = special(values) if special else domain_valid(prop, values)
            if valid is None:
                valid = all(math.isfinite(v) for v in values)
            try:
                times = proxy.TimestepValues
                t = times[-1] if times else None
            except AttributeError:
                t = None
            where = "%s.%s = %r" % (xml_name, property_name, values if len(values) > 1 else values[0])
            print("case " + where, flush=True)  # the last one printed names a crash
            data = pftest.fetch(proxy, t)
            error = " ".join(messages.errors)
            if error:
                if property_name not in error:
                    failures.append("%s: the error does not name the property: %r" % (where, error[-300:]))
            elif not valid:
                failures.append("%s: accepted silently (outside its documented domain)" % where)
            elif not output_finite(data):
                failures.append("%s: NaN or infinite output" % where)
            Delete(proxy)
            sys.stdout.flush()
    Delete(probe)

# Enumerations: a value that is none of the choices (-1, 99) is refused by name, the setting kept,
# and the filter runs on with it.
ENUMERATIONS = [("SPHStep", "WallFriction"), ("SPHStep", "SurfaceTensionModel"), ("SPHStep", "PressureSolver"),
                ("Rain", "WallFriction"), ("Rain", "PressureSolver"), ("ProceduralTerrain", "Method"),
                ("ProceduralTerrain", "FractalType"), ("HydraulicErosion", "Method"), ("StableFluids", "Preconditioner")]
for xml_name, name in ENUMERATIONS:
    for bad in (-1, 99):
        cases += 1
        proxy = MAKERS[xml_name]()
        messages = pftest.Messages(proxy.GetClientSideObject())
        proxy.SetPropertyWithName(name, bad)
        proxy.UpdateVTKObjects()
        where = "%s.%s = %d" % (xml_name, name, bad)
        refused = [e for e in messages.errors if name in e]
        if not refused:
            failures.append("%s: taken with no error naming it (errors %r)" % (where, messages.errors))
        del messages.errors[:]
        try:
            times = proxy.TimestepValues
            t = times[-1] if times else None
        except AttributeError:
            t = None
        data = pftest.fetch(proxy, t)
        if messages.errors or not output_finite(data):
            failures.append("%s: the filter did not run on with its kept setting: %r" % (where, messages.errors))
        Delete(proxy)

# Times: every time-aware source and filter gives its last output for +inf and 1e30, its first
# for -inf and -1e30, and refuses NaN with an error naming it.
steps_file = os.path.join(pftest.scratch_dir(), "times.h5part")
pftest.write_h5(steps_file, """
for k in range(3):
    g = f.create_group('Step#%d' % k)
    g.attrs['time'] = 0.5 * k
    g['x'] = np.arange(4, dtype='f4') + k
    g['y'] = np.zeros(4, dtype='f4')
    g['z'] = np.zeros(4, dtype='f4')
""")
TIME_AWARE = dict(MAKERS, ParaFluidHDF5Particles=lambda: ParaFluidHDF5Particles(FileName=steps_file))
for xml_name in ("ParaFluidHDF5Particles", "SPHStep", "GerstnerOcean", "Rain", "StableFluids"):
    proxy = TIME_AWARE[xml_name]()
    proxy.UpdatePipelineInformation()
    times = list(proxy.TimestepValues)
    messages = pftest.Messages(proxy.GetClientSideObject())

    def points_at(t):
        data = pftest.fetch(proxy, t)
        data = data if data.IsA("vtkDataSet") else data.GetBlock(0)
        if not data.GetNumberOfPoints():
            return np.zeros((0, 3))
        # Points of a point set, the first point array of an image (a grid's points never move).
        values = data.GetPoints().GetData() if data.IsA("vtkPointSet") else data.GetPointData().GetArray(0)
        return vtk_to_numpy(values).copy()

    first, last = points_at(times[0]), points_at(times[-1])
    for t, expected, label in ((float("inf"), last, "last"), (1e30, last, "last"), (float("-inf"), first, "first"),
                               (-1e30, first, "first")):
        cases += 1
        got = points_at(t)
        if messages.errors or got.shape != expected.shape or not np.array_equal(got, expected):
            failures.append("%s at t = %g: not its %s output (errors %r)" % (xml_name, t, label, messages.errors))
        del messages.errors[:]
    cases += 1
    proxy.UpdatePipeline(float("nan"))
    if not any("not a number" in e or "NaN" in e for e in messages.errors):
        failures.append("%s at t = NaN: no error saying so (errors %r)" % (xml_name, messages.errors))
    Delete(proxy)

for failure in failures:
    print(failure)
pftest.check(not failures, "%d of %d parameter cases failed" % (len(failures), cases))
print("parameter table: %d cases clean" % cases)
