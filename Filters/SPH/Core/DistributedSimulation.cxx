// A distributed run's process (DistributedSimulation.h): the CPU simulation of its slab, the ghost
// layer it asks for neighbours' values, and the hand-over of particles after every step.
#include "parafluid/sph/DistributedSimulation.h"

#include "parafluid/sph/InitialState.h"
#include "parafluid/sph/SPHSolver.h"
#include "parafluid/sph/SolverRegistry.h"
#include "parafluid/sph/TimeStepControl.h"
#include "private/SlabDecomposition.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <stdexcept>

namespace parafluid::sph
{
namespace
{
using Bytes = std::vector<std::uint8_t>;

template<typename T>
void put(Bytes& out, const T* values, std::size_t count)
{
  const std::size_t at = out.size();
  out.resize(at + count * sizeof(T));
  if (count > 0)
  {
    std::memcpy(out.data() + at, values, count * sizeof(T));
  }
}

template<typename T>
void take(const Bytes& in, std::size_t& at, T* values, std::size_t count)
{
  if (at + count * sizeof(T) > in.size())
  {
    throw std::logic_error("SPH: a distributed run's message is shorter than its header says");
  }
  if (count > 0)
  {
    std::memcpy(values, in.data() + at, count * sizeof(T));
  }
  at += count * sizeof(T);
}

/// Particles `which` of the columns, ids and indices as one message: the count, the number of
/// columns, each column's values, the ids, the original indices.
Bytes packRows(const std::vector<const std::vector<float>*>& columns, const std::vector<std::int64_t>& id,
               const std::vector<std::uint32_t>& index, const std::vector<std::uint32_t>& which)
{
  Bytes out;
  const std::uint64_t header[2] = { which.size(), columns.size() };
  put(out, header, 2);
  std::vector<float> f(which.size());
  for (const std::vector<float>* column : columns)
  {
    for (std::size_t k = 0; k < which.size(); ++k)
    {
      f[k] = (*column)[which[k]];
    }
    put(out, f.data(), f.size());
  }
  std::vector<std::int64_t> ids(which.size());
  std::vector<std::uint32_t> indices(which.size());
  for (std::size_t k = 0; k < which.size(); ++k)
  {
    ids[k] = id[which[k]];
    indices[k] = index[which[k]];
  }
  put(out, ids.data(), ids.size());
  put(out, indices.data(), indices.size());
  return out;
}

/// Appends a packRows message to `rows` (whose column count it must have); returns its count.
std::size_t unpackRows(const Bytes& in, ParticleRows& rows)
{
  if (in.empty())
  {
    return 0;
  }
  std::size_t at = 0;
  std::uint64_t header[2];
  take(in, at, header, 2);
  if (header[1] != rows.columns.size())
  {
    throw std::logic_error("SPH: a distributed run's processes carry different columns");
  }
  const auto count = static_cast<std::size_t>(header[0]);
  for (std::vector<float>& column : rows.columns)
  {
    const std::size_t from = column.size();
    column.resize(from + count);
    take(in, at, column.data() + from, count);
  }
  const std::size_t from = rows.id.size();
  rows.id.resize(from + count);
  rows.originalIndex.resize(from + count);
  take(in, at, rows.id.data() + from, count);
  take(in, at, rows.originalIndex.data() + from, count);
  return count;
}

std::vector<const std::vector<float>*> constant(const std::vector<std::vector<float>*>& columns)
{
  return { columns.begin(), columns.end() };
}

std::vector<const std::vector<float>*> constant(const std::vector<std::vector<float>>& columns)
{
  std::vector<const std::vector<float>*> out;
  for (const std::vector<float>& c : columns)
  {
    out.push_back(&c);
  }
  return out;
}

/// The exclusive prefix over the processes of `count` (this process's first global number) and
/// the total.
std::pair<double, double> prefixOf(double count, Communicator& communicator)
{
  std::vector<double> counts(static_cast<std::size_t>(communicator.size()), 0.0);
  counts[static_cast<std::size_t>(communicator.rank())] = count;
  communicator.reduce(counts, Reduction::Sum);
  const double before = std::accumulate(counts.begin(), counts.begin() + communicator.rank(), 0.0);
  return { before, std::accumulate(counts.begin(), counts.end(), 0.0) };
}

/// Throws on every process when any refused (`anyRefused`): its own problem, or that another refused.
void refuseTogether(const std::string& problem, bool anyRefused)
{
  if (anyRefused)
  {
    throw std::invalid_argument(problem.empty() ? "SPH: another process of the distributed run refused its particles"
                                                : problem);
  }
}

class DistributedSimulation final
  : public Simulation
  , public GhostLayer
{
public:
  DistributedSimulation(const SPHParameters& parameters, ParticleState piece,
                        std::shared_ptr<const TriangleBoundary> boundary, Communicator& communicator);

  std::int64_t advance(double duration, const std::function<bool(double)>& progress) override;
  void addParticles(const std::vector<float>& x, const std::vector<float>& y, const std::vector<float>& z,
                    const std::vector<float>& vx, const std::vector<float>& vy, const std::vector<float>& vz) override;
  std::size_t removeParticles(const std::vector<std::uint8_t>& remove) override;
  const ParticleState& hostState() const override;
  std::vector<float> smoothedPressure() const override { return this->own(this->Solver->smoothedPressure()); }
  std::vector<std::uint32_t> neighbourCounts() const override { return this->own(this->Solver->neighbourCounts()); }
  const SPHParameters& parameters() const override { return this->Solver->parameters(); }
  const StepStatistics& lastStep() const override { return this->Solver->lastStep(); }
  double time() const override { return this->Time; }
  std::int64_t stepCount() const override { return this->Solver->stepCount(); }
  double proposedTimeStep() const override { return this->Solver->proposedTimeStep(); }
  double kineticEnergy() const override { return this->Solver->kineticEnergy(); }
  double bytesPerParticle() const override { return this->Solver->bytesPerParticle(); }
  std::string stabilityAdvice() const override { return this->Solver->stabilityAdvice(); }
  const char* backendName() const override { return "CPU (distributed)"; }

  // GhostLayer
  const std::vector<std::uint8_t>& ghostFlags() const override { return this->Flags; }
  void refresh(std::initializer_list<float*> columns) override { this->refreshColumns(columns); }
  void permuted(const std::vector<std::uint32_t>& order) override;
  double sum(double value) override { return this->Comm.reduce(value, Reduction::Sum); }
  double min(double value) override { return this->Comm.reduce(value, Reduction::Min); }
  double max(double value) override { return this->Comm.reduce(value, Reduction::Max); }

private:
  /// Sends each particle of `rows` to the process that owns its slab; returns what this one owns.
  ParticleRows handOver(const ParticleRows& rows);
  /// Sends copies of this process's particles (the first `own` of the columns) to the processes
  /// whose slab they are within reach of; records whom each goes to and where each received ghost
  /// lands (after `own`); returns the received ghosts.
  ParticleRows gatherGhosts(const std::vector<const std::vector<float>*>& columns, const std::vector<std::int64_t>& id,
                            const std::vector<std::uint32_t>& index, std::size_t own, std::size_t columnCount);
  /// After a step, an addition or a removal (ghosts dropped): the cuts balanced if need be, the
  /// particles that left the slab handed over, the ghosts gathered and the state sorted.
  void redistribute();
  void dropGhosts();
  /// The values of this process's own particles, in state order.
  template<typename T>
  std::vector<T> own(const std::vector<T>& all) const;
  /// Every carried column of the ghosts from their owners: after each step, and after a start,
  /// whose accelerations the force passes compute for own particles only.
  void refreshCarried();
  /// The ghosts' values of `columns` from their owners.
  template<class Columns>
  void refreshColumns(const Columns& columns);
  /// How far the particles moved in the step of `dt` at most, over the processes [m]; throws on
  /// every process when that is further than the ghosts reach.
  double checkReach(double dt);
  /// After a step: while the particles have moved less than the margin since the ghosts were
  /// gathered, the ghosts keep their particles and take their owners' new state; else the
  /// particles are handed over and the ghosts gathered afresh.
  void afterStep(double moved);

  Communicator& Comm;
  SPHParameters Parameters;
  float Reach = 0.0f;  // [m] how far from its slab a particle is this process's ghost
  float Margin = 0.0f; // [m] what the particles may move between gatherings: (Reach - support) / 2
  double Moved = 0.0;  // [m] the most a particle has moved since the ghosts were gathered
  std::unique_ptr<detail::SlabDecomposition> Slabs;
  std::vector<std::uint8_t> Flags;
  // SendIndex[r]: this process's particles whose ghosts process r holds, in the order r keeps
  // them at RecvIndex[this process] (state indices on each side).
  std::vector<std::vector<std::uint32_t>> SendIndex, RecvIndex;
  std::unique_ptr<SPHSolver> Solver;
  double Time = 0.0;
  mutable ParticleState Own;
  mutable bool OwnFresh = false;
};

DistributedSimulation::DistributedSimulation(const SPHParameters& parameters, ParticleState piece,
                                             std::shared_ptr<const TriangleBoundary> boundary,
                                             Communicator& communicator)
  : Comm(communicator)
  , Parameters(parameters)
{
  const auto size = static_cast<std::size_t>(communicator.size());
  this->SendIndex.resize(size);
  this->RecvIndex.resize(size);
  // Every process checks its own input, and all refuse together if one does (none is left waiting).
  std::string problem = distributedRunLacks(parameters);
  if (problem.empty())
  {
    problem = parameters.validate();
    problem = problem.empty() ? problem : "SPH: " + problem;
  }
  const std::size_t n = piece.size();
  const bool givenIds = piece.id.size() == n;
  const bool givenDensity = piece.density.size() == n;
  try
  {
    if (problem.empty())
    {
      completeInitialState(piece);
    }
  }
  catch (const std::exception& e)
  {
    problem = e.what();
  }
  std::vector<double> agreed = { problem.empty() ? 0.0 : 1.0, givenIds || n == 0 ? 0.0 : 1.0,
                                 givenDensity || n == 0 ? 0.0 : 1.0 };
  communicator.reduce(agreed, Reduction::Max);
  refuseTogether(problem, agreed[0] > 0.0);
  // Numbers across the processes in rank order: original indices always, ids unless all gave them.
  const double first = prefixOf(static_cast<double>(n), communicator).first;
  for (std::size_t i = 0; i < n; ++i)
  {
    piece.originalIndex[i] = static_cast<std::uint32_t>(first) + static_cast<std::uint32_t>(i);
    if (agreed[1] > 0.0)
    {
      piece.id[i] = static_cast<std::int64_t>(first) + static_cast<std::int64_t>(i);
    }
  }
  const std::vector<float>* position[3] = { &piece.x, &piece.y, &piece.z };
  this->Slabs = std::make_unique<detail::SlabDecomposition>(parameters, position, communicator);
  // A step moves a particle by far less than a tenth of the support (the CFL condition), shifting
  // by 0.2 spacings more: ghosts within the support and two margins of a quarter support each.
  this->Margin = 0.25f * parameters.smoothingLength;
  this->Reach = parameters.smoothingLength + 2.0f * this->Margin;

  ParticleRows rows;
  rows.columns = { std::move(piece.x),  std::move(piece.y),  std::move(piece.z),
                   std::move(piece.vx), std::move(piece.vy), std::move(piece.vz) };
  if (agreed[2] == 0.0)
  {
    rows.columns.push_back(std::move(piece.density));
  }
  rows.id = std::move(piece.id);
  rows.originalIndex = std::move(piece.originalIndex);
  ParticleRows owned = this->handOver(rows);
  const std::size_t own = owned.size();
  const ParticleRows ghosts =
    this->gatherGhosts(constant(owned.columns), owned.id, owned.originalIndex, own, owned.columns.size());
  ParticleState state;
  std::vector<float>* into[] = { &state.x, &state.y, &state.z, &state.vx, &state.vy, &state.vz, &state.density };
  for (std::size_t c = 0; c < owned.columns.size(); ++c)
  {
    *into[c] = std::move(owned.columns[c]);
    into[c]->insert(into[c]->end(), ghosts.columns[c].begin(), ghosts.columns[c].end());
  }
  state.id = std::move(owned.id);
  state.id.insert(state.id.end(), ghosts.id.begin(), ghosts.id.end());
  state.originalIndex = std::move(owned.originalIndex);
  state.originalIndex.insert(state.originalIndex.end(), ghosts.originalIndex.begin(), ghosts.originalIndex.end());
  this->Flags.assign(own, 0);
  this->Flags.resize(own + ghosts.size(), 1);
  // Two particles at one place are on the same processes (an owner and its ghosts' holders).
  problem.clear();
  try
  {
    checkCoincident(state);
  }
  catch (const std::exception& e)
  {
    problem = e.what();
  }
  refuseTogether(problem, this->max(problem.empty() ? 0.0 : 1.0) > 0.0);
  this->Solver = std::make_unique<SPHSolver>(parameters, std::move(state), std::move(boundary), this);
  this->refreshCarried();
}

void DistributedSimulation::refreshCarried()
{
  std::vector<float*> columns;
  for (std::vector<float>* column : this->Solver->carriedColumns())
  {
    columns.push_back(column->data());
  }
  this->refreshColumns(columns);
}

ParticleRows DistributedSimulation::handOver(const ParticleRows& rows)
{
  const auto size = static_cast<std::size_t>(this->Comm.size());
  const int axis = this->Slabs->axis();
  std::vector<std::vector<std::uint32_t>> which(size);
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    which[static_cast<std::size_t>(this->Slabs->owner(rows.columns[static_cast<std::size_t>(axis)][i]))].push_back(
      static_cast<std::uint32_t>(i));
  }
  std::vector<Bytes> sends(size);
  const std::vector<const std::vector<float>*> columns = constant(rows.columns);
  for (std::size_t r = 0; r < size; ++r)
  {
    if (!which[r].empty())
    {
      sends[r] = packRows(columns, rows.id, rows.originalIndex, which[r]);
    }
  }
  const std::vector<Bytes> received = this->Comm.exchange(sends);
  ParticleRows owned;
  owned.columns.resize(rows.columns.size());
  for (const Bytes& message : received)
  {
    unpackRows(message, owned);
  }
  return owned;
}

ParticleRows DistributedSimulation::gatherGhosts(const std::vector<const std::vector<float>*>& columns,
                                                 const std::vector<std::int64_t>& id,
                                                 const std::vector<std::uint32_t>& index, std::size_t own,
                                                 std::size_t columnCount)
{
  const auto size = static_cast<std::size_t>(this->Comm.size());
  const auto me = this->Comm.rank();
  const std::vector<float>& coordinate = *columns[static_cast<std::size_t>(this->Slabs->axis())];
  for (auto& list : this->SendIndex)
  {
    list.clear();
  }
  for (std::size_t i = 0; i < own; ++i)
  {
    const auto [firstRank, lastRank] = this->Slabs->within(coordinate[i], this->Reach);
    for (int r = firstRank; r < lastRank; ++r)
    {
      if (r != me)
      {
        this->SendIndex[static_cast<std::size_t>(r)].push_back(static_cast<std::uint32_t>(i));
      }
    }
  }
  std::vector<Bytes> sends(size);
  for (std::size_t r = 0; r < size; ++r)
  {
    if (!this->SendIndex[r].empty())
    {
      sends[r] = packRows(columns, id, index, this->SendIndex[r]);
    }
  }
  const std::vector<Bytes> received = this->Comm.exchange(sends);
  ParticleRows ghosts;
  ghosts.columns.resize(columnCount);
  for (std::size_t r = 0; r < size; ++r)
  {
    const std::size_t from = own + ghosts.size();
    const std::size_t count = unpackRows(received[r], ghosts);
    this->RecvIndex[r].resize(count);
    std::iota(this->RecvIndex[r].begin(), this->RecvIndex[r].end(), static_cast<std::uint32_t>(from));
  }
  return ghosts;
}

void DistributedSimulation::dropGhosts()
{
  this->Solver->takeRows(this->Flags);
  this->Flags.assign(this->Solver->state().size(), 0);
  for (auto& list : this->RecvIndex)
  {
    list.clear();
  }
  this->OwnFresh = false;
}

void DistributedSimulation::redistribute()
{
  const ParticleState& s = this->Solver->state();
  const std::vector<float>* position[3] = { &s.x, &s.y, &s.z };
  const std::vector<float>& coordinate = *position[this->Slabs->axis()];
  // The cuts move when one process holds a fifth more than the mean (a thousand particles' slack).
  std::vector<double> counts(static_cast<std::size_t>(this->Comm.size()), 0.0);
  counts[static_cast<std::size_t>(this->Comm.rank())] = static_cast<double>(s.size());
  this->Comm.reduce(counts, Reduction::Sum);
  const double mean = std::accumulate(counts.begin(), counts.end(), 0.0) / static_cast<double>(counts.size());
  if (*std::max_element(counts.begin(), counts.end()) > 1.2 * mean + 1000.0 / static_cast<double>(counts.size()))
  {
    this->Slabs->balance(coordinate, this->Comm);
  }
  std::vector<std::uint8_t> leaving(s.size(), 0);
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    leaving[i] = this->Slabs->owner(coordinate[i]) != this->Comm.rank() ? 1 : 0;
  }
  const ParticleRows gone = this->Solver->takeRows(leaving);
  this->Solver->appendRows(this->handOver(gone));
  const std::size_t own = this->Solver->state().size();
  const std::vector<std::vector<float>*> columns = this->Solver->carriedColumns();
  const ParticleRows ghosts = this->gatherGhosts(constant(columns), this->Solver->state().id,
                                                 this->Solver->state().originalIndex, own, columns.size());
  this->Solver->appendRows(ghosts);
  this->Flags.assign(own, 0);
  this->Flags.resize(own + ghosts.size(), 1);
  this->Solver->sortState();
  this->Moved = 0.0;
  this->OwnFresh = false;
}

