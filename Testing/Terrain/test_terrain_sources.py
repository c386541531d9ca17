"""Procedural Terrain, Terrain From Image and Hydraulic Erosion through ParaView: outputs and
arrays, determinism by seed, DEM-style cell data with no-data, a 16-bit PNG heightmap, the
sediment budget of both erosion methods, and errors that name the property."""
import os

import numpy as np
from paraview.simple import *
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter, vtkTIFFWriter
from vtkmodules.util.numpy_support import numpy_to_vtk
import pftest

pftest.load(globals())
check = pftest.check
out = pftest.scratch_dir()


def fetch_port(proxy, port):
    proxy.UpdatePipeline()
    return servermanager.Fetch(proxy, idx=port)


# --- Procedural Terrain: both outputs, heights within base +- scale, surface arrays ---
terrain = ProceduralTerrain(Extent=[2000, 1000], Resolution=[129, 65], HeightScale=200, BaseHeight=50, Seed=3,
                            ComputeSlope=1, ComputeCurvature=1)
image = fetch_port(terrain, 0)
surface = fetch_port(terrain, 1)
check(image.GetDimensions() == (129, 65, 1), "image dimensions %s" % (image.GetDimensions(),))
check(abs(image.GetSpacing()[0] - 2000 / 128) < 1e-9, "spacing %s" % (image.GetSpacing(),))
h = pftest.point_array(image, "elevation")
check(h.min() >= -150 and h.max() <= 250 and h.max() - h.min() > 50, "elevation range %g..%g" % (h.min(), h.max()))
check(image.GetPointData().GetScalars().GetName() == "elevation", "elevation is the active scalar")
for name in ("slope", "curvature"):
    pftest.point_array(image, name)
check(surface.GetNumberOfPoints() == 129 * 65 and surface.GetNumberOfCells() == 2 * 128 * 64,
      "surface: %d points, %d cells" % (surface.GetNumberOfPoints(), surface.GetNumberOfCells()))
z = pftest.points(surface)[:, 2]
check(np.allclose(z, h), "surface z is the elevation")
normals = pftest.point_array(surface, "Normals")
check(np.all(normals[:, 2] > 0) and np.allclose(np.linalg.norm(normals, axis=1), 1, atol=1e-5), "upward unit normals")
check(np.allclose(pftest.point_array(surface, "slope"), pftest.point_array(image, "slope")), "surface carries slope")

# Same seed, same terrain; another seed, another terrain; other methods run.
again = pftest.point_array(fetch_port(ProceduralTerrain(Extent=[2000, 1000], Resolution=[129, 65], HeightScale=200,
                                                        BaseHeight=50, Seed=3), 0), "elevation")
check(np.array_equal(again, h), "same seed gives the same terrain")
terrain.Seed = 4
check(not np.allclose(pftest.point_array(fetch_port(terrain, 0), "elevation"), h), "another seed, another terrain")
for settings in (dict(Method="Diamond-Square", Roughness=0.6), dict(FractalType="Ridged"),
                 dict(FractalType="Turbulence", WarpStrength=300)):
    other = ProceduralTerrain(Resolution=[65, 65], **settings)
    values = pftest.point_array(fetch_port(other, 0), "elevation")
    check(np.all(np.isfinite(values)) and values.std() > 1.0, "%s: a terrain" % settings)

