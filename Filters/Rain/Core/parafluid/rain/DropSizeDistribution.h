#pragma once
// Raindrop sizes and speeds.
//  - Marshall & Palmer (1948): drops per volume of air per diameter N(D) = N0 exp(-Lambda D), with
//    Lambda = 4.1 R^-0.21 per mm for a rainfall rate R in mm/h (their N0 is 8000 m^-3 mm^-1).
//  - Atlas, Srivastava & Sekhon (1973): terminal fall speed v(D) = 9.65 - 10.3 exp(-0.6 D) m/s
//    (D in mm), which falls to zero near 0.11 mm; drops are drawn between 0.2 mm (0.5 m/s) and
//    6 mm (larger drops break up).
// With Atlas's speeds and Marshall-Palmer's N0, the water the distribution carries is not exactly R
// (the law is a fit): N0 here is chosen so that the volume flux integral of N v pi D^3 / 6 equals R,
// and nominalN0Ratio() says how far that is from 8000.
#include <cstdint>

namespace parafluid::rain
{
class DropSizeDistribution
{
public:
  static constexpr double kMinDiameter = 0.2e-3;     // [m]
  static constexpr double kMaxDiameter = 6.0e-3;     // [m]
  static constexpr double kMarshallPalmerN0 = 8.0e6; // [m^-4] = 8000 m^-3 mm^-1

  /// rainfall rate R [mm/h] > 0. Throws std::invalid_argument otherwise.
  explicit DropSizeDistribution(double rainfallRate);

  /// Lambda [1/m].
  double slope() const { return this->Lambda; }
  /// N0 [m^-4], normalised so the volume flux equals the rainfall rate.
  double intercept() const { return this->N0; }
  /// N0 over Marshall & Palmer's 8000 m^-3 mm^-1.
  double nominalN0Ratio() const { return this->N0 / kMarshallPalmerN0; }
  /// N(D) [m^-4] for D in metres.
  double density(double diameter) const;
  /// Drops per cubic metre of air (between the diameter limits) [m^-3].
  double dropsPerVolume() const { return this->DropsPerVolume; }
  /// Drops reaching the ground per square metre per second [m^-2 s^-1].
  double dropsPerAreaTime() const { return this->NumberFlux; }
  /// Rainfall rate [m/s] (R mm/h / 3.6e6).
  double rate() const { return this->Rate; }

  /// The diameter [m] at cumulative fraction u in [0, 1) of the drops in the air: the inverse of
  /// the truncated exponential's distribution function.
  double diameterAt(double u) const;
  /// The fraction of the drops in the air with diameter below D.
  double cumulative(double diameter) const;

  /// Atlas et al.'s terminal speed [m/s] of a drop of diameter D [m] (at least 0.1 m/s).
  static double terminalSpeed(double diameter);
  /// Volume [m^3] of a drop of diameter D [m].
  static double volume(double diameter);

private:
  double Rate = 0.0, Lambda = 0.0, N0 = 0.0, DropsPerVolume = 0.0, NumberFlux = 0.0;
};
} // namespace parafluid::rain
