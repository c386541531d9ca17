/**
 * @class vtkPFFluidFlowLines
 * @brief Filter: short flow lines through the particles' velocity, for illustration.
 *
 * From every SeedStride-th particle (or from the points of the optional second input, Seeds, for
 * instance an extracted selection), a polyline of PointsPerLine points is integrated over
 * LineDuration seconds (RK2 or RK4) through the velocity interpolated with the poly6 kernel of
 * radius KernelRadius * d, so a line's length follows the local speed. The lines that are long
 * and curved, ranked by length x turning, are kept up to MaxLines
 * (parafluid::npr::traceFlowLines). Output: polylines with point arrays `speed` [m/s] and
 * `curvature` [1/m], and cell arrays `length` [m], `turning` [rad] and `seed`. Under MPI the
 * particles are gathered on process 0, which traces all lines.
 */
#pragma once

#include "ParaFluidNPRFiltersModule.h"
#include "vtkPFParticleAlgorithm.h"

#include "ParticleContract.h"

#include <string>

class PARAFLUIDNPRFILTERS_EXPORT vtkPFFluidFlowLines : public vtkPFParticleAlgorithm
{
public:
  static vtkPFFluidFlowLines* New();
  vtkTypeMacro(vtkPFFluidFlowLines, vtkPFParticleAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Point array holding the particles' velocity (3 components) [m/s].
  void SetVelocityArray(const char* name);
  const char* GetVelocityArray() const { return this->VelocityArray.c_str(); }
  /// Particle spacing d [m]; 0 takes it from the input's particle_spacing field data.
  vtkSetMacro(ParticleSpacing, double);
  vtkGetMacro(ParticleSpacing, double);
  /// Support radius of the interpolation kernel, in particle spacings.
  vtkSetMacro(KernelRadius, double);
  vtkGetMacro(KernelRadius, double);
  /// Without Seeds: a line from every k-th particle.
  vtkSetMacro(SeedStride, int);
  vtkGetMacro(SeedStride, int);
  vtkSetMacro(PointsPerLine, int);
  vtkGetMacro(PointsPerLine, int);
  /// Time integrated along each line [s].
  vtkSetMacro(LineDuration, double);
  vtkGetMacro(LineDuration, double);
  /// 0: RK2 (midpoint), 1: RK4.
  vtkSetClampMacro(Integrator, int, 0, 1);
  vtkGetMacro(Integrator, int);
  /// Most lines kept (the best by length x turning).
  vtkSetMacro(MaxLines, int);
  vtkGetMacro(MaxLines, int);

protected:
  vtkPFFluidFlowLines();
  ~vtkPFFluidFlowLines() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestParticles(const Particles& particles, vtkInformationVector** inputVector, vtkInformation* outInfo,
                       vtkPolyData* output) override;

  std::string VelocityArray = parafluid::contract::Velocity;
  double ParticleSpacing = 0.0;
  double KernelRadius = 2.0;
  int SeedStride = 10;
  int PointsPerLine = 16;
  double LineDuration = 0.05;
  int Integrator = 1;
  int MaxLines = 2000;

private:
  vtkPFFluidFlowLines(const vtkPFFluidFlowLines&) = delete;
  void operator=(const vtkPFFluidFlowLines&) = delete;
};