template<class Columns>
void DistributedSimulation::refreshColumns(const Columns& columns)
{
  const auto size = static_cast<std::size_t>(this->Comm.size());
  std::vector<Bytes> sends(size);
  for (std::size_t r = 0; r < size; ++r)
  {
    const std::vector<std::uint32_t>& which = this->SendIndex[r];
    if (which.empty())
    {
      continue;
    }
    std::vector<float> values(which.size() * columns.size());
    std::size_t k = 0;
    for (const float* column : columns)
    {
      for (std::uint32_t i : which)
      {
        values[k++] = column[i];
      }
    }
    put(sends[r], values.data(), values.size());
  }
  const std::vector<Bytes> received = this->Comm.exchange(sends);
  for (std::size_t r = 0; r < size; ++r)
  {
    const std::vector<std::uint32_t>& where = this->RecvIndex[r];
    if (received[r].size() != where.size() * columns.size() * sizeof(float))
    {
      throw std::logic_error("SPH: a distributed run's ghost refresh got the wrong number of values");
    }
    std::size_t at = 0;
    for (float* column : columns)
    {
      for (std::uint32_t i : where)
      {
        take(received[r], at, column + i, 1);
      }
    }
  }
}

void DistributedSimulation::permuted(const std::vector<std::uint32_t>& order)
{
  std::vector<std::uint32_t> moved(order.size());
  std::vector<std::uint8_t> flags(order.size());
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    moved[order[k]] = static_cast<std::uint32_t>(k);
    flags[k] = this->Flags[order[k]];
  }
  this->Flags = std::move(flags);
  for (auto* lists : { &this->SendIndex, &this->RecvIndex })
  {
    for (std::vector<std::uint32_t>& list : *lists)
    {
      for (std::uint32_t& i : list)
      {
        i = moved[i];
      }
    }
  }
}

