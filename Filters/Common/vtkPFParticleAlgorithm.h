/**
 * @class vtkPFParticleAlgorithm
 * @brief Base of the filters that need every particle at once (SPH Step, the particle surfaces,
 * the flow lines): it owns their common preamble.
 *
 * RequestData checks that input 0 is a point set, gathers the pieces of all processes on process
 * 0 under MPI (as well as those of the extra ports named by SetGatheredInputPort), leaves the
 * output empty on the other processes, and hands the gathered particles to RequestParticles;
 * a filter that WorksOnPieces gets each process's own piece on every process instead.
 * Errors are reported with the filter's GUI label in front, so the user knows which filter
 * speaks.
 */
#pragma once

#include "ParaFluidFiltersCommonModule.h"
#include "ParameterCheck.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkPointSet;

class PARAFLUIDFILTERSCOMMON_EXPORT vtkPFParticleAlgorithm : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkPFParticleAlgorithm, vtkPolyDataAlgorithm);

protected:
  /// `label`: the filter's name in the GUI ("SPH Step"), put before every error.
  explicit vtkPFParticleAlgorithm(const char* label);
  ~vtkPFParticleAlgorithm() override;

  /// The particles of the whole pipeline, on the process that holds them all.
  struct Particles
  {
    vtkPointSet* Gathered = nullptr; ///< every process's piece (the input itself in serial); never null
    vtkPointSet* Local = nullptr;    ///< this process's own piece: its MTime and time say what changed
    vtkPointSet* Extra = nullptr;    ///< the gathered points of the extra port, or null
  };
  /// The filter's work, called on the process that holds all the particles (process 0), or on
  /// every process with its piece (WorksOnPieces).
  virtual int RequestParticles(const Particles& particles, vtkInformationVector** inputVector, vtkInformation* outInfo,
                               vtkPolyData* output) = 0;

  /// What the filter does with particles whose position (or one of `arrays`) is NaN or infinite:
  /// Refuse them (an error naming the first such particle) or Drop them (a warning saying how
  /// many were left out). Default: Refuse, positions only.
  enum class NonFinite
  {
    Refuse,
    Drop
  };
  void SetNonFinitePolicy(NonFinite policy, std::vector<std::string> arrays = {})
  {
    this->NonFinitePolicy = policy;
    this->FiniteArrays = std::move(arrays);
  }

  /// True when this update runs on every process with its own piece, the filter exchanging what
  /// its particles need itself (a distributed SPH run): the pieces are not gathered, and
  /// RequestParticles gets the local piece as Gathered on every process. Default: false.
  virtual bool WorksOnPieces() const { return false; }

  /// An optional input port whose points are gathered too (seeds); -1: none.
  void SetGatheredInputPort(int port) { this->GatheredInputPort = port; }

  /// The particle spacing d [m]: `property` when positive, else the input's particle_spacing field
  /// data, else 0 after an error that names `propertyName`.
  double ParticleSpacingOr(double property, vtkPointSet* input, const char* propertyName);

  /// True when `check` found nothing; else reports its problem and returns false.
  bool Accept(const parafluid::vtk::ParameterCheck& check)
  {
    if (!check.ok())
    {
      this->ReportError(check.problem());
    }
    return check.ok();
  }

  /// vtkErrorMacro with the filter's label in front.
  void ReportError(const std::string& message);

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) final;

private:
  vtkPFParticleAlgorithm(const vtkPFParticleAlgorithm&) = delete;
  void operator=(const vtkPFParticleAlgorithm&) = delete;

  /// The particles with finite positions and arrays, `input` itself when all are; null after an
  /// error (Refuse).
  vtkSmartPointer<vtkPointSet> ApplyNonFinitePolicy(vtkPointSet* input);

  std::string Label;
  int GatheredInputPort = -1;
  NonFinite NonFinitePolicy = NonFinite::Refuse;
  std::vector<std::string> FiniteArrays;
};
