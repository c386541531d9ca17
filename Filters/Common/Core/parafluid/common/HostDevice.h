#pragma once
// PARAFLUID_HOST_DEVICE marks a small inline function of a Core that the CUDA backend calls on the
// GPU as well, so the CPU and the GPU evaluate one formula; it is empty in host-only compilers.
#ifdef __CUDACC__
#define PARAFLUID_HOST_DEVICE __host__ __device__
#else
#define PARAFLUID_HOST_DEVICE
#endif
