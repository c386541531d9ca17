#include "parafluid/common/ThreadCommunicator.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace parafluid
{
ThreadGroup::ThreadGroup(int size)
  : Size(size)
{
  if (size < 1)
  {
    throw std::invalid_argument("ThreadGroup: a group needs at least one thread, not " + std::to_string(size));
  }
  this->Mailbox.resize(static_cast<std::size_t>(size) * static_cast<std::size_t>(size));
  this->Values.resize(static_cast<std::size_t>(size));
  this->Abandoned.assign(static_cast<std::size_t>(size), 0);
}

void ThreadGroup::barrier()
{
  std::unique_lock<std::mutex> lock(this->Mutex);
  const std::size_t generation = this->Generation;
  if (++this->Waiting == this->Size)
  {
    this->Waiting = 0;
    ++this->Generation;
    this->Arrived.notify_all();
    return;
  }
  this->Arrived.wait(lock, [&] { return this->Generation != generation; });
}

ThreadCommunicator::ThreadCommunicator(std::shared_ptr<ThreadGroup> group, int rank)
  : Group(std::move(group))
  , Rank(rank)
{
  if (!this->Group || rank < 0 || rank >= this->Group->size())
  {
    throw std::invalid_argument("ThreadCommunicator: rank " + std::to_string(rank) + " is not in the group");
  }
}

void ThreadCommunicator::checkNoneAbandoned(bool abandoning)
{
  ThreadGroup& g = *this->Group;
  g.Abandoned[static_cast<std::size_t>(this->Rank)] = abandoning ? 1 : 0;
  g.barrier();
  int who = -1;
  for (int r = 0; r < this->size(); ++r)
  {
    who = who < 0 && g.Abandoned[static_cast<std::size_t>(r)] ? r : who;
  }
  g.barrier(); // every process has read the flags before the next call writes them
  if (who >= 0 && !abandoning)
  {
    throw ProcessFailure("process " + std::to_string(who) + " of " + std::to_string(this->size()) + " failed");
  }
}

void ThreadCommunicator::abandon()
{
  this->checkNoneAbandoned(true);
}

std::vector<std::vector<std::uint8_t>> ThreadCommunicator::exchange(const std::vector<std::vector<std::uint8_t>>& sends)
{
  const auto n = static_cast<std::size_t>(this->size());
  if (sends.size() != n)
  {
    throw std::invalid_argument("ThreadCommunicator::exchange needs one buffer per process");
  }
  this->checkNoneAbandoned(false);
  ThreadGroup& g = *this->Group;
  const auto me = static_cast<std::size_t>(this->Rank);
  for (std::size_t to = 0; to < n; ++to)
  {
    g.Mailbox[me * n + to] = sends[to];
  }
  g.barrier(); // every buffer is written
  std::vector<std::vector<std::uint8_t>> received(n);
  for (std::size_t from = 0; from < n; ++from)
  {
    received[from] = std::move(g.Mailbox[from * n + me]);
  }
  g.barrier(); // every buffer is taken before the next exchange writes
  return received;
}

void ThreadCommunicator::reduce(std::vector<double>& values, Reduction op)
{
  this->checkNoneAbandoned(false);
  ThreadGroup& g = *this->Group;
  g.Values[static_cast<std::size_t>(this->Rank)] = values;
  g.barrier();
  for (int r = 0; r < this->size(); ++r)
  {
    const std::vector<double>& other = g.Values[static_cast<std::size_t>(r)];
    if (other.size() != values.size())
    {
      throw std::logic_error("ThreadCommunicator::reduce: processes reduced different numbers of values");
    }
  }
  std::vector<double> result = g.Values[0];
  for (int r = 1; r < this->size(); ++r)
  {
    const std::vector<double>& other = g.Values[static_cast<std::size_t>(r)];
    for (std::size_t k = 0; k < result.size(); ++k)
    {
      result[k] = op == Reduction::Sum   ? result[k] + other[k]
                  : op == Reduction::Min ? std::min(result[k], other[k])
                                         : std::max(result[k], other[k]);
    }
  }
  g.barrier(); // every process has read every value
  values = std::move(result);
}
} // namespace parafluid