double DistributedSimulation::checkReach(double dt)
{
  const ParticleState& s = this->Solver->state();
  double fastest = 0.0;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    if (!this->Flags[i])
    {
      fastest =
        std::max(fastest, std::sqrt(static_cast<double>(s.vx[i]) * s.vx[i] + static_cast<double>(s.vy[i]) * s.vy[i] +
                                    static_cast<double>(s.vz[i]) * s.vz[i]));
    }
  }
  const SPHParameters& p = this->Parameters;
  const double spacing = latticeSpacingForMass(p.particleMass, p.smoothingLength, p.restDensity, p.densityKernel());
  const double moved = this->max(fastest) * dt + (p.particleShifting ? 0.2 * spacing : 0.0);
  if (moved > this->Margin)
  {
    throw std::runtime_error("SPH (distributed): particles moved up to " + std::to_string(moved) +
                             " m in one step, more than the " + std::to_string(this->Margin) +
                             " m the processes' ghost layers allow (a quarter of SmoothingLength); " +
                             this->Solver->stabilityAdvice());
  }
  return moved;
}

void DistributedSimulation::afterStep(double moved)
{
  // A ghost layer gathered with a margin M each side stays complete while no particle has moved
  // more than M: one not sent to a process was over h + 2M from its slab, whose particles have not
  // left it by more than M. The next step is taken to move as far as this one, with a half more.
  this->Moved += moved;
  if (this->Moved + 1.5 * moved > this->Margin)
  {
    this->dropGhosts();
    this->redistribute();
    return;
  }
  this->refreshCarried();
}

