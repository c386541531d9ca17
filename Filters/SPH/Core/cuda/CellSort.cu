// The state's order by grid cell on the GPU (see CellSort.cuh), with CUB's radix sort.
#include "cuda/CellSort.cuh"

#include <cub/device/device_radix_sort.cuh>

namespace parafluid::sph::cuda
{
namespace
{
constexpr int kThreads = 256;

__global__ void cellKeys(const float* x, const float* y, const float* z, const std::int64_t* id, std::uint32_t n,
                         DeviceGrid grid, std::uint64_t* keys, std::uint32_t* values)
{
  const std::uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n)
  {
    return;
  }
  keys[i] = (static_cast<std::uint64_t>(grid.cellOf(x[i], y[i], z[i])) << 32) |
            static_cast<std::uint32_t>(static_cast<std::uint64_t>(id[i]));
  values[i] = i;
}

/// cellStart[c] = the first slot whose cell is c or later, for every c up to cells (inclusive):
/// slot k writes the cells after its predecessor's up to its own.
__global__ void cellStarts(const std::uint64_t* keys, std::uint32_t n, std::uint32_t cells, std::uint32_t* cellStart)
{
  const std::uint32_t k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k > n)
  {
    return;
  }
  const std::int64_t previous = k == 0 ? -1 : static_cast<std::int64_t>(keys[k - 1] >> 32);
  const std::int64_t own = k == n ? static_cast<std::int64_t>(cells) : static_cast<std::int64_t>(keys[k] >> 32);
  for (std::int64_t c = previous + 1; c <= own; ++c)
  {
    cellStart[c] = k;
  }
}

int bitsFor(std::uint64_t count)
{
  int bits = 1;
  while ((std::uint64_t{ 1 } << bits) < count)
  {
    ++bits;
  }
  return bits;
}
} // namespace

const std::uint32_t* CellSort::sort(const float* x, const float* y, const float* z, const std::int64_t* id,
                                    std::uint32_t n, DeviceGrid& grid, cudaStream_t stream)
{
  const auto cells = static_cast<std::uint32_t>(grid.cellCount());
  this->CellStart.reserve(static_cast<std::size_t>(cells) + 1);
  grid.cellStart = this->CellStart.data();
  if (n == 0)
  {
    check(
      cudaMemsetAsync(this->CellStart.data(), 0, (static_cast<std::size_t>(cells) + 1) * sizeof(std::uint32_t), stream),
      "clearing the cells");
    return this->ValuesOut.data();
  }
  this->KeysIn.reserve(n);
  this->KeysOut.reserve(n);
  this->ValuesIn.reserve(n);
  this->ValuesOut.reserve(n);
  const unsigned int blocks = (n + kThreads - 1) / kThreads;
  cellKeys<<<blocks, kThreads, 0, stream>>>(x, y, z, id, n, grid, this->KeysIn.data(), this->ValuesIn.data());
  check(cudaGetLastError(), "the cell-key kernel");
  const int endBit = 32 + bitsFor(cells);
  std::size_t temporary = 0;
  check(cub::DeviceRadixSort::SortPairs(nullptr, temporary, this->KeysIn.data(), this->KeysOut.data(),
                                        this->ValuesIn.data(), this->ValuesOut.data(), n, 0, endBit, stream),
        "sizing the radix sort");
  this->Temporary.reserve(temporary);
  check(cub::DeviceRadixSort::SortPairs(this->Temporary.data(), temporary, this->KeysIn.data(), this->KeysOut.data(),
                                        this->ValuesIn.data(), this->ValuesOut.data(), n, 0, endBit, stream),
        "the radix sort");
  cellStarts<<<(n + 1 + kThreads - 1) / kThreads, kThreads, 0, stream>>>(this->KeysOut.data(), n, cells,
                                                                         this->CellStart.data());
  check(cudaGetLastError(), "the cell-start kernel");
  return this->ValuesOut.data();
}
} // namespace parafluid::sph::cuda
