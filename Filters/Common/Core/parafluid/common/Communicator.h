#pragma once
// The processes of a distributed run as the numerics see them: byte messages between processes and
// reductions over them. The plugin implements it over ParaView's MPI controller
// (vtkPFMPICommunicator); ThreadCommunicator runs the processes as threads of one program (tests,
// and a machine without MPI). Every call is collective: each process makes the same calls in the
// same order.
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace parafluid
{
enum class Reduction
{
  Sum,
  Min,
  Max
};

/// Thrown by a collective call when another process gave up (Communicator::abandon) instead of
/// making it.
class ProcessFailure : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

class Communicator
{
public:
  virtual ~Communicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// Sends sends[r] to each process r (sends has size() entries; empty ones send nothing) and
  /// returns what each process sent to this one, indexed by sender.
  virtual std::vector<std::vector<std::uint8_t>> exchange(const std::vector<std::vector<std::uint8_t>>& sends) = 0;
  /// Replaces each value by its reduction over the processes (every process passes as many).
  virtual void reduce(std::vector<double>& values, Reduction op) = 0;
  /// Made by a process whose own work failed between collective calls, in place of its next one:
  /// the call the others are making (an exchange or a reduction) throws ProcessFailure on them
  /// instead of waiting for this process forever. Collective with that call.
  virtual void abandon() = 0;

  double reduce(double value, Reduction op)
  {
    std::vector<double> v{ value };
    this->reduce(v, op);
    return v[0];
  }
};
} // namespace parafluid