std::int64_t DistributedSimulation::advance(double duration, const std::function<bool(double)>& progress)
{
  checkAdvanceDuration(duration);
  const double begin = this->Time;
  this->Solver->beginPressureMean();
  // Every process takes the same steps (their lengths are reduced over the processes) and stops
  // together: progress is asked on each and the run goes on only if all say so.
  const auto agreed = [&](double fraction)
  {
    const bool go = progress ? progress(fraction) : true;
    return this->min(go ? 1.0 : 0.0) > 0.5;
  };
  const std::int64_t taken = advanceInSteps(
    this->Parameters, this->Time, duration,
    [&](double remaining)
    {
      try
      {
        const double dt = this->Solver->step(remaining);
        this->Time = this->Solver->time(); // advanceInSteps lands it exactly on the end time
        this->Solver->addToPressureMean(dt);
        this->afterStep(this->checkReach(dt));
        return dt;
      }
      catch (const ProcessFailure& e)
      {
        throw std::runtime_error(std::string("SPH: the distributed step stopped: ") + e.what() +
                                 " (its own error says why)");
      }
      catch (...)
      {
        // This process failed on its own (a failed allocation) between two collective calls: the
        // others are waiting in the next one, which it makes as a failure, so that they stop too.
        this->Comm.abandon();
        throw;
      }
    },
    agreed, [this] { return this->Solver->stabilityAdvice(); });
  this->Solver->endPressureMean(this->Time - begin);
  this->OwnFresh = false;
  return taken;
}

