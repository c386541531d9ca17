#pragma once
#include <chrono>

namespace parafluid::validation
{
/// Wall-clock seconds since construction.
class SceneTimer
{
public:
  double seconds() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - this->Start).count();
  }

private:
  std::chrono::steady_clock::time_point Start = std::chrono::steady_clock::now();
};
} // namespace parafluid::validation
