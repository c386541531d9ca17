/**
 * @class vtkPFFoamParticles
 * @brief Filter: marks foam, crest and spray particles, steadily over time.
 *
 * Per time step each particle gets a score (parafluid::npr::scoreFoam): surface particles (by the
 * colour field's gradient) on convex, sharply curved surface score by their crest potential over
 * CrestThreshold; particles with at most SprayNeighbours neighbours are spray. A score of 1 or more
 * makes a candidate. A particle (followed by its stable IdArray) switches to foam only after being
 * a candidate for PersistFrames time steps in a row, and back after as many steps as a
 * non-candidate, so foam does not flicker. The state carries over as time moves forward; going
 * back in time, or changing a property, starts again. Output: the input with point arrays `foam`
 * (0/1) and `foam_score`. Under MPI each process keeps its piece, and process 0 scores all the
 * pieces' particles together, so the flags are those of a serial session.
 */
#pragma once

#include "ParaFluidNPRFiltersModule.h"
#include "vtkPassInputTypeAlgorithm.h"

#include "ParticleContract.h"
#include <memory>

#include <string>

// (Nested namespace blocks: VTK's wrapper parser rejects `namespace a::b`.)
namespace parafluid
{
class Communicator;
namespace npr
{
class FoamHysteresis;
}
}

class PARAFLUIDNPRFILTERS_EXPORT vtkPFFoamParticles : public vtkPassInputTypeAlgorithm
{
public:
  static vtkPFFoamParticles* New();
  vtkTypeMacro(vtkPFFoamParticles, vtkPassInputTypeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Particle spacing d [m]; 0 takes it from the input's particle_spacing field data.
  vtkSetMacro(ParticleSpacing, double);
  vtkGetMacro(ParticleSpacing, double);
  /// Neighbourhood radius in particle spacings (the thresholds' defaults suit 3).
  vtkSetMacro(KernelRadius, double);
  vtkGetMacro(KernelRadius, double);
  /// Crest potential that makes a candidate (lower: more crest foam).
  vtkSetMacro(CrestThreshold, double);
  vtkGetMacro(CrestThreshold, double);
  /// A particle with at most this many neighbours is spray.
  vtkSetMacro(SprayNeighbours, int);
  vtkGetMacro(SprayNeighbours, int);
  /// Time steps a particle must stay a candidate (or stay off) before it switches.
  vtkSetClampMacro(PersistFrames, int, 1, 1000);
  vtkGetMacro(PersistFrames, int);
  /// Point array of stable particle ids.
  void SetIdArray(const char* name);
  const char* GetIdArray() const { return this->IdArray.c_str(); }

protected:
  vtkPFFoamParticles();
  ~vtkPFFoamParticles() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double ParticleSpacing = 0.0;
  double KernelRadius = 3.0;
  double CrestThreshold = 1.0;
  int SprayNeighbours = 4;
  int PersistFrames = 3;
  std::string IdArray = parafluid::contract::Id;

private:
  vtkPFFoamParticles(const vtkPFFoamParticles&) = delete;
  void operator=(const vtkPFFoamParticles&) = delete;

  // The hysteresis state, and the state before the last step (to redo that step when the same
  // time is asked for again).
  std::unique_ptr<parafluid::npr::FoamHysteresis> State, StateBefore;
  // The processes under MPI (null in a serial session).
  std::unique_ptr<parafluid::Communicator> Processes;
  bool HasState = false;
  double LastTime = 0.0;
  vtkMTimeType StateSettings = 0;
};
