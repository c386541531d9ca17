#pragma once
// What the CPU simulation of one process's region in a distributed run asks of the other processes
// (DistributedSimulation implements it). Its state holds its own particles and ghosts: read-only
// copies of the other processes' particles within reach of its region, refreshed from their owners
// between the passes that read them at neighbours. Reductions run over the processes' own particles
// only, so every process takes the same decisions (time step, blow-up checks) as a serial run.
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace parafluid::sph
{
class GhostLayer
{
public:
  virtual ~GhostLayer() = default;
  /// One flag per particle in state order: 1 for a ghost.
  virtual const std::vector<std::uint8_t>& ghostFlags() const = 0;
  /// Copies the owners' values of each per-particle column (one float per particle, state order)
  /// into their ghosts.
  virtual void refresh(std::initializer_list<float*> columns) = 0;
  /// The state was reordered: order[k] is the old index of particle k.
  virtual void permuted(const std::vector<std::uint32_t>& order) = 0;
  /// The value's sum, smallest or largest over the processes.
  virtual double sum(double value) = 0;
  virtual double min(double value) = 0;
  virtual double max(double value) = 0;
};
} // namespace parafluid::sph
