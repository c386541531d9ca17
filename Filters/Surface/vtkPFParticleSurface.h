/**
 * @class vtkPFParticleSurface
 * @brief Filter: the liquid's surface around a set of particles, by sparse marching cubes.
 *
 * The field is the covered-volume fraction phi(x) = d^3 sum_j W(|x - x_j|), W the poly6 kernel
 * with support KernelRadius * d, d the particle spacing: about 1 inside the fluid, 0 beyond the
 * kernel's reach; IsoValue 0.5 is the edge of the volume N d^3 the particles stand for. It is
 * sampled on a grid of CellSize * d only in 8^3-point blocks within reach of a particle, and
 * polygonised there (parafluid::surface::ParticleSurface). The output is one watertight
 * triangle mesh with shared vertices, outward Normals from the field gradient, optional Taubin
 * smoothing, and the chosen particle arrays interpolated to the vertices (kernel-weighted mean).
 * Under MPI the pieces are gathered on process 0, which builds the whole surface.
 */
#pragma once

#include "ParaFluidSurfaceFiltersModule.h"
#include "vtkPFParticleAlgorithm.h"

#include <string>
#include <vector>

class PARAFLUIDSURFACEFILTERS_EXPORT vtkPFParticleSurface : public vtkPFParticleAlgorithm
{
public:
  static vtkPFParticleSurface* New();
  vtkTypeMacro(vtkPFParticleSurface, vtkPFParticleAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Particle spacing d [m]; 0 takes it from the input's particle_spacing field data.
  vtkSetMacro(ParticleSpacing, double);
  vtkGetMacro(ParticleSpacing, double);
  /// Grid cell edge in particle spacings (0.5: half a spacing).
  vtkSetMacro(CellSize, double);
  vtkGetMacro(CellSize, double);
  /// Support radius of the poly6 kernel in particle spacings.
  vtkSetMacro(KernelRadius, double);
  vtkGetMacro(KernelRadius, double);
  /// Level of the covered-volume fraction the surface passes through (0 < IsoValue < 1).
  vtkSetMacro(IsoValue, double);
  vtkGetMacro(IsoValue, double);
  /// Taubin lambda|mu smoothing iterations (0: none).
  vtkSetMacro(Smoothing, int);
  vtkGetMacro(Smoothing, int);
  /// Output vertex normals from the field gradient.
  vtkSetMacro(ComputeNormals, bool);
  vtkGetMacro(ComputeNormals, bool);
  vtkBooleanMacro(ComputeNormals, bool);

  /// Point arrays of the particles to interpolate to the surface's vertices.
  void AddArrayToInterpolate(const char* name);
  void ClearArraysToInterpolate();

  /// Figures of the last run: blocks holding field values, blocks polygonised, working bytes.
  vtkGetMacro(AllocatedBlocks, vtkIdType);
  vtkGetMacro(SurfaceBlocks, vtkIdType);
  vtkGetMacro(WorkingBytes, vtkIdType);

protected:
  vtkPFParticleSurface();
  ~vtkPFParticleSurface() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestParticles(const Particles& particles, vtkInformationVector** inputVector, vtkInformation* outInfo,
                       vtkPolyData* output) override;

  double ParticleSpacing = 0.0;
  double CellSize = 0.5;
  double KernelRadius = 3.0;
  double IsoValue = 0.5;
  int Smoothing = 10;
  bool ComputeNormals = true;
  std::vector<std::string> ArraysToInterpolate;
  vtkIdType AllocatedBlocks = 0, SurfaceBlocks = 0, WorkingBytes = 0;

private:
  vtkPFParticleSurface(const vtkPFParticleSurface&) = delete;
  void operator=(const vtkPFParticleSurface&) = delete;
};
