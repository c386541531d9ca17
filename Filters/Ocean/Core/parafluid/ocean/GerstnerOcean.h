#pragma once
// The ocean surface as a sum of Gerstner waves, in deep water, in water of uniform finite depth, or
// over a bathymetry where waves shoal, refract and break. One CPU implementation: the Gerstner
// Ocean source evaluates it on a grid, and tests hold the GPU representation to it.
//
// Per wave i at a rest point p on the sea surface (depth h):
//   phase      theta0 = Phi_i(p) - omega_i t + phase_i, Phi = k x in uniform depth, the integral of
//              the local wavenumber along the direction over a bathymetry (WavePhaseField);
//              omega_i = sqrt(g k_deep) is conserved as the wave shoals.
//   wind       theta = theta0 - e (1 + sin theta0) / 2, e = WindLean max(D . wind, 0): points high on
//              a wave run ahead of the trough, so crests lean downwind.
//   orbit      an ellipse in the vertical plane through the local direction D = grad Phi / |grad Phi|
//              (after Fournier & Reeves 1986): horizontal semi-axis Q A Sx, vertical A Sz with
//              Sx = 1 / (1 - exp(-k h)) (grows towards the shore) and Sz = 1 - exp(-k h) (shrinks),
//              tilted forward by atan(bottom slope ahead) exp(-k h) (slopes falling ahead clamped to
//              zero). Where the summed horizontal steepness would reach MaxSteepness, Sx is limited
//              so that orbits never loop.
//   breaking   (after Gonzato & Le Saec 2000) weight b rising from 0 to 1 as the local height
//              2 A Sz reaches BreakingDepthRatio h; with P = max(sin theta, 0): the crest is
//              stretched up by b Stretch A Sz P^2, tilted forward by b Lean P [rad] and thrown forward
//              by b Shift A P^2: all functions of the phase, weighted by depth.
// Normals and the Jacobian of the horizontal map come from the analytic derivatives, treating the
// slowly varying amplitude factors as locally constant. Jacobian <= 0 marks a fold.
#include "parafluid/ocean/GerstnerWave.h"
#include "parafluid/ocean/WaveDispersion.h"
#include "parafluid/ocean/WavePhaseField.h"

#include "parafluid/ocean/Bathymetry.h"

#include <memory>
#include <vector>

namespace parafluid::ocean
{

struct OceanParameters
{
  std::vector<GerstnerWave> waves;
  double gravity = kStandardGravity; // [m/s^2]
  double depth = kDeepWater;         // [m] uniform water depth when there is no bathymetry
  double maxSteepness = 0.9;         // cap on the summed horizontal steepness (1 = the fold limit)
  double windDirection = 0.0;        // [degrees] direction the wind blows towards
  double windLean = 0.0;             // [0, 0.5] how far crests lean downwind
  double breakingDepthRatio = 0.78;  // wave height / depth at which a wave breaks (McCowan 1894)
  double breakingStretch = 0.6;      // breaking crest raised by this fraction of its amplitude
  double breakingLean = 0.6;         // [rad] forward tilt of a breaking crest
  double breakingShift = 0.8;        // breaking crest thrown forward by this fraction of its amplitude
  double minDepth = 0.05;            // [m] shallower water counts as shore: no waves
};

/// Throws std::invalid_argument naming the parameter that is out of range.
void validate(const OceanParameters& parameters);

/// Upper bounds [m] of how far any surface point moves from its rest position, at any time:
/// vertically sum A (1 + breakingStretch) (orbits shrink with depth, crests rise by the stretch),
/// horizontally sum A (Q + breakingShift) in deep water; over a floor the orbits' major axes are
/// capped by maxSteepness, each at most maxSteepness / k, which is added. For the bounds a view
/// needs (camera reset, clipping range) before any point is evaluated.
void displacementBound(const OceanParameters& parameters, bool overFloor, double& horizontal, double& vertical);

class GerstnerOcean
{
public:
  static constexpr int kMaxWaves = 64;

  /// region: x0, x1, y0, y1 [m] where the ocean will be evaluated (used to lay out the phase fields
  /// over a bathymetry; points outside still work, with phases continued past the edge).
  GerstnerOcean(OceanParameters parameters, std::shared_ptr<const Bathymetry> bathymetry = nullptr,
                const double region[4] = nullptr);

  /// Evaluates n rest points (x, y) on the sea surface at `time` [s]. Outputs (any may be null):
  /// displacement (3n, metres, added to (x, y, sea level)), unit normal (3n), jacobian (n) of the
  /// horizontal map, foam (n, 0..1: breaking crests and compressed surface), depth (n, metres of
  /// water, 0 on land). `threads` <= 0 uses all OpenMP threads.
  void evaluate(const float* x, const float* y, std::size_t n, double time, float* displacement, float* normal,
                float* jacobian, float* foam, float* depth, int threads = 0) const;

  /// The waves as evaluated: steepness scaled down when the summed Q k A exceeded MaxSteepness.
  const std::vector<GerstnerWave>& effectiveWaves() const { return this->Waves; }
  const OceanParameters& parameters() const { return this->Parameters; }
  /// Per wave: deep-water wavenumber, angular frequency, wind lean term, unit direction, and the
  /// wavenumber in the uniform depth; the phase fields when there is a bathymetry.
  const std::vector<double>& deepWavenumbers() const { return this->DeepK; }
  const std::vector<double>& angularFrequencies() const { return this->Omega; }
  const std::vector<double>& leans() const { return this->Lean; }
  double directionX(std::size_t i) const { return this->DirX[i]; }
  double directionY(std::size_t i) const { return this->DirY[i]; }
  const std::vector<double>& uniformWavenumbers() const { return this->UniformK; }
  const std::vector<WavePhaseField>& phaseFields() const { return this->Phases; }
  const Bathymetry* bathymetry() const { return this->Floor.get(); }

private:
  OceanParameters Parameters;
  std::shared_ptr<const Bathymetry> Floor;
  std::vector<GerstnerWave> Waves;
  std::vector<double> DeepK, Omega, Lean, DirX, DirY;
  std::vector<double> UniformK;       // local wavenumber in uniform depth
  std::vector<WavePhaseField> Phases; // one per wave, over a bathymetry
};
} // namespace parafluid::ocean
