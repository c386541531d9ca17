#pragma once
// The processes of a distributed run as threads of one program: ThreadGroup is what they share,
// each thread holds a ThreadCommunicator of its rank. Used by the Core's distributed tests and
// where there is no MPI.
#include "parafluid/common/Communicator.h"

#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>

namespace parafluid
{
class ThreadGroup
{
public:
  explicit ThreadGroup(int size);
  int size() const { return this->Size; }

private:
  friend class ThreadCommunicator;
  /// Blocks until every thread of the group has arrived.
  void barrier();

  int Size;
  std::mutex Mutex;
  std::condition_variable Arrived;
  int Waiting = 0;
  std::size_t Generation = 0;
  // Mailbox[from * Size + to]: the bytes of the exchange in progress; Values[rank]: a reduction's.
  std::vector<std::vector<std::uint8_t>> Mailbox;
  std::vector<std::vector<double>> Values;
  std::vector<char> Abandoned; // per rank, in the collective call in progress
};

class ThreadCommunicator final : public Communicator
{
public:
  ThreadCommunicator(std::shared_ptr<ThreadGroup> group, int rank);
  int rank() const override { return this->Rank; }
  int size() const override { return this->Group->size(); }
  std::vector<std::vector<std::uint8_t>> exchange(const std::vector<std::vector<std::uint8_t>>& sends) override;
  void reduce(std::vector<double>& values, Reduction op) override;
  void abandon() override;
  using Communicator::reduce;

private:
  /// Every collective call begins here: throws ProcessFailure on all when one process abandons.
  void checkNoneAbandoned(bool abandoning);

  std::shared_ptr<ThreadGroup> Group;
  int Rank;
};
} // namespace parafluid
