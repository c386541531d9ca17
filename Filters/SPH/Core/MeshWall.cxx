#include "private/MeshWall.h"

#include "private/AnyKernel.h"

#include <algorithm>
#include <cmath>

namespace parafluid::sph::detail
{
namespace
{
constexpr int kSamples = 512; // table entries over [0, reach]: S is smooth (the kernel is C1 or better)
}

MeshWallTable::MeshWallTable(DensityKernel kernel, float h, float spacing)
{
  if (!(h > 0.0f) || !(spacing > 0.0f) || h / spacing > 50.0f)
  {
    return;
  }
  this->Reach = h - 0.5f * spacing;
  if (!(this->Reach > 0.0f))
  {
    return;
  }
  const AnyKernel w(kernel, h);
  const int lateral = static_cast<int>(std::ceil(h / spacing));
  const double step = static_cast<double>(this->Reach) / kSamples;
  this->InverseStep = static_cast<float>(1.0 / step);
  this->Sum.assign(kSamples + 2, 0.0f);
  this->Slope.assign(kSamples + 2, 0.0f);
  this->Count.assign(kSamples + 2, 0.0f);
  for (int k = 0; k <= kSamples; ++k)
  {
    // The particle at height d over the plane; the lattice beyond it in layers at depths
    // d + spacing / 2 + m spacing (a rest lattice whose first layer is half a spacing off the
    // wall mirrors onto exactly these), columns aligned with the particle.
    const double d = k * step;
    double sum = 0.0, slope = 0.0, count = 0.0;
    for (int m = 0; d + (m + 0.5) * spacing < h; ++m)
    {
      const double depth = d + (m + 0.5) * spacing;
      for (int j = -lateral; j <= lateral; ++j)
      {
        for (int i = -lateral; i <= lateral; ++i)
        {
          const double r = std::sqrt(depth * depth + (double(i) * i + double(j) * j) * spacing * spacing);
          if (r >= h)
          {
            continue;
          }
          sum += w.value(static_cast<float>(r));
          slope += w.derivative(static_cast<float>(r)) * depth / r;
          count += 1.0;
        }
      }
    }
    this->Sum[k] = static_cast<float>(sum);
    this->Slope[k] = static_cast<float>(slope);
    this->Count[k] = static_cast<float>(count);
  }
}

MeshWallTableView MeshWallTable::view() const
{
  MeshWallTableView v;
  if (!this->Sum.empty())
  {
    v.sum = this->Sum.data();
    v.slope = this->Slope.data();
    v.count = this->Count.data();
    v.samples = kSamples;
    v.reach = this->Reach;
    v.inverseStep = this->InverseStep;
  }
  return v;
}
} // namespace parafluid::sph::detail
