#pragma once
// Stateless rain over a height field (after the seed method's precipitation grid).
//
// The precipitation area is cut into cells; each cell holds a fixed number of drop "slots", in
// proportion to the air column above it (Marshall-Palmer drops per m^3 of air, thinned by
// DropsPerRealDrop), so the number of drops in the air is constant. A slot keeps one diameter
// (drawn from the drops in the air, N(D)) and a period P: the time its drops take to fall from the
// precipitation plane to the lowest ground in the cell. Its k-th drop is born at t = k P - phase and
// meets the ground exactly when the next one is born, at a random point of the cell drawn from
// (seed, slot, k) with a random horizontal velocity: the drop's path is written backwards from that
// target, so its position at any time is one evaluation, nothing is stepped, and a drop born over
// lower ground than the cell's lowest simply starts a little above the plane. Impacts are found on
// the path itself (the first crossing of the bilinear ground, solved piece by piece between grid
// lines), so a fast drop never tunnels through a ridge.
//
// Water is carried by volume: each cell's drops carry, per impact, w_c vol(D) of water with w_c set
// so that the cell receives exactly RainfallRate over time.
#include "parafluid/common/HeightField.h"
#include "parafluid/rain/DropSizeDistribution.h"
#include "parafluid/rain/RainParameters.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace parafluid::rain
{
struct Impact
{
  std::uint32_t slot = 0;
  std::uint32_t cell = 0;
  std::int64_t drop = 0; // k: the slot's k-th drop
  double time = 0.0;     // [s]
  float position[3] = { 0, 0, 0 };
  float velocity[3] = { 0, 0, 0 };
  bool onWater = false;
};

class RainField
{
public:
  /// Throws std::invalid_argument for bad parameters (message names the property), a ground with
  /// NaN heights, or a precipitation plane not above the ground under it.
  RainField(const RainParameters& parameters, std::shared_ptr<const HeightField> ground);

  std::size_t dropCount() const { return this->Diameter.size(); }
  int cellCount() const { return this->Parameters.cells[0] * this->Parameters.cells[1]; }
  const RainParameters& parameters() const { return this->Parameters; }
  const DropSizeDistribution& sizes() const { return this->Sizes; }
  const HeightField& ground() const { return *this->Ground; }
  /// The cell containing (x, y) (clamped to the area).
  std::uint32_t cellOf(double x, double y) const;
  /// Area of one cell [m^2].
  double cellArea() const { return this->CellSize[0] * this->CellSize[1]; }
  void cellSize(double size[2]) const { size[0] = this->CellSize[0], size[1] = this->CellSize[1]; }

  /// Per slot: diameter [m], period [s], water per impact [m^3].
  const std::vector<float>& diameters() const { return this->Diameter; }
  const std::vector<float>& periods() const { return this->Period; }
  double waterPerImpact(std::uint32_t slot) const;

  /// Every drop at time t: positions and velocities (3 floats each, may be null) and whether it is
  /// in the air (above the ground and above `waterLevels`, one height per cell or null). Keeps
  /// each slot's current path between calls (so not for concurrent calls on one field).
  void evaluate(double t, const std::vector<float>* waterLevels, float* position, float* velocity,
                std::uint8_t* inAir) const;
  /// The drop of a slot in the air at time t: position [m] and velocity [m/s], in double precision.
  void drop(std::uint32_t slot, double t, double position[3], double velocity[3]) const;
  /// Where and when drop k of a slot meets the ground or the water of its cell.
  Impact impactOf(std::uint32_t slot, std::int64_t k, const std::vector<float>* waterLevels) const;
  /// The impacts at times in (.., t] of drops after lastCounted[slot] (updated), in slot order; the
  /// runoff's accounting: each drop is counted once even when the water level changes.
  void collectImpacts(double t, const std::vector<float>* waterLevels, std::vector<std::int64_t>& lastCounted,
                      std::vector<Impact>& impacts) const;
  /// The impacts at times in (t - window, t], in slot order (splashes: nothing is stored).
  void recentImpacts(double t, double window, const std::vector<float>* waterLevels,
                     std::vector<Impact>& impacts) const;
  /// Index of the drop of a slot in the air at time t (born at or before t).
  std::int64_t dropAt(std::uint32_t slot, double t) const;

private:
  struct DropPath
  {
    double target[2];     // where it meets the ground [m]
    double ground;        // ground height there [m]
    double horizontal[2]; // horizontal velocity [m/s]
    double birth;         // [s]
  };
  DropPath path(std::uint32_t slot, std::int64_t k) const;
  /// Height of the drop above its target's ground `remaining` seconds before it gets there.
  double heightAbove(std::uint32_t slot, double remaining) const;
  /// Whether drop k of a slot is born before the shower ends (RainParameters::duration).
  bool born(std::uint32_t slot, std::int64_t k) const;
  /// Whether the water of the slot's cell stands above its lowest ground (so it may stop a drop).
  bool mayBeUnderWater(std::uint32_t slot, const std::vector<float>* waterLevels) const;
  /// Vertical velocity [m/s] at time-since-birth s.
  double verticalSpeed(std::uint32_t slot, double s) const;

  RainParameters Parameters;
  std::shared_ptr<const HeightField> Ground;
  DropSizeDistribution Sizes;
  double CellSize[2] = { 1, 1 };
  // Per slot (structure of arrays): its cell, diameter, speed (terminal, or initial), period, phase.
  std::vector<std::uint32_t> Cell;
  std::vector<float> Diameter, Speed, Period, Phase;
  std::vector<double> InversePeriod;
  // The path of the drop each slot had at the last evaluate() (a drop lives for seconds, a frame
  // is a few milliseconds): values of pure functions, so results never depend on what was cached.
  struct DropCache
  {
    std::vector<double> drop, birth; // the drop's index (exact in a double) and birth time [s]
    std::vector<float> targetX, targetY, ground, horizontalX, horizontalY; // float: a frame's precision
    std::vector<std::uint8_t> changed, candidate, inAir;                   // scratch of the passes
    std::vector<float> position, velocity;
  };
  mutable DropCache Cache;
  std::vector<double> CellLowest;      // lowest ground in each cell [m]
  std::vector<std::int64_t> CellStart; // the slots of cell c are CellStart[c] .. CellStart[c + 1] - 1
  std::vector<double> CellWater;       // w_c: real drops per drawn drop in each cell
};
} // namespace parafluid::rain