# --- Terrain From Image: a DEM as cell data with NaN and -9999 holes ---
dem = ProgrammableSource(OutputDataSetType="vtkImageData")
dem.Script = """
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
out = self.GetImageDataOutput()
out.SetDimensions(41, 31, 1)          # 40 x 30 cells
out.SetOrigin(500000.0, 4000000.0, 0.0)
out.SetSpacing(30.0, 30.0, 1.0)
i, j = np.meshgrid(np.arange(40), np.arange(30))
v = (100.0 + 2.0 * i + 1.0 * j).astype(np.float32)
v[10:14, 10:14] = -9999.0
v[20, 5] = np.nan
a = numpy_to_vtk(v.ravel(), deep=True)
a.SetName('Band 1')
out.GetCellData().SetScalars(a)
"""
dem.ScriptRequestInformation = """
executive = self.GetExecutive()
executive.GetOutputInformation(0).Set(executive.WHOLE_EXTENT(), 0, 40, 0, 30, 0, 0)
"""
converted = TerrainFromImage(Input=dem, UseNoDataValue=1, NoDataValue=-9999, HeightScale=2.0, BaseHeight=-100)
terrain_image = fetch_port(converted, 0)
check(terrain_image.GetDimensions() == (40, 30, 1), "cell data gives one sample per cell: %s" % (terrain_image.GetDimensions(),))
check(abs(terrain_image.GetOrigin()[0] - 500015.0) < 1e-6, "samples at the cell centres: origin %s" % (terrain_image.GetOrigin(),))
e = pftest.point_array(terrain_image, "elevation").reshape(30, 40)
ii, jj = np.meshgrid(np.arange(40), np.arange(30))
truth = 2.0 * (100.0 + 2.0 * ii + jj) - 100
check(np.all(np.isfinite(e)), "no-data filled")
check(np.abs(e - truth).max() < 8.0, "filled holes continue the plane (worst %g m)" % np.abs(e - truth).max())
mask = np.ones_like(e, dtype=bool)
mask[10:14, 10:14] = False
mask[20, 5] = False
check(np.allclose(e[mask], truth[mask]), "valid samples scaled exactly")
converted.UpdatePropertyInformation()

# --- a 16-bit PNG heightmap ---
png = os.path.join(out, "heightmap.png")
heights16 = (np.add.outer(np.arange(33) * 1000, np.arange(17) * 500)).T.astype(np.uint16)  # 17 rows x 33 columns
raw = vtkImageData()
raw.SetDimensions(33, 17, 1)
raw.GetPointData().SetScalars(numpy_to_vtk(heights16.ravel(), deep=True))
writer = vtkPNGWriter()
writer.SetFileName(png)
writer.SetInputData(raw)
writer.Write()
heightmap = PNGSeriesReader(FileNames=[png])
from_png = TerrainFromImage(Input=heightmap, HeightScale=0.01, Spacing=[5, 5])
png_terrain = fetch_port(from_png, 0)
values = pftest.point_array(png_terrain, "elevation")
check(png_terrain.GetSpacing()[0] == 5.0, "Spacing applied: %s" % (png_terrain.GetSpacing(),))
check(abs(values.max() - 0.01 * heights16.max()) < 1e-3 and values.min() == 0.0,
      "16-bit values kept (max %g, expected %g)" % (values.max(), 0.01 * heights16.max()))

# --- a GeoTIFF DEM through ParaView's own GDAL Raster Reader (a vtkUniformGrid, heights as cell
# data "Elevation", rows north-up): every terrain consumer takes it as it is ---
tif = os.path.join(out, "dem.tif")
raw_dem = vtkImageData()
raw_dem.SetDimensions(24, 16, 1)
jj, ii = np.mgrid[0:16, 0:24]
dem_values = (50.0 + 3.0 * ii + 2.0 * jj + 10.0 * np.sin(ii / 3.0)).astype(np.float32)
raw_dem.GetPointData().SetScalars(numpy_to_vtk(dem_values.ravel(), deep=True))
tiff_writer = vtkTIFFWriter()
tiff_writer.SetFileName(tif)
tiff_writer.SetInputData(raw_dem)
tiff_writer.Write()
gdal = GDALRasterReader(FileName=tif)
check(fetch_port(gdal, 0).GetCellData().GetNumberOfArrays() == 1, "the GDAL reader gives cell data")
from_gdal = pftest.point_array(fetch_port(TerrainFromImage(Input=gdal), 0), "elevation")
check(len(from_gdal) == 24 * 16 and abs(from_gdal.max() - dem_values.max()) < 1e-3, "DEM heights kept")
gdal_eroded = HydraulicErosion(Input=gdal, Drops=300)
check(fetch_port(gdal_eroded, 0).GetDimensions() == (24, 16, 1), "erosion takes the DEM as it is")
for consumer in (GerstnerOcean(Bathymetry=gdal, Resolution=[16, 16], SeaLevel=80),
                 SPHStep(Input=ParticleBlock(Spacing=2.0, BlockBounds=[4, 10, 4, 10, 130, 136],
                                             DomainBounds=[0, 24, 0, 16, 40, 150]), Boundary=gdal,
                         NumberOfOutputs=1)):
    catcher = pftest.ErrorCatcher(consumer)
    times = consumer.TimestepValues
    consumer.UpdatePipeline(times[-1] if times else 0.0)
    check(not catcher.text(), "%s takes the DEM: %r" % (consumer.GetXMLLabel(), catcher.text()))