void DistributedSimulation::addParticles(const std::vector<float>& x, const std::vector<float>& y,
                                         const std::vector<float>& z, const std::vector<float>& vx,
                                         const std::vector<float>& vy, const std::vector<float>& vz)
{
  this->dropGhosts();
  const std::size_t from = this->Solver->state().size();
  std::string problem;
  std::size_t added = 0;
  try
  {
    added = this->Solver->appendParticles(x, y, z, vx, vy, vz);
  }
  catch (const std::exception& e)
  {
    problem = e.what();
  }
  if (this->max(problem.empty() ? 0.0 : 1.0) > 0.0)
  {
    // Nothing was added anywhere (a refused addition adds nothing); the ghosts come back.
    this->redistribute();
    throw std::invalid_argument(problem.empty() ? "SPH: another process refused its added particles" : problem);
  }
  // New ids continue after the largest of every process's particles before the addition, in rank
  // order.
  const ParticleState& s = this->Solver->state();
  double nextId = 0.0;
  double nextIndex = 0.0;
  for (std::size_t i = 0; i < from; ++i)
  {
    nextId = std::max(nextId, static_cast<double>(s.id[i]) + 1.0);
    nextIndex = std::max(nextIndex, static_cast<double>(s.originalIndex[i]) + 1.0);
  }
  nextId = this->max(nextId);
  nextIndex = this->max(nextIndex);
  const auto [before, total] = prefixOf(static_cast<double>(added), this->Comm);
  if (total == 0.0)
  {
    this->redistribute();
    return;
  }
  this->Solver->numberParticles(from, static_cast<std::int64_t>(nextId + before),
                                static_cast<std::uint32_t>(nextIndex + before));
  this->redistribute();
  this->Solver->restartPressure();
  this->refreshCarried();
}

