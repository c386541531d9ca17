#pragma once
// Internal to the CUDA backend: CUDA runtime errors as exceptions that say what failed.
#include <cuda_runtime.h>

#include <stdexcept>
#include <string>

namespace parafluid::sph::cuda
{
inline void check(cudaError_t status, const char* what)
{
  if (status != cudaSuccess)
  {
    throw std::runtime_error(std::string("SPH (CUDA): ") + what + " failed: " + cudaGetErrorString(status));
  }
}
} // namespace parafluid::sph::cuda
