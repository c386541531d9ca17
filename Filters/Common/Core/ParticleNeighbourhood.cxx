#include "parafluid/common/ParticleNeighbourhood.h"

namespace parafluid
{
void ParticleNeighbourhood::build(const float* xyz, std::size_t n, float radius)
{
  std::vector<float> x(n), y(n), z(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    x[i] = xyz[3 * i];
    y[i] = xyz[3 * i + 1];
    z[i] = xyz[3 * i + 2];
  }
  this->Grid.build(x.data(), y.data(), z.data(), n, radius);
  this->Radius = radius;
  const std::vector<std::uint32_t>& order = this->Grid.sortedOrder();
  this->Sorted.resize(3 * n);
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::uint32_t i = order[k];
    this->Sorted[3 * k] = x[i];
    this->Sorted[3 * k + 1] = y[i];
    this->Sorted[3 * k + 2] = z[i];
  }
}
} // namespace parafluid
