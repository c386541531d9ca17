#include "parafluid/common/ParticleState.h"

namespace parafluid
{
void ParticleState::resize(std::size_t n)
{
  for (auto* a : { &x, &y, &z, &vx, &vy, &vz, &ax, &ay, &az, &density, &pressure })
  {
    a->resize(n, 0.0f);
  }
  const std::size_t old = id.size();
  id.resize(n);
  originalIndex.resize(n);
  for (std::size_t i = old; i < n; ++i)
  {
    id[i] = static_cast<std::int64_t>(i);
    originalIndex[i] = static_cast<std::uint32_t>(i);
  }
}

ParticleState ParticleState::atRest(std::vector<float> px, std::vector<float> py, std::vector<float> pz)
{
  ParticleState s;
  const std::size_t n = px.size();
  s.x = std::move(px);
  s.y = std::move(py);
  s.z = std::move(pz);
  s.y.resize(n, 0.0f);
  s.z.resize(n, 0.0f);
  s.resize(n);
  return s;
}

std::size_t ParticleState::bytes() const
{
  std::size_t total = 0;
  for (const auto* a : { &x, &y, &z, &vx, &vy, &vz, &ax, &ay, &az, &density, &pressure })
  {
    total += a->capacity() * sizeof(float);
  }
  return total + id.capacity() * sizeof(std::int64_t) + originalIndex.capacity() * sizeof(std::uint32_t);
}
} // namespace parafluid