std::size_t DistributedSimulation::removeParticles(const std::vector<std::uint8_t>& remove)
{
  const std::size_t ownCount = this->hostState().size();
  if (remove.size() != ownCount)
  {
    throw std::invalid_argument("SPH: removeParticles needs one flag per particle");
  }
  // hostState() lists the own particles in state order: its flags go to the own rows, and the
  // ghosts go too (gathered afresh below).
  std::vector<std::uint8_t> out(this->Flags.size(), 1);
  std::size_t k = 0;
  std::size_t removed = 0;
  for (std::size_t i = 0; i < out.size(); ++i)
  {
    if (!this->Flags[i])
    {
      out[i] = remove[k++] ? 1 : 0;
      removed += out[i];
    }
  }
  if (this->sum(static_cast<double>(removed)) == 0.0)
  {
    return 0;
  }
  this->Solver->takeRows(out);
  this->Flags.assign(this->Solver->state().size(), 0);
  for (auto& list : this->RecvIndex)
  {
    list.clear();
  }
  this->redistribute();
  this->Solver->startPressure();
  this->refreshCarried();
  return removed;
}

template<typename T>
std::vector<T> DistributedSimulation::own(const std::vector<T>& all) const
{
  std::vector<T> out;
  out.reserve(all.size());
  for (std::size_t i = 0; i < all.size(); ++i)
  {
    if (!this->Flags[i])
    {
      out.push_back(all[i]);
    }
  }
  return out;
}

