#pragma once
// How a raindrop redirects light: the phase function of a sphere of water by geometric optics
// (as the seed's discrete transfer function; van de Hulst 1957, ch. 12). A parallel beam hits the
// drop at impact parameter b = sin(i); each ray splits at every interface by Fresnel's law
// (unpolarised), the p-th path (p = 0 reflected outside, p >= 1 refracted in, p - 1 internal
// reflections, refracted out) leaving at deviation
//   D_0 = pi - 2 i,   D_p = 2 (i - r) + (p - 1) (pi - 2 r),   sin i = n sin r,
// with energy R (p = 0) or T^2 R^(p-1) (p >= 1), and optionally attenuated inside by absorption
// over its chord lengths 2 p cos r (in drop radii). The energy is summed into equal bins of the
// scattering angle (the angle between the incoming and outgoing directions), so the rainbow
// caustics stay finite, and divided by each bin's solid angle: P(theta) [1/sr], integrating to the
// fraction of light not absorbed (1 for clear water, less only by the paths beyond the last).
#include "parafluid/rain/SphericalHarmonics.h"

#include <vector>

namespace parafluid::rain
{
struct DropTransferSettings
{
  double refractiveIndex = 1.333; // water in visible light
  int interactions = 9;           // paths p = 0 .. interactions - 1 (the seed's 9)
  int bins = 1800;                // equal bins of the scattering angle over [0, pi]
  int samples = 400000;           // impact parameters (uniform in b^2, i.e. in beam area)
  double absorption = 0.0;        // optical depth per drop radius inside the water
};

class DropTransfer
{
public:
  explicit DropTransfer(const DropTransferSettings& settings = {});

  /// P(theta) [1/sr] per bin, all paths; and of one path p alone.
  const std::vector<double>& phase() const { return this->Phase; }
  std::vector<double> pathPhase(int p) const;
  /// Bin centre [rad].
  double angle(int bin) const;
  /// Integral of P over the sphere.
  double energy() const;
  /// The zonal coefficients lambda_l = 2 pi integral P(t) P_l(t) dt of the phase function (l = 0..3):
  /// the radiance a drop sends back along view direction v is sum_lm lambda_l L_lm Y_lm(v), L_lm the
  /// environment's coefficients (Funk-Hecke).
  std::array<double, kSHBands> zonal() const;
  /// The transfer vector lambda_l Y_lm(v) for view directions v (from the eye towards the drop) on an
  /// equirectangular grid (width x height, azimuth along the width, z up; row 0 at z = -1): 16 floats
  /// per direction. The renderer stores it as a texture.
  std::vector<float> transferTable(int width, int height) const;

private:
  DropTransferSettings Settings;
  std::vector<double> Phase;
  std::vector<std::vector<double>> PathEnergy; // per path, energy per bin
};
} // namespace parafluid::rain
