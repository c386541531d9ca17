#pragma once
// The phase of one wave over uneven bathymetry. A wave entering shallower water slows down and
// shortens (its frequency is conserved), so its phase is the integral of the local wavenumber along
// the direction of travel, Phi(p) = integral of k(h) ds. Across the direction, Phi varies where the
// depth does, so the wave vector grad Phi turns towards shallower water: crests bend to follow the
// shore (refraction). Sampled on a grid aligned with the wave's direction; bilinear in between.
#include "parafluid/ocean/Bathymetry.h"

#include <vector>

namespace parafluid::ocean
{

class WavePhaseField
{
public:
  /// direction: unit vector of travel (x, y); bounds: x0, x1, y0, y1 of the region to cover [m];
  /// step: sampling distance [m] (enlarged so the grid stays under 4 M samples); minDepth: depth
  /// [m] used wherever the water is shallower (and on land), where the wave is not shown anyway.
  WavePhaseField(const Bathymetry& bathymetry, double kDeep, const double direction[2], const double bounds[4],
                 double step, double minDepth);

  /// Phase Phi [rad], local wavenumber k [rad/m] and wave vector grad Phi [rad/m] at (x, y).
  /// Beyond the covered region the phase continues with the wavenumber at its edge.
  void sample(double x, double y, double& phase, double& wavenumber, double gradient[2]) const;

  int samplesAlong() const { return this->NS; }
  int samplesAcross() const { return this->NT; }
  /// The grid as stored, for GPU upload: s0, t0, step; and per sample (along fastest) the phase,
  /// the wavenumber and the phase's derivative across.
  void grid(double& s0, double& t0, double& step) const { s0 = this->S0, t0 = this->T0, step = this->Step; }
  const std::vector<double>& phases() const { return this->Phase; }
  const std::vector<float>& wavenumbers() const { return this->Wavenumber; }
  const std::vector<float>& phasesAcross() const { return this->PhaseAcross; }

private:
  double Direction[2];
  double S0 = 0.0, T0 = 0.0, Step = 1.0;
  int NS = 0, NT = 0;
  std::vector<double> Phase;      // Phi at (s_i, t_j), i fastest
  std::vector<float> Wavenumber;  // k = dPhi/ds
  std::vector<float> PhaseAcross; // dPhi/dt
};
} // namespace parafluid::ocean
