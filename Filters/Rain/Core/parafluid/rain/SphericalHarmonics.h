#pragma once
// Real spherical harmonics up to band 4 (l = 0..3, 16 coefficients), the basis of the rain's
// precomputed radiance transfer (Sloan, Kautz & Snyder 2002; for rain, Wang et al. 2006): the
// environment's light and a drop's transfer are both projected on it, and a drop's radiance is the
// dot product of the two coefficient vectors.
#include <array>
#include <functional>
#include <vector>

namespace parafluid::rain
{
constexpr int kSHBands = 4;
constexpr int kSHCount = kSHBands * kSHBands;
using SHVector = std::array<double, kSHCount>;

/// Index of (l, m), m = -l..l: l (l + 1) + m.
constexpr int shIndex(int l, int m)
{
  return l * (l + 1) + m;
}

/// The 16 real, orthonormal harmonics at the unit direction (x, y, z) (z up).
SHVector shBasis(double x, double y, double z);

/// Coefficients of f over the sphere, f_lm = integral of f Y_lm: Gauss-Legendre in cos(theta) and
/// the trapezoid rule in phi (exact for band-limited f of degree < 2 * rings).
SHVector shProject(const std::function<double(double, double, double)>& f, int rings = 32);

/// f at a direction from its coefficients.
double shEvaluate(const SHVector& coefficients, double x, double y, double z);

/// Coefficients of an OpenGL cube map (six square faces +X, -X, +Y, -Y, +Z, -Z, `size` texels a side,
/// `channels` floats a texel, rows from the face's top) per channel, each texel weighted by its
/// exact solid angle. Returns channels * 16 values, channel-major.
std::vector<double> shProjectCubeMap(const std::array<const float*, 6>& faces, int size, int channels);
} // namespace parafluid::rain
