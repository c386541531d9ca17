#pragma once
// Internal to the CUDA backend: a typed array in GPU memory that frees itself, and that says how
// many bytes it asked for and how many were free when the GPU has too few.
#include "cuda/CudaCheck.h"

#include <cstddef>
#include <string>
#include <utility>

namespace parafluid::sph::cuda
{
/// Throws std::runtime_error naming `bytes` and the GPU's free memory when `bytes` more do not fit.
void requireDeviceMemory(std::size_t bytes, const std::string& what);
/// Throws std::runtime_error naming `bytes` and the GPU's free memory after cudaMalloc could not
/// get them (the free memory may lie in pieces smaller than that).
[[noreturn]] void reportFailedAllocation(std::size_t bytes, const std::string& what);

template<class T>
class DeviceBuffer
{
public:
  DeviceBuffer() = default;
  ~DeviceBuffer() { this->release(); }
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;
  DeviceBuffer(DeviceBuffer&& other) noexcept { this->swap(other); }
  DeviceBuffer& operator=(DeviceBuffer&& other) noexcept
  {
    this->swap(other);
    return *this;
  }

  /// Room for n values; the contents are lost when it grows.
  void reserve(std::size_t n)
  {
    if (n <= this->Capacity)
    {
      return;
    }
    this->release();
    void* p = nullptr;
    const cudaError_t status = cudaMalloc(&p, n * sizeof(T));
    if (status == cudaErrorMemoryAllocation)
    {
      cudaGetLastError(); // an allocation failure is not sticky; clear it for the next call
      reportFailedAllocation(n * sizeof(T), "an array");
    }
    check(status, "cudaMalloc");
    this->Data = static_cast<T*>(p);
    this->Capacity = n;
  }
  void release()
  {
    if (this->Data)
    {
      cudaFree(this->Data);
    }
    this->Data = nullptr;
    this->Capacity = 0;
  }
  void swap(DeviceBuffer& other) noexcept
  {
    std::swap(this->Data, other.Data);
    std::swap(this->Capacity, other.Capacity);
  }
  void upload(const T* host, std::size_t n, cudaStream_t stream)
  {
    this->reserve(n);
    if (n > 0)
    {
      check(cudaMemcpyAsync(this->Data, host, n * sizeof(T), cudaMemcpyHostToDevice, stream), "a copy to the GPU");
    }
  }
  void download(T* host, std::size_t n, cudaStream_t stream) const
  {
    if (n > 0)
    {
      check(cudaMemcpyAsync(host, this->Data, n * sizeof(T), cudaMemcpyDeviceToHost, stream), "a copy from the GPU");
    }
  }
  T* data() const { return this->Data; }
  std::size_t capacity() const { return this->Capacity; }
  std::size_t bytes() const { return this->Capacity * sizeof(T); }

private:
  T* Data = nullptr;
  std::size_t Capacity = 0;
};
} // namespace parafluid::sph::cuda
