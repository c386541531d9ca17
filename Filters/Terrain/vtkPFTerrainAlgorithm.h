/**
 * @class vtkPFTerrainAlgorithm
 * @brief Base of the terrain sources and filters: output 0 the height image, output 1 its surface.
 *
 * Output 0 is a 2-D vtkImageData with the point array `elevation` [m] (the active scalars) and
 * whatever a subclass adds; output 1, when GenerateSurface is on, the same terrain as a
 * triangulated surface z = elevation with point `Normals` and the same point arrays (what SPH
 * Step's Boundary, Carpet Surface and the ocean's Bathymetry take, as they take the image).
 * ComputeSlope adds `slope` [degrees], ComputeCurvature `curvature` [1/m] (the Laplacian:
 * positive in hollows). Subclasses fill a parafluid::terrain::ElevationGrid in ComputeTerrain.
 */
#pragma once

#include "ParaFluidTerrainFiltersModule.h"
#include "vtkAlgorithm.h"

#include "parafluid/terrain/ElevationGrid.h"

#include <string>
#include <utility>
#include <vector>

class vtkImageData;

class PARAFLUIDTERRAINFILTERS_EXPORT vtkPFTerrainAlgorithm : public vtkAlgorithm
{
public:
  vtkTypeMacro(vtkPFTerrainAlgorithm, vtkAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetMacro(GenerateSurface, bool);
  vtkGetMacro(GenerateSurface, bool);
  vtkSetMacro(ComputeSlope, bool);
  vtkGetMacro(ComputeSlope, bool);
  vtkSetMacro(ComputeCurvature, bool);
  vtkGetMacro(ComputeCurvature, bool);

  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
                             vtkInformationVector* outputVector) override;

protected:
  vtkPFTerrainAlgorithm();
  ~vtkPFTerrainAlgorithm() override = default;
  int FillOutputPortInformation(int port, vtkInformation* info) override;

  /// Extra per-sample arrays a subclass returns with its terrain.
  using NamedArrays = std::vector<std::pair<std::string, std::vector<float>>>;
  /// Fills `grid` (and `arrays`) from the inputs; returns false after reporting an error.
  virtual bool ComputeTerrain(vtkInformationVector** inputVector, parafluid::terrain::ElevationGrid& grid,
                              NamedArrays& arrays) = 0;
  /// The grid's geometry, for the pipeline's information pass (false: not known yet / error).
  virtual bool TerrainGeometry(vtkInformationVector** inputVector, int dims[2], double origin[2],
                               double spacing[2]) = 0;
  /// Label for messages ("Procedural Terrain").
  virtual const char* Label() const = 0;

  /// Reports progress in [0, 1] and returns false when the user aborted.
  bool Progress(double fraction);

  /// For filters: the geometry of the image on input port 0 (its whole extent, origin, spacing).
  static bool InputGeometry(vtkInformationVector** inputVector, int dims[2], double origin[2], double spacing[2]);

  /// Sets a field of a settings struct and marks the algorithm modified when it changes.
  template<class Field, class Value>
  void SetSetting(Field& field, Value value)
  {
    if (!(field == value))
    {
      field = value;
      this->Modified();
    }
  }

private:
  vtkPFTerrainAlgorithm(const vtkPFTerrainAlgorithm&) = delete;
  void operator=(const vtkPFTerrainAlgorithm&) = delete;
  int RequestInformation(vtkInformationVector** inputVector, vtkInformationVector* outputVector);
  int RequestUpdateExtent(vtkInformationVector** inputVector);
  int RequestData(vtkInformationVector** inputVector, vtkInformationVector* outputVector);

  bool GenerateSurface = true;
  bool ComputeSlope = false;
  bool ComputeCurvature = false;
};
