#pragma once
// Mathematical constants, defined once for every concern (C++17 has no std::numbers).

namespace parafluid
{
constexpr double kPi = 3.14159265358979323846;
/// π rounded to float, for single-precision kernels (the same value float arithmetic used before).
constexpr float kPiF = static_cast<float>(kPi);
} // namespace parafluid