const ParticleState& DistributedSimulation::hostState() const
{
  if (!this->OwnFresh)
  {
    const ParticleState& s = this->Solver->state();
    for (auto array : { &ParticleState::x, &ParticleState::y, &ParticleState::z, &ParticleState::vx, &ParticleState::vy,
                        &ParticleState::vz, &ParticleState::ax, &ParticleState::ay, &ParticleState::az,
                        &ParticleState::density, &ParticleState::pressure })
    {
      this->Own.*array = this->own(s.*array);
    }
    this->Own.id = this->own(s.id);
    this->Own.originalIndex = this->own(s.originalIndex);
    this->OwnFresh = true;
  }
  return this->Own;
}
} // namespace

std::string distributedRunLacks(const SPHParameters& parameters)
{
  const SolverEntry& solver = solverEntry(parameters.pressureSolver);
  if (!solver.runsDistributed)
  {
    return std::string("SPH: ") + solver.label + " does not run distributed over processes yet; choose " +
           "PressureSolver δ-SPH or WCSPH, or run on one process";
  }
  if (parameters.periodic[0] && parameters.periodic[1] && parameters.periodic[2])
  {
    return "SPH: a distributed run cuts the domain along an axis that is not periodic; every axis is periodic "
           "(turn one of PeriodicX, PeriodicY, PeriodicZ off)";
  }
  return {};
}

std::unique_ptr<Simulation> makeDistributedSimulation(const SPHParameters& parameters, ParticleState localPiece,
                                                      std::shared_ptr<const TriangleBoundary> boundary,
                                                      Communicator& communicator)
{
  return std::make_unique<DistributedSimulation>(parameters, std::move(localPiece), std::move(boundary), communicator);
}
} // namespace parafluid::sph
