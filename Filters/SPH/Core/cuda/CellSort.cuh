#pragma once
// Internal to the CUDA backend: the state's order by grid cell, every step. A radix sort of keys
// (cell, id) gives each particle its slot, ties broken by id, so the order, and with it every sum,
// is the same run to run; the cells' first slots follow from the sorted keys.
#include "cuda/DeviceBuffer.h"
#include "cuda/DeviceGrid.cuh"

#include <cuda_runtime.h>

#include <cstdint>

namespace parafluid::sph::cuda
{
class CellSort
{
public:
  /// Sorts particles at (x, y, z) with ids `id` into grid's cells: returns order (order[k] is the
  /// particle that goes to slot k) and fills cellStart (grid.cellCount() + 1 entries), which
  /// grid.cellStart is pointed at.
  const std::uint32_t* sort(const float* x, const float* y, const float* z, const std::int64_t* id, std::uint32_t n,
                            DeviceGrid& grid, cudaStream_t stream);
  std::size_t bytes() const
  {
    return this->KeysIn.bytes() + this->KeysOut.bytes() + this->ValuesIn.bytes() + this->ValuesOut.bytes() +
           this->Temporary.bytes() + this->CellStart.bytes();
  }

private:
  DeviceBuffer<std::uint64_t> KeysIn, KeysOut;
  DeviceBuffer<std::uint32_t> ValuesIn, ValuesOut, CellStart;
  DeviceBuffer<unsigned char> Temporary;
};
} // namespace parafluid::sph::cuda
