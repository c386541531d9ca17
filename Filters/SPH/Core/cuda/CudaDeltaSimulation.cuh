#pragma once
// Internal to the CUDA backend: δ-SPH on the GPU as a Simulation, each step the CPU's
// (DeltaSPHSolver::step) with the passes of DeltaSPHKernels.cuh.
#include "cuda/CudaSimulation.cuh"
#include "cuda/DeltaSPHKernels.cuh"
#include "cuda/SurfaceTensionKernels.cuh"

#include <optional>

namespace parafluid::sph::cuda
{
class CudaDeltaSimulation final : public CudaSimulation
{
public:
  /// `boundary` (may be null) is copied to the GPU; it need not outlive the simulation.
  CudaDeltaSimulation(const SPHParameters& parameters, ParticleState initial,
                      std::shared_ptr<const TriangleBoundary> boundary);

private:
  /// δ-SPH's bytes per particle beyond the state: 14 floats (its own arrays, the 6 of the
  /// gradient correction, the 3 of the push).
  static constexpr std::size_t kSolverBytesPerParticle = 4 * 14;
  /// The columns: each particle's fullness (new: 1) and slow departure (new: NaN, from where it is).
  enum Column
  {
    FULLNESS,
    SLOW
  };

  void prepare(ParticleState& s, Columns& columns) override;
  void startPasses() override;
  double stepPasses(double remaining) override;
  std::vector<float> newParticleColumns() const override;
  Columns downloadColumns() const override;
  std::vector<DeviceBuffer<float>*> sortedSolverArrays() override;
  std::vector<DeviceBuffer<float>*> solverArrays() override;
  double signalSpeed() const override { return this->SoundSpeed; }

  /// The accelerations of the state as it is: the force pass, then the surface tension.
  void accelerations();
  DeltaArrays arrays() const;

  delta::Constants K;
  DeviceBuffer<float> Rate, Fullness, NextFullness, Slow, Correction, Push, Interior;
  std::optional<AkinciConstants<WendlandC2Kernel>> Tension; // SPHParameters::surfaceTension > 0
  double SoundSpeed = 0.0, SlowDepartureTime = 0.0;
  float PressureCorrection = 1.0f;
};
} // namespace parafluid::sph::cuda
