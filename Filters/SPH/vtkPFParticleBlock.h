/**
 * @class vtkPFParticleBlock
 * @brief Source: particles on a cubic lattice filling a box (a dam-break water column, a pool).
 *
 * Output follows the ParaFluid data contract: velocity (zero), density (rest density), pressure
 * (zero), mass, int64 id, and field data particle_spacing, smoothing_length (2 spacings),
 * rest_density and domain_bounds, which the SPH Step filter picks up.
 */
#pragma once

#include "ParaFluidSPHFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

namespace parafluid
{
struct ParticleLattice;
}

class PARAFLUIDSPHFILTERS_EXPORT vtkPFParticleBlock : public vtkPolyDataAlgorithm
{
public:
  static vtkPFParticleBlock* New();
  vtkTypeMacro(vtkPFParticleBlock, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Distance between neighbouring particles [m].
  vtkSetMacro(Spacing, double);
  vtkGetMacro(Spacing, double);
  /// The box filled with particles: xmin, xmax, ymin, ymax, zmin, zmax [m].
  vtkSetVector6Macro(BlockBounds, double);
  vtkGetVector6Macro(BlockBounds, double);
  /// The container the SPH Step filter should use, stored as field data "domain_bounds" [m].
  vtkSetVector6Macro(DomainBounds, double);
  vtkGetVector6Macro(DomainBounds, double);
  /// [kg/m^3]
  vtkSetMacro(RestDensity, double);
  vtkGetMacro(RestDensity, double);

protected:
  vtkPFParticleBlock();
  ~vtkPFParticleBlock() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  /// Checks the properties and the memory the block takes; false after reporting an error.
  /// `count`: the particles it will hold.
  bool CheckProperties(double& count);
  /// The lattice as the particle contract's points, arrays and field data.
  void WriteBlock(const parafluid::ParticleLattice& lattice, float mass, double h, vtkPolyData* output);

  vtkPFParticleBlock(const vtkPFParticleBlock&) = delete;
  void operator=(const vtkPFParticleBlock&) = delete;

  double Spacing = 0.01;
  double BlockBounds[6] = { 0.0, 0.2, 0.0, 0.1, 0.0, 0.4 };
  double DomainBounds[6] = { 0.0, 0.8, 0.0, 0.1, 0.0, 0.6 };
  double RestDensity = 1000.0;
};
