#pragma once
// Linear dispersion of surface gravity waves: how fast a wave of a given wavenumber travels in
// water of a given depth, and how a wave's wavenumber changes as it runs into shallower water
// (its frequency is conserved, so omega^2 = g k_deep = g k tanh(k h) fixes the local k).
#include <limits>

namespace parafluid::ocean
{
constexpr double kStandardGravity = 9.81;                              // [m/s^2]
constexpr double kDeepWater = std::numeric_limits<double>::infinity(); // depth meaning "no bottom"

/// Angular frequency omega [rad/s] of a wave of wavenumber k [rad/m] in water `depth` metres deep:
/// omega^2 = g k tanh(k h); deep water (depth infinite) gives omega^2 = g k.
double angularFrequency(double k, double depth, double gravity = kStandardGravity);

/// Phase (crest) speed omega / k [m/s].
double phaseSpeed(double k, double depth, double gravity = kStandardGravity);

/// The local wavenumber k [rad/m] of a wave whose deep-water wavenumber is kDeep, in water `depth`
/// metres deep: the root of k tanh(k h) = kDeep, by Newton's method from the closed form below
/// (relative error under 1e-12). Infinite depth returns kDeep; depth <= 0 (land) is not allowed.
double shoalingWavenumber(double kDeep, double depth);

/// Closed form kDeep / sqrt(tanh(kDeep h)): exact in deep and in very shallow water, and within
/// 5.0 % of shoalingWavenumber in between (4.98 % at kDeep h = 0.69; see WaveDispersionTest).
double shoalingWavenumberApproximation(double kDeep, double depth);
} // namespace parafluid::ocean
