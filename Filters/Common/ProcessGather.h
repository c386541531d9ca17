#pragma once
// A filter that scores all particles together under MPI while each process keeps its own piece as
// output: the pieces' values gathered on process 0, its results cut back into the pieces.
#include "parafluid/common/Communicator.h"

#include <cstddef>
#include <cstring>
#include <vector>

namespace parafluid::vtk
{
/// Every process's `local` values on process 0, in rank order (empty on the others); `counts` gets
/// every process's value count, on every process. Collective.
template<class T>
std::vector<T> gatherOnFirst(const std::vector<T>& local, parafluid::Communicator& processes,
                             std::vector<std::size_t>& counts)
{
  const auto size = static_cast<std::size_t>(processes.size());
  std::vector<double> sizes(size, 0.0);
  sizes[static_cast<std::size_t>(processes.rank())] = static_cast<double>(local.size());
  processes.reduce(sizes, parafluid::Reduction::Sum);
  counts.assign(sizes.begin(), sizes.end());
  std::vector<std::vector<std::uint8_t>> sends(size);
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(local.data());
  sends[0].assign(bytes, bytes + local.size() * sizeof(T));
  const auto received = processes.exchange(sends);
  std::vector<T> all;
  if (processes.rank() == 0)
  {
    for (const auto& message : received)
    {
      const std::size_t at = all.size();
      all.resize(at + message.size() / sizeof(T));
      if (!message.empty())
      {
        std::memcpy(all.data() + at, message.data(), message.size());
      }
    }
  }
  return all;
}

/// Process 0's `all` cut into each process's share of `perValue` × counts[r] values (counts as
/// gatherOnFirst gave them); every process gets its own. Collective.
template<class T>
std::vector<T> scatterFromFirst(const std::vector<T>& all, const std::vector<std::size_t>& counts, std::size_t perValue,
                                parafluid::Communicator& processes)
{
  std::vector<std::vector<std::uint8_t>> sends(static_cast<std::size_t>(processes.size()));
  if (processes.rank() == 0)
  {
    std::size_t at = 0;
    for (std::size_t r = 0; r < sends.size(); ++r)
    {
      const std::size_t n = counts[r] * perValue;
      const auto* bytes = reinterpret_cast<const std::uint8_t*>(all.data() + at);
      sends[r].assign(bytes, bytes + n * sizeof(T));
      at += n;
    }
  }
  const auto received = processes.exchange(sends);
  const auto& mine = received[0];
  std::vector<T> out(mine.size() / sizeof(T));
  if (!mine.empty())
  {
    std::memcpy(out.data(), mine.data(), mine.size());
  }
  return out;
}
} // namespace parafluid::vtk
