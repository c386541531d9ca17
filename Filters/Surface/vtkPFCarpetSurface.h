/**
 * @class vtkPFCarpetSurface
 * @brief Filter: the "carpet" height-field surface of a shallow flow over terrain.
 *
 * A Resolution x Resolution grid over the domain in x, y takes, per cell, the height of the
 * highest particle above it (parafluid::surface::CarpetSurface). Where the particles leave, the
 * carpet falls with FallAcceleration until particles come back or it is within MinDepth of the
 * terrain, leaving the trail a thin film leaves on a slope. The state is kept between time steps:
 * moving forward in time continues it, moving back (or changing a property) starts again.
 *
 * Terrain (optional, port 1): a 2D image whose point scalars are ground heights [m], or a terrain
 * surface. The domain is the terrain's extent; without a terrain it is the input's domain_bounds
 * field data (else the particles' extent at the first time) with a flat floor at its bottom.
 * Output: triangles where the fluid is above the terrain, with Normals and `depth` [m].
 */
#pragma once

#include "ParaFluidSurfaceFiltersModule.h"
#include "vtkPFParticleAlgorithm.h"

#include <memory>

namespace parafluid
{
namespace surface
{
class CarpetSurface;
}
}

class PARAFLUIDSURFACEFILTERS_EXPORT vtkPFCarpetSurface : public vtkPFParticleAlgorithm
{
public:
  static vtkPFCarpetSurface* New();
  vtkTypeMacro(vtkPFCarpetSurface, vtkPFParticleAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The ground (port 1): a 2D height image or a terrain surface.
  void SetTerrainConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  /// Cells along each side of the domain.
  vtkSetClampMacro(Resolution, int, 1, 65536);
  vtkGetMacro(Resolution, int);
  /// Downward acceleration of the carpet where particles have left [m/s^2].
  vtkSetMacro(FallAcceleration, double);
  vtkGetMacro(FallAcceleration, double);
  /// Fluid thinner than this above the terrain is dry [m].
  vtkSetMacro(MinDepth, double);
  vtkGetMacro(MinDepth, double);

  /// Figures of the last run: wet cells and quadtree nodes the emission visited.
  vtkGetMacro(WetCells, vtkIdType);
  vtkGetMacro(VisitedNodes, vtkIdType);

protected:
  vtkPFCarpetSurface();
  ~vtkPFCarpetSurface() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestParticles(const Particles& particles, vtkInformationVector** inputVector, vtkInformation* outInfo,
                       vtkPolyData* output) override;

  int Resolution = 256;
  double FallAcceleration = 9.81;
  double MinDepth = 0.001;
  vtkIdType WetCells = 0, VisitedNodes = 0;

private:
  vtkPFCarpetSurface(const vtkPFCarpetSurface&) = delete;
  void operator=(const vtkPFCarpetSurface&) = delete;

  std::unique_ptr<parafluid::surface::CarpetSurface> Carpet;
  double LastTime = 0.0;
  vtkMTimeType StateTime = 0; // this filter's and the terrain's MTime the state was built under
  bool HasState = false;
};
