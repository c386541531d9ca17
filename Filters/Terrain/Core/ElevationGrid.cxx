#include "parafluid/terrain/ElevationGrid.h"

#include <cmath>
#include <stdexcept>

namespace parafluid::terrain
{
std::string ElevationGrid::problem() const
{
  if (nx < 2 || ny < 2)
  {
    return "the terrain needs at least 2 x 2 samples, got " + std::to_string(nx) + " x " + std::to_string(ny);
  }
  if (!(dx > 0.0 && dy > 0.0 && std::isfinite(dx) && std::isfinite(dy)))
  {
    return "the terrain's spacing must be positive and finite, got " + std::to_string(dx) + " x " + std::to_string(dy);
  }
  if (elevation.size() != size())
  {
    return "the terrain has " + std::to_string(elevation.size()) + " elevations for " + std::to_string(nx) + " x " +
           std::to_string(ny) + " samples";
  }
  for (std::size_t k = 0; k < elevation.size(); ++k)
  {
    if (!std::isfinite(elevation[k]))
    {
      return "the terrain's elevation is not finite at sample " + std::to_string(k) +
             " (mark no-data with Terrain From Image's NoDataValue)";
    }
  }
  return {};
}

std::size_t fillNoData(std::vector<float>& values, int nx, int ny, std::vector<unsigned char> valid)
{
  const std::size_t n = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  if (nx < 1 || ny < 1 || values.size() != n || valid.size() != n)
  {
    throw std::invalid_argument("no-data filling: the mask and the values must both have nx * ny entries");
  }
  std::size_t missing = 0;
  for (const unsigned char v : valid)
  {
    missing += v ? 0 : 1;
  }
  if (missing == n)
  {
    throw std::invalid_argument("every sample is no-data: there is no elevation to build a terrain from");
  }
  const std::size_t total = missing;
  std::vector<std::size_t> ring;
  while (missing > 0)
  {
    ring.clear();
    for (int j = 0; j < ny; ++j)
    {
      for (int i = 0; i < nx; ++i)
      {
        const std::size_t k = static_cast<std::size_t>(j) * nx + i;
        if (valid[k])
        {
          continue;
        }
        double sum = 0.0;
        int count = 0;
        for (int dj = -1; dj <= 1; ++dj)
        {
          for (int di = -1; di <= 1; ++di)
          {
            const int a = i + di, b = j + dj;
            if ((di || dj) && a >= 0 && a < nx && b >= 0 && b < ny && valid[static_cast<std::size_t>(b) * nx + a])
            {
              sum += values[static_cast<std::size_t>(b) * nx + a], ++count;
            }
          }
        }
        if (count > 0)
        {
          values[k] = static_cast<float>(sum / count);
          ring.push_back(k);
        }
      }
    }
    // The ring becomes valid only after the sweep, so the filling does not depend on sweep order.
    for (const std::size_t k : ring)
    {
      valid[k] = 1;
    }
    missing -= ring.size();
  }
  return total;
}
} // namespace parafluid::terrain
