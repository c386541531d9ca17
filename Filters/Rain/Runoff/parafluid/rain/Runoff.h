#pragma once
// Rain that becomes SPH water (after the seed method): the stateless drops of RainField fall on a
// height field; in each precipitation cell the water of the impacts is gathered and becomes SPH
// particles at the impact points, with the drops' velocities, and SPH Step's solver moves them
// with the triangulated ground as their boundary.
//  - ConserveVolume (default): every particle carries d^3 of water (d the particle spacing); a cell
//    inserts one whenever the rain it gathered reaches d^3, and the cells' remainders, once they add
//    up to a particle, become particles in the cells owed the most; so the water in the SPH equals
//    the rain that fell within one particle's volume over the whole terrain, at any rate and Cells.
//    (With Infiltration the remainders are not pooled: they soak into the ground of their cell.)
//  - Otherwise the seed's rule: one particle every RainScale impacts in a cell.
//  - The drops step by `rainStep`; the SPH advances once every `sphEvery` drop steps, with the
//    impacts of those steps gathered.
//  - Infiltration [mm/h] takes water from wet cells (first the rain waiting in the cell, then
//    particles resting on its ground), so runoff starts only where the rain outpaces it.
//  - The water's surface (per cell, the highest particle plus half a spacing) stops later drops.
#include "parafluid/common/HeightField.h"
#include "parafluid/rain/RainField.h"
#include "parafluid/sph/SPHParameters.h"
#include "parafluid/sph/Simulation.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace parafluid
{
class TriangleBoundary;
}

namespace parafluid::rain
{
struct RunoffParameters
{
  /// The solver's settings; smoothingLength, particleMass, domainBounds, gravity and (when 0) the
  /// sound speed and the CFL number are derived from the spacing, the ground, the precipitation
  /// area and the solver. DFSPH, and water that keeps none of its normal velocity when it meets the
  /// ground (a drop's water spreads; it does not bounce as a ball).
  sph::SPHParameters sph = runoffDefaults();
  static sph::SPHParameters runoffDefaults()
  {
    sph::SPHParameters p;
    // DFSPH, not SPH Step's δ-SPH: with the terrain a wall in its sums its water pools at the level
    // its volume gives (a bowl's pond within a quarter of a spacing of it), where δ-SPH's integrated
    // density lets the pond drain into a film over the bowl (docs/design-notes.md). Its
    // step costs about six of δ-SPH's (14k runoff particles: 30 against 5 ms on 2 cores), within
    // the frame rate asked of rain with runoff (Testing/Benchmarks/README.md, Rain).
    p.pressureSolver = sph::PressureSolverType::DFSPH;
    p.boundaryDamping = 1.0f;
    p.cflNumber = 0.0f; // automaticCFLNumber(pressureSolver)
    return p;
  }
  /// The CFL number a cflNumber of 0 stands for: the solver's registry entry's runoffCFLNumber.
  static float automaticCFLNumber(sph::PressureSolverType solver);
  double particleSpacing = 0.05; // d [m]
  bool conserveVolume = true;
  int rainScale = 10;           // impacts per particle without ConserveVolume
  int sphEvery = 1;             // drop steps per SPH advance
  double rainStep = 1.0 / 60.0; // [s]
  double infiltration = 0.0;    // [mm/h]
  std::size_t maxParticles = 4000000;
  /// Where the water's SPH runs (sph::makeSimulation; the CUDA backend runs δ-SPH, not yet the
  /// default DFSPH, which Automatic runs on the CPU).
  sph::Backend backend = sph::Backend::Automatic;
};

class Runoff
{
public:
  /// Throws std::invalid_argument for bad parameters (naming the property).
  Runoff(const RainParameters& rain, const RunoffParameters& runoff, std::shared_ptr<const HeightField> ground);
  ~Runoff();
  Runoff(Runoff&&) noexcept;
  Runoff& operator=(Runoff&&) noexcept;