# --- Hydraulic Erosion: both methods close their sediment budget ---
hills = ProceduralTerrain(Extent=[640, 640], Resolution=[129, 129], HeightScale=60, FeatureSize=400)
for method, extra in (("Droplets", dict(Drops=4000)), ("Virtual Pipes", dict(Iterations=150, RainRate=0.01))):
    eroded = HydraulicErosion(Input=hills, Method=method, **extra)
    data = fetch_port(eroded, 0)
    for name in ("elevation", "water_flow", "sediment_deposited", "eroded_depth"):
        check(np.all(np.isfinite(pftest.point_array(data, name))), "%s: %s finite" % (method, name))
    eroded.UpdatePropertyInformation()
    budget = [eroded.GetPropertyValue(n) for n in ("ErodedVolume", "DepositedVolume", "CarriedVolume")]
    check(budget[0] > 0 and abs(budget[0] - budget[1] - budget[2]) <= 1e-3 * budget[0],
          "%s: eroded %g = deposited %g + carried %g" % (method, budget[0], budget[1], budget[2]))
    before = pftest.point_array(fetch_port(hills, 0), "elevation")
    after = pftest.point_array(data, "elevation")
    check(not np.array_equal(before, after), "%s changed the terrain" % method)
    check(fetch_port(eroded, 1).GetPointData().GetArray("eroded_depth") is not None, "%s: surface arrays" % method)

# --- errors name the property ---
bad = HydraulicErosion(Input=hills, Inertia=3.0)  # domains advise the GUI; pvpython passes it on
catcher = pftest.ErrorCatcher(bad)
bad.UpdatePipeline()
check("Inertia" in catcher.text(), "erosion names Inertia: %r" % catcher.text())
nan_image = ProgrammableSource(OutputDataSetType="vtkImageData")
nan_image.Script = """
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
out = self.GetImageDataOutput()
out.SetDimensions(8, 8, 1)
a = numpy_to_vtk(np.full(64, np.nan, dtype=np.float32), deep=True)
a.SetName('h')
out.GetPointData().SetScalars(a)
"""
nan_image.ScriptRequestInformation = """
executive = self.GetExecutive()
executive.GetOutputInformation(0).Set(executive.WHOLE_EXTENT(), 0, 7, 0, 7, 0, 0)
"""
all_nan = TerrainFromImage(Input=nan_image)
catcher = pftest.ErrorCatcher(all_nan)
all_nan.UpdatePipeline()
check("no-data" in catcher.text() and "'h'" in catcher.text(), "all-NaN image refused by name: %r" % catcher.text())
# A height image with a NaN: erosion and SPH Step's Boundary refuse it by name (Terrain From Image
# is the way to fill it).
holed = ProgrammableSource(OutputDataSetType="vtkImageData")
holed.Script = nan_image.Script.replace("np.full(64, np.nan, dtype=np.float32)",
                                        "np.where(np.arange(64) == 9, np.nan, 1.0).astype(np.float32)")
holed.ScriptRequestInformation = nan_image.ScriptRequestInformation
erode_nan = HydraulicErosion(Input=holed, Drops=10)
catcher = pftest.ErrorCatcher(erode_nan)
erode_nan.UpdatePipeline()
check("not finite" in catcher.text() and "NoDataValue" in catcher.text(), "NaN terrain refused: %r" % catcher.text())
filled = pftest.point_array(fetch_port(TerrainFromImage(Input=holed), 0), "elevation")
check(np.all(filled == 1.0), "the NaN filled from its neighbours")
water_block = ParticleBlock(Spacing=0.5, BlockBounds=[1, 3, 1, 3, 2, 3], DomainBounds=[0, 7, 0, 7, -1, 5])
nan_boundary = SPHStep(Input=water_block, Boundary=holed, NumberOfOutputs=1)
catcher = pftest.ErrorCatcher(nan_boundary)
nan_boundary.UpdatePipeline(nan_boundary.TimestepValues[-1])
check("Boundary" in catcher.text(), "SPH Step names its Boundary for a NaN height: %r" % catcher.text())
huge = ProceduralTerrain(Octaves=24, Lacunarity=16)
catcher = pftest.ErrorCatcher(huge)
huge.UpdatePipeline()
check("Octaves or Lacunarity" in catcher.text(), "absurd octaves refused: %r" % catcher.text())
print("terrain sources: OK")
