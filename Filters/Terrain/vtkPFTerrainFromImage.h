/**
 * @class vtkPFTerrainFromImage
 * @brief Filter: any 2-D image (a DEM from the GDAL Raster Reader, a 16-bit PNG heightmap, ...)
 * to the terrain contract.
 *
 * Reads the chosen array (point data, or cell data with the nodes at the cell centres), makes
 * elevation = HeightScale * value + BaseHeight [m], fills no-data samples (NaN, and with
 * UseNoDataValue those equal to NoDataValue) from their surroundings, and keeps the image's
 * origin and spacing unless Spacing (metres per sample; 0 keeps the input's) is given.
 */
#pragma once

#include "vtkPFTerrainAlgorithm.h"

class PARAFLUIDTERRAINFILTERS_EXPORT vtkPFTerrainFromImage : public vtkPFTerrainAlgorithm
{
public:
  static vtkPFTerrainFromImage* New();
  vtkTypeMacro(vtkPFTerrainFromImage, vtkPFTerrainAlgorithm);

  vtkSetMacro(HeightScale, double);
  vtkGetMacro(HeightScale, double);
  vtkSetMacro(BaseHeight, double);
  vtkGetMacro(BaseHeight, double);
  vtkSetMacro(UseNoDataValue, bool);
  vtkGetMacro(UseNoDataValue, bool);
  vtkSetMacro(NoDataValue, double);
  vtkGetMacro(NoDataValue, double);
  vtkSetVector2Macro(Spacing, double);
  vtkGetVector2Macro(Spacing, double);
  /// Samples filled because they were no-data, in the last update.
  vtkGetMacro(FilledSamples, long long);

protected:
  vtkPFTerrainFromImage();
  ~vtkPFTerrainFromImage() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  bool ComputeTerrain(vtkInformationVector** inputVector, parafluid::terrain::ElevationGrid& grid,
                      NamedArrays& arrays) override;
  bool TerrainGeometry(vtkInformationVector** inputVector, int dims[2], double origin[2], double spacing[2]) override;
  const char* Label() const override { return "Terrain From Image"; }

private:
  vtkPFTerrainFromImage(const vtkPFTerrainFromImage&) = delete;
  void operator=(const vtkPFTerrainFromImage&) = delete;
  double HeightScale = 1.0;
  double BaseHeight = 0.0;
  bool UseNoDataValue = false;
  double NoDataValue = -9999.0;
  double Spacing[2] = { 0.0, 0.0 };
  long long FilledSamples = 0;
};
