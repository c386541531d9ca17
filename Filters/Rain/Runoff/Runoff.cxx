#include "parafluid/rain/Runoff.h"

#include "parafluid/rain/GroundSurface.h"
#include "parafluid/rain/RunoffParameterTable.h"
#include "parafluid/sph/SolverRegistry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace parafluid::rain
{
namespace
{
constexpr float kDry = -std::numeric_limits<float>::max();
}

Runoff::Runoff(const RainParameters& rain, const RunoffParameters& runoff, std::shared_ptr<const HeightField> ground)
  : RainSettings(rain)
  , Parameters(runoff)
  , Ground(ground)
  , Rain(rain, ground)
{
  const RunoffParameters& p = this->Parameters;
  const double d = p.particleSpacing;
  double b[4];
  ground->bounds(b);
  if (!(d > 0.0) || !std::isfinite(d) || d > 0.25 * std::min(b[1] - b[0], b[3] - b[2]))
  {
    throw std::invalid_argument("Rain: ParticleSpacing must be positive and at most a quarter of the terrain's width "
                                "(got " +
                                std::to_string(d) + " m)");
  }
  const std::string declared = checkDeclared(runoffParameterTable(), p);
  if (!declared.empty())
  {
    throw std::invalid_argument("Rain: " + declared);
  }
  // The SPH: the ground's box up to the precipitation plane, gravity down, the kernel of SPH Step
  // for this spacing, and a sound speed from the fastest runoff the relief allows.
  sph::SPHParameters& s = this->Resolved;
  s = p.sph;
  const auto& z = ground->elevation();
  const auto [lowest, highest] = std::minmax_element(z.begin(), z.end());
  const double top = std::max(rain.height, static_cast<double>(*highest) + 10.0 * d);
  const sph::SolverEntry& solver = sph::solverEntry(s.pressureSolver);
  s.smoothingLength = sph::defaultSmoothingLength(solver, d, 0.0);
  if (!solver.meshWallInRunoff)
  {
    s.meshWallDensity = false;
  }
  if (s.cflNumber == 0.0f)
  {
    s.cflNumber = RunoffParameters::automaticCFLNumber(s.pressureSolver);
  }
  // The box's floor a kernel radius and a spacing below the lowest ground: the terrain is the
  // floor, and the box floor's mirror images (inside the ground) never reach water above it.
  s.domainBounds = { static_cast<float>(b[0]),
                     static_cast<float>(b[1]),
                     static_cast<float>(b[2]),
                     static_cast<float>(b[3]),
                     static_cast<float>(*lowest - s.smoothingLength - d),
                     static_cast<float>(top) };
  s.gravity = { 0.0f, 0.0f, static_cast<float>(-rain.gravity) };
  s.particleMass = sph::latticeParticleMass(static_cast<float>(d), s.smoothingLength, s.restDensity, s.densityKernel());
  if (!(s.soundSpeed > 0.0f))
  {
    // Ten times the speed of water that ran down the whole relief (at least ten spacings of it).
    const double relief = std::max(static_cast<double>(*highest - *lowest), 10.0 * d);
    s.soundSpeed = static_cast<float>(10.0 * std::sqrt(2.0 * rain.gravity * relief));
  }
  const std::string problem = s.validate();
  if (!problem.empty())
  {
    throw std::invalid_argument("Rain: " + problem);
  }
  this->Boundary = groundBoundary(*ground);
  const auto cells = static_cast<std::size_t>(this->Rain.cellCount());
  this->WaterLevels.assign(cells, kDry);
  this->ImpactCount.assign(cells, 0);
  this->Gathered.assign(cells, 0.0);
  this->Latest.assign(cells, LastImpact{});
  this->Tally.assign(cells, 0);
  this->Soak.assign(cells, 0.0);
}

float RunoffParameters::automaticCFLNumber(sph::PressureSolverType solver)
{
  return sph::solverEntry(solver).runoffCFLNumber;
}

Runoff::~Runoff() = default;
Runoff::Runoff(Runoff&&) noexcept = default;
Runoff& Runoff::operator=(Runoff&&) noexcept = default;

const sph::Simulation* Runoff::water() const
{
  return this->Water.get();
}

double Runoff::particleVolume() const
{
  const double d = this->Parameters.particleSpacing;
  return d * d * d;
}

std::size_t Runoff::particleCount() const
{
  return this->Water ? this->Water->hostState().size() : 0;
}

double Runoff::waitingVolume() const
{
  double sum = 0.0;
  for (double v : this->Gathered)
  {
    sum += v;
  }
  return sum;
}

void Runoff::advance(double duration, const std::function<bool(double)>& progress)
{
  if (!(duration >= 0.0) || !std::isfinite(duration))
  {
    throw std::invalid_argument("Rain: the time to advance must be a non-negative number of seconds");
  }
  const double end = this->Time + duration;
  const double step = this->Parameters.rainStep;
  // A last sliver of a step (the rounding of the sum of steps) is no step: a solver asked to
  // advance 1e-15 s would divide by its square.
  while (end - this->Time > 1e-6 * step)
  {
    const double dt = end - this->Time < 1.000001 * step ? end - this->Time : step;
    this->dropStep(dt);
    if (progress && !progress(duration > 0.0 ? 1.0 - (end - this->Time) / duration : 1.0))
    {
      return;
    }
  }
  this->Time = std::max(this->Time, end);
  // The water catches up with the rain at the end of the span, whatever SPHEvery says.
  if (this->Water && this->Time - this->WaterTime > 1e-6 * step)
  {
    this->SPHSteps += this->Water->advance(this->Time - this->WaterTime);
    this->WaterTime = this->Time;
    this->updateWaterLevels();
  }
}

void Runoff::dropStep(double dt)
{
  const double t = this->Time + dt;
  this->Impacts.clear();
  this->Rain.collectImpacts(t, &this->WaterLevels, this->Counted, this->Impacts);
  // Infiltration takes the rain waiting in the cells before it becomes particles.
  this->gather(this->Impacts);
  if (this->Parameters.infiltration > 0.0)
  {
    this->infiltrate(dt);
  }
  this->makeParticles();
  this->Time = t;
  ++this->DropSteps;
  if (this->Water && this->DropSteps % this->Parameters.sphEvery == 0)
  {
    this->SPHSteps += this->Water->advance(this->Time - this->WaterTime);
    this->WaterTime = this->Time;
    this->updateWaterLevels();
  }
}

void Runoff::gather(const std::vector<Impact>& impacts)
{
  const RunoffParameters& p = this->Parameters;
  for (const Impact& impact : impacts)
  {
    const double water = this->Rain.waterPerImpact(impact.slot);
    this->Fallen += water;
    ++this->ImpactCount[impact.cell];
    if (!p.conserveVolume)
    {
      if (++this->Tally[impact.cell] >= static_cast<std::uint32_t>(p.rainScale))
      {
        this->Tally[impact.cell] = 0;
        this->emit(LastImpact::of(impact), 1, this->Born);
      }
      continue;
    }
    // Each cell keeps the water it gathered and its latest impact, where its particles appear.
    if (this->Latest[impact.cell].step != this->DropSteps)
    {
      this->Touched.push_back(impact.cell);
    }
    this->Latest[impact.cell] = LastImpact::of(impact, this->DropSteps);
    this->Gathered[impact.cell] += water;
    this->Waiting += water;
  }
}

void Runoff::makeParticles()
{
  const double volume = this->particleVolume();
  for (std::uint32_t c : this->Touched)
  {
    // A cell that gathered whole particles' water makes them where its latest drop fell.
    if (this->Gathered[c] >= volume)
    {
      const double whole = std::min(std::floor(this->Gathered[c] / volume), 1e6);
      this->Gathered[c] -= whole * volume;
      this->Waiting -= whole * volume;
      this->emit(this->Latest[c], static_cast<int>(whole), this->Born);
    }
  }
  this->Touched.clear();
  // With Infiltration the cells' remainders are not pooled: a wet cell keeps soaking, so what waits
  // in it (under a particle) goes into the ground.
  if (this->Parameters.conserveVolume && this->Parameters.infiltration == 0.0)
  {
    this->apportionRemainders(this->Born);
  }
  this->addToWater(this->Born);
}

void Runoff::apportionRemainders(NewParticles& born)
{
  // Every cell now holds less than a particle, but together they may hold several: those go to the
  // cells owed the most (the largest-remainder rule, ties to the lower cell), which then owe less
  // than a particle each. So the water waiting over the whole terrain stays under one particle's,
  // and each cell's account under one particle either way, at any rate and any Cells.
  const double volume = this->particleVolume();
  if (this->Waiting < volume)
  {
    return;
  }
  double total = 0.0; // the running sum, refreshed against rounding
  std::vector<std::uint32_t> owed;
  for (std::uint32_t c = 0; c < this->Gathered.size(); ++c)
  {
    total += this->Gathered[c];
    if (this->Gathered[c] > 0.0)
    {
      owed.push_back(c);
    }
  }
  this->Waiting = total;
  const auto due = static_cast<std::size_t>(std::min(std::floor(total / volume), static_cast<double>(owed.size())));
  if (due == 0)
  {
    return;
  }
  auto first = [this](std::uint32_t a, std::uint32_t b)
  { return this->Gathered[a] > this->Gathered[b] || (this->Gathered[a] == this->Gathered[b] && a < b); };
  std::nth_element(owed.begin(), owed.begin() + static_cast<std::ptrdiff_t>(due - 1), owed.end(), first);
  owed.resize(due);
  std::sort(owed.begin(), owed.end()); // the cells' order, not the remainders': the same on every run
  for (std::uint32_t c : owed)
  {
    this->Gathered[c] -= volume;
    this->Waiting -= volume;
    this->emit(this->Latest[c], 1, born);
  }
}

Runoff::LastImpact Runoff::LastImpact::of(const Impact& impact, std::int64_t step)
{
  LastImpact l;
  std::copy(impact.position, impact.position + 3, l.position);
  std::copy(impact.velocity, impact.velocity + 3, l.velocity);
  l.onWater = impact.onWater;
  l.step = step;
  return l;
}

void Runoff::emit(const LastImpact& impact, int count, NewParticles& born)
{
  const RunoffParameters& p = this->Parameters;
  const double volume = this->particleVolume(), d = p.particleSpacing;
  // New particles stay half a spacing inside the SPH's box across the ground: one beyond a side
  // is put back onto it by the solver, where two of them could land millimetres apart (under a
  // cloudburst at a terrain's edge such a pair, pulled together by the film's tension, ran away
  // and blew the run up).
  const auto& box = this->Resolved.domainBounds;
  const double lo[2] = { box[0] + 0.5 * d, box[2] + 0.5 * d };
  const double hi[2] = { box[1] - 0.5 * d, box[3] - 0.5 * d };
  auto inside = [&](double px, double py) { return px >= lo[0] && px <= hi[0] && py >= lo[1] && py <= hi[1]; };
  // The impact itself, kept inside; more than one particle: on a spiral of spacing d around it
  // (the golden angle), so none coincide, skipping the spiral's points outside the box.
  const double centre[2] = { std::clamp(static_cast<double>(impact.position[0]), lo[0], hi[0]),
                             std::clamp(static_cast<double>(impact.position[1]), lo[1], hi[1]) };
  int turn = 0;
  for (int k = 0; k < count; ++k)
  {
    double px = centre[0], py = centre[1];
    for (int tries = 0; tries < 64; ++tries, ++turn)
    {
      const double angle = 2.399963 * turn, radius = d * std::sqrt(static_cast<double>(turn));
      px = centre[0] + radius * std::cos(angle);
      py = centre[1] + radius * std::sin(angle);
      if (inside(px, py))
      {
        break;
      }
    }
    ++turn;
    px = std::clamp(px, lo[0], hi[0]); // a spiral grown past the whole box: on its edge
    py = std::clamp(py, lo[1], hi[1]);
    // Half a spacing above the surface it hit: above the triangulated ground (which the SPH's
    // boundary is) as well as the bilinear one, or on top of the water's highest particle. Never
    // under the ground where the particle goes, which on a slope may be above the water level
    // the drop met (the spiral, or the impact moved inside the box, shifts it sideways): a
    // particle started under the terrain stays there (under a cloudburst into a bowl, 3 runs of
    // 13 with different seeds left one there).
    const double triangulated = triangulatedHeight(*this->Ground, px, py);
    const double ground = std::max(this->Ground->heightAt(px, py), triangulated);
    const double surface = impact.onWater ? std::max(static_cast<double>(impact.position[2]), ground) : ground;
    const double pz = surface + 0.5 * d;
    float v[3] = { impact.velocity[0], impact.velocity[1], impact.velocity[2] };
    if (pz - triangulated < p.sph.smoothingLength)
    {
      // On the ground, or on water too thin to take the drop's momentum (a cell's water level is
      // its highest particle's: a film, or one particle somewhere in the cell), the drop's water
      // keeps only its speed along the ground: it spreads. (The mesh's wall in the SPH's sums
      // would otherwise stop the normal speed elastically and bounce the particle off as a ball.)
      const double e = 0.5 * d;
      const double gx =
        (triangulatedHeight(*this->Ground, px + e, py) - triangulatedHeight(*this->Ground, px - e, py)) / (2 * e);
      const double gy =
        (triangulatedHeight(*this->Ground, px, py + e) - triangulatedHeight(*this->Ground, px, py - e)) / (2 * e);
      const double length = std::sqrt(gx * gx + gy * gy + 1.0);
      const double n[3] = { -gx / length, -gy / length, 1.0 / length };
      const double normal = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
      if (normal < 0.0)
      {
        for (int a = 0; a < 3; ++a)
        {
          v[a] = static_cast<float>(v[a] - normal * n[a]);
        }
      }
    }
    born.x.push_back(static_cast<float>(px));
    born.y.push_back(static_cast<float>(py));
    born.z.push_back(static_cast<float>(pz));
    born.vx.push_back(v[0]);
    born.vy.push_back(v[1]);
    born.vz.push_back(v[2]);
    this->Inserted += volume;
  }
}

void Runoff::addToWater(NewParticles& born)
{
  // Emptied whatever happens: the particles either join the water or are refused with the error.
  NewParticles n = std::move(born);
  born = NewParticles{};
  if (n.x.empty())
  {
    return;
  }
  if (this->particleCount() + n.x.size() > this->Parameters.maxParticles)
  {
    throw std::runtime_error("Rain: the runoff would exceed MaxParticles (" +
                             std::to_string(this->Parameters.maxParticles) +
                             " particles): raise ParticleSpacing or MaxParticles, or shorten the rain");
  }
  if (!this->Water)
  {
    ParticleState state;
    state.x = std::move(n.x), state.y = std::move(n.y), state.z = std::move(n.z);
    state.vx = std::move(n.vx), state.vy = std::move(n.vy), state.vz = std::move(n.vz);
    this->Water = sph::makeSimulation(this->Resolved, std::move(state), this->Boundary, this->Parameters.backend);
    this->WaterTime = this->Time;
  }
  else
  {
    this->Water->addParticles(n.x, n.y, n.z, n.vx, n.vy, n.vz);
  }
}

void Runoff::infiltrate(double dt)
{
  // Each cell soaks up to Infiltration * area * dt of the water it holds: first the rain waiting
  // in it, then whole particles resting on its ground (within 1.5 spacings of it). A dry cell's
  // capacity does not build up.
  const double rate = this->Parameters.infiltration / 3.6e6 * this->Rain.cellArea() * dt;
  const double volume = this->particleVolume(), d = this->Parameters.particleSpacing;
  std::vector<std::vector<std::uint32_t>> resting(this->Gathered.size());
  if (this->Water)
  {
    const ParticleState& s = this->Water->hostState();
    for (std::size_t i = 0; i < s.size(); ++i)
    {
      if (s.z[i] - triangulatedHeight(*this->Ground, s.x[i], s.y[i]) < 1.5 * d)
      {
        resting[this->Rain.cellOf(s.x[i], s.y[i])].push_back(static_cast<std::uint32_t>(i));
      }
    }
  }
  std::vector<std::uint8_t> remove(this->particleCount(), 0);
  std::size_t removing = 0;
  for (std::size_t c = 0; c < this->Gathered.size(); ++c)
  {
    const bool wet = this->Gathered[c] > 0.0 || !resting[c].empty();
    if (!wet)
    {
      this->Soak[c] = 0.0;
      continue;
    }
    this->Soak[c] += rate;
    // A cell that owes water (it made a particle before its rain was all there) has none to give.
    const double taken = std::min(this->Soak[c], std::max(this->Gathered[c], 0.0));
    this->Gathered[c] -= taken;
    this->Waiting -= taken;
    this->Soak[c] -= taken;
    this->Infiltrated += taken;
    for (std::uint32_t i : resting[c])
    {
      if (this->Soak[c] < volume)
      {
        break;
      }
      remove[i] = 1;
      ++removing;
      this->Soak[c] -= volume;
      this->Infiltrated += volume;
    }
  }
  if (removing > 0)
  {
    this->Water->removeParticles(remove);
    if (this->Water->hostState().size() == 0)
    {
      this->Water.reset(); // all soaked up
    }
    this->updateWaterLevels();
  }
}

void Runoff::updateWaterLevels()
{
  std::fill(this->WaterLevels.begin(), this->WaterLevels.end(), kDry);
  if (!this->Water)
  {
    return;
  }
  const ParticleState& s = this->Water->hostState();
  const auto half = static_cast<float>(0.5 * this->Parameters.particleSpacing);
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    float& level = this->WaterLevels[this->Rain.cellOf(s.x[i], s.y[i])];
    level = std::max(level, s.z[i] + half);
  }
}
} // namespace parafluid::rain