  /// Advances `duration` seconds in drop steps (the last shortened to land on the end); progress
  /// as sph::Simulation::advance. Throws std::runtime_error when the SPH becomes unstable, or when the
  /// water would exceed maxParticles.
  void advance(double duration, const std::function<bool(double)>& progress = {});

  double time() const { return this->Time; }
  const RainField& rain() const { return this->Rain; }
  const RunoffParameters& parameters() const { return this->Parameters; }
  /// The SPH water, or null before the first particle.
  const sph::Simulation* water() const;
  /// The solver's settings as resolved from the parameters (what the water is stepped with).
  const sph::SPHParameters& sphParameters() const { return this->Resolved; }
  /// Per precipitation cell: the water surface [m] (lowest float when dry), and its impacts so far.
  const std::vector<float>& waterLevels() const { return this->WaterLevels; }
  const std::vector<std::uint32_t>& impactCounts() const { return this->ImpactCount; }
  /// Volumes [m^3]: rain that reached the ground or the water, water inserted as particles, taken by
  /// infiltration, and still waiting in the cells.
  double fallenVolume() const { return this->Fallen; }
  double insertedVolume() const { return this->Inserted; }
  double infiltratedVolume() const { return this->Infiltrated; }
  double waitingVolume() const;
  /// Per precipitation cell, the rain it gathered less the particles it made [m^3] (ConserveVolume):
  /// under one particle's volume either way.
  const std::vector<double>& cellAccounts() const { return this->Gathered; }
  /// Volume of one particle's water [m^3] (d^3).
  double particleVolume() const;
  std::size_t particleCount() const;
  /// SPH steps taken so far.
  std::int64_t sphSteps() const { return this->SPHSteps; }

private:
  /// A cell's latest impact: where its next particle appears.
  struct LastImpact
  {
    float position[3] = { 0, 0, 0 };
    float velocity[3] = { 0, 0, 0 };
    bool onWater = false;
    std::int64_t step = -1; // the drop step that recorded it
    static LastImpact of(const Impact& impact, std::int64_t step = -1);
  };
  struct NewParticles
  {
    std::vector<float> x, y, z, vx, vy, vz;
  };
  void dropStep(double dt);
  /// Adds the impacts' water to their cells (ConserveVolume), or counts them (RainScale).
  void gather(const std::vector<Impact>& impacts);
  /// Turns the water the cells gathered into particles and adds them to the SPH.
  void makeParticles();
  void apportionRemainders(NewParticles& born);
  /// `count` particles of d^3 at and around an impact, on the ground or the water it hit.
  void emit(const LastImpact& impact, int count, NewParticles& born);
  void addToWater(NewParticles& born);
  void infiltrate(double dt);
  void updateWaterLevels();

  RainParameters RainSettings;
  RunoffParameters Parameters;
  std::shared_ptr<const HeightField> Ground;
  RainField Rain;
  sph::SPHParameters Resolved;
  std::shared_ptr<const TriangleBoundary> Boundary;
  std::unique_ptr<sph::Simulation> Water;
  double Time = 0.0, WaterTime = 0.0;
  std::int64_t DropSteps = 0, SPHSteps = 0;
  std::vector<std::int64_t> Counted;
  std::vector<float> WaterLevels;
  std::vector<std::uint32_t> ImpactCount;
  std::vector<double> Gathered;       // water each cell is owed [m^3], under d^3 either way (ConserveVolume)
  std::vector<LastImpact> Latest;     // each cell's latest impact (ConserveVolume)
  double Waiting = 0.0;               // the sum of Gathered [m^3], in [0, d^3) after each drop step
  std::vector<std::uint32_t> Touched; // cells with impacts in this drop step
  NewParticles Born;                  // particles made in this drop step
  std::vector<std::uint32_t> Tally;   // impacts since the cell's last particle (RainScale)
  std::vector<double> Soak;           // infiltration capacity each wet cell has built up [m^3]
  double Fallen = 0.0, Inserted = 0.0, Infiltrated = 0.0;
  std::vector<Impact> Impacts;
};
} // namespace parafluid::rain
