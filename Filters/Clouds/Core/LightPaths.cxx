#include "parafluid/clouds/LightPaths.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace parafluid::clouds
{
std::vector<float> densityPathToward(const std::vector<float>& density, const int dims[3], const double spacing[3],
                                     const double toward[3])
{
  const double length = std::sqrt(toward[0] * toward[0] + toward[1] * toward[1] + toward[2] * toward[2]);
  bool spaced = true;
  for (int axis = 0; axis < 3; ++axis)
  {
    spaced = spaced && spacing[axis] > 0.0 && std::isfinite(spacing[axis]);
  }
  if (!(length > 0.0) || !std::isfinite(length) || !spaced)
  {
    throw std::invalid_argument("light paths: the direction must be finite and not zero, the spacing positive");
  }
  const std::size_t count = static_cast<std::size_t>(dims[0]) * dims[1] * dims[2];
  if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1 || density.size() != count)
  {
    throw std::invalid_argument("light paths: the density does not match its dimensions");
  }
  const double L[3] = { toward[0] / length, toward[1] / length, toward[2] / length };
  // The direction in samples per metre of travel; its dominant axis a crosses the most slices,
  // the two others (b, c) lie in the slice.
  const double S[3] = { L[0] / spacing[0], L[1] / spacing[1], L[2] / spacing[2] };
  int a = 0;
  for (int axis = 1; axis < 3; ++axis)
  {
    if (std::abs(S[axis]) > std::abs(S[a]))
    {
      a = axis;
    }
  }
  const int b = (a + 1) % 3, c = (a + 2) % 3;
  const std::size_t stride[3] = { 1, static_cast<std::size_t>(dims[0]),
                                  static_cast<std::size_t>(dims[0]) * static_cast<std::size_t>(dims[1]) };
  // One slice toward the light: +1 along a when the light is on the + side.
  const int toLight = S[a] > 0.0 ? 1 : -1;
  const double segment = 1.0 / std::abs(S[a]);                              // ray length between slices [m]
  const double shift[2] = { S[b] / std::abs(S[a]), S[c] / std::abs(S[a]) }; // in-slice offset [samples]
  std::vector<float> path(count, 0.0f);
  const int n = dims[a];
  const int first = toLight > 0 ? n - 1 : 0;
  auto at = [&](int ia, int ib, int ic)
  {
    int idx[3];
    idx[a] = ia;
    idx[b] = ib;
    idx[c] = ic;
    return idx[0] * stride[0] + idx[1] * stride[1] + idx[2] * stride[2];
  };
  for (int step = 0; step < n; ++step)
  {
    const int slice = first - toLight * step;
#pragma omp parallel for schedule(static)
    for (int ic = 0; ic < dims[c]; ++ic)
    {
      for (int ib = 0; ib < dims[b]; ++ib)
      {
        const std::size_t here = at(slice, ib, ic);
        if (step == 0)
        {
          // From the sample to the volume's face: half a slice.
          path[here] = static_cast<float>(density[here] * 0.5 * segment);
          continue;
        }
        const int previous = slice + toLight;
        // The point one slice toward the light, bilinear in that slice; beyond its sides the
        // light has come in from outside (no density, no path).
        const double pb = ib + shift[0], pc = ic + shift[1];
        const double fb = std::floor(pb), fc = std::floor(pc);
        const double wb = pb - fb, wc = pc - fc;
        double upPath = 0.0, upDensity = 0.0;
        for (int corner = 0; corner < 4; ++corner)
        {
          const int qb = static_cast<int>(fb) + (corner & 1), qc = static_cast<int>(fc) + (corner >> 1);
          const double w = ((corner & 1) ? wb : 1.0 - wb) * ((corner >> 1) ? wc : 1.0 - wc);
          if (w == 0.0 || qb < 0 || qc < 0 || qb >= dims[b] || qc >= dims[c])
          {
            continue;
          }
          const std::size_t q = at(previous, qb, qc);
          upPath += w * path[q];
          upDensity += w * density[q];
        }
        path[here] = static_cast<float>(upPath + 0.5 * (density[here] + upDensity) * segment);
      }
    }
  }
  return path;
}
} // namespace parafluid::clouds
