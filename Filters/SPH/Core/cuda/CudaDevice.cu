// Whether the CUDA backend can run here, on which GPU, and how much memory it has (CudaBackend.h).
#include "cuda/DeviceBuffer.h"
#include "parafluid/sph/CudaBackend.h"

#include <string>

namespace parafluid::sph
{
namespace
{
// A kernel whose attributes say whether this build's GPU code runs on the current device.
__global__ void probe() {}
} // namespace

bool cudaBackendUsable(std::string* reason)
{
  auto refuse = [&](const std::string& why)
  {
    if (reason)
    {
      *reason = why;
    }
    return false;
  };
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount(&count);
  if (status != cudaSuccess || count == 0)
  {
    cudaGetLastError();
    return refuse(std::string("no usable CUDA GPU here (") +
                  (status != cudaSuccess ? cudaGetErrorString(status) : "no CUDA device") + ")");
  }
  cudaFuncAttributes attributes;
  const cudaError_t image = cudaFuncGetAttributes(&attributes, probe);
  if (image != cudaSuccess)
  {
    cudaGetLastError();
    cudaDeviceProp properties;
    cudaGetDeviceProperties(&properties, 0);
    return refuse(std::string("this build's GPU code does not run on the ") + properties.name +
                  " (compute capability " + std::to_string(properties.major) + "." + std::to_string(properties.minor) +
                  ": " + cudaGetErrorString(image) + "); rebuild with CMAKE_CUDA_ARCHITECTURES including it");
  }
  return true;
}

std::string cudaDeviceName()
{
  int device = 0;
  cudaDeviceProp properties;
  if (cudaGetDevice(&device) != cudaSuccess || cudaGetDeviceProperties(&properties, device) != cudaSuccess)
  {
    cudaGetLastError();
    return {};
  }
  return properties.name;
}

namespace cuda
{
namespace
{
[[noreturn]] void outOfMemory(std::size_t bytes, const std::string& what, std::size_t freeBytes, std::size_t totalBytes)
{
  throw std::runtime_error("SPH (CUDA): " + what + " needs " + std::to_string(bytes) +
                           " bytes of GPU memory, and the " + cudaDeviceName() + " has " + std::to_string(freeBytes) +
                           " bytes free (of " + std::to_string(totalBytes) +
                           "): choose Backend CPU, or fewer particles");
}
} // namespace

void requireDeviceMemory(std::size_t bytes, const std::string& what)
{
  std::size_t freeBytes = 0, totalBytes = 0;
  check(cudaMemGetInfo(&freeBytes, &totalBytes), "asking the GPU's free memory");
  if (bytes > freeBytes)
  {
    outOfMemory(bytes, what, freeBytes, totalBytes);
  }
}

void reportFailedAllocation(std::size_t bytes, const std::string& what)
{
  std::size_t freeBytes = 0, totalBytes = 0;
  cudaMemGetInfo(&freeBytes, &totalBytes);
  outOfMemory(bytes, what, freeBytes, totalBytes);
}
} // namespace cuda
} // namespace parafluid::sph
