#pragma once
// Fournier, Fussell & Carpenter's (1982) midpoint displacement in its diamond-square form on a
// (2^n + 1)^2 grid: each level sets square centres (diamond step), then edge midpoints (square
// step), to the mean of their parents plus a random displacement whose amplitude shrinks by
// 2^-H per level, H being the roughness (Hurst exponent; power spectrum ~ k^(-2H-1) along a line).
#include <cstdint>
#include <vector>

namespace parafluid::terrain
{
/// Values on a size x size grid (size = 2^levels + 1, x fastest), scaled so max |value| = 1. Every
/// displacement is a hash of (seed, node), so the result does not depend on the thread count.
/// Throws std::invalid_argument for levels outside 1..15 or H outside [0, 2].
std::vector<float> diamondSquare(int levels, double roughness, std::uint64_t seed);

/// The smallest n with 2^n + 1 >= points.
int diamondSquareLevels(int points);
} // namespace parafluid::terrain
