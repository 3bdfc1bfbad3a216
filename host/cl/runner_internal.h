// Shared by host/cl/runner.cpp (building programs), host/cl/runner_launch.cpp and
// host/cl/runner_own.cpp (running the kernels): the integrators' kernel names, the fixed CPU local
// size, the arguments of a family's kernel, and the private structs.
#pragma once
#include <CL/opencl.hpp>
#include <algorithm>
#include <string>
#include <vector>

#include "cl/runner.h"

namespace brdfbake::runner_detail {

inline const char* const kHemisphere = "bake_hemisphere";
inline const char* const kKp = "bake_kp";

// On a CPU device (PoCL) every launch uses these local sizes: PoCL generates one work-group
// function per kernel and local size, a few tenths of a second each, so one size per kernel keeps
// it to one. Small groups balance the uneven texel costs over the threads.
constexpr size_t kLocalX = 8, kLocalY = 1;

inline cl::Buffer outBuffer(const cl::Context& ctx, size_t n) {
  return cl::Buffer(ctx, CL_MEM_WRITE_ONLY, n * sizeof(float));
}
template <class T = float>
std::vector<T> readBack(cl::CommandQueue& q, const cl::Buffer& b, size_t n) {
  std::vector<T> v(n);
  q.enqueueReadBuffer(b, CL_TRUE, 0, n * sizeof(T), v.data());
  return v;
}
inline size_t roundUp(size_t n, size_t m) { return (n + m - 1) / m * m; }

// Sets `args` (KernelRunner::launch) on k in order: In and InReals copied into buffers of `ctx`
// (reals as double when fp64, else float; an empty or absent input as one value, so that the
// buffer is valid), Out and OutReals as buffers of their sizes (at least one value). The buffers go
// to *ins and *outs, which keep them alive until the launch has run (setArg keeps no reference).
void setLaunchArgs(cl::Kernel& k, const cl::Context& ctx, const std::vector<LaunchArg>& args, bool fp64,
                   std::vector<cl::Buffer>* ins, std::vector<cl::Buffer>* outs);

// The weight arguments (moments, fresnel, fr_x, fr_y, fr_z) from index `first` on: kWeightArgs.
constexpr int kWeightArgs = 5;
inline void setWeightArgs(cl::Kernel& k, int first, const HemiWeight& w) {
  k.setArg(first, w.moments);
  k.setArg(first + 1, w.fresnel);
  k.setArg(first + 2, w.x);
  k.setArg(first + 3, w.y);
  k.setArg(first + 4, w.z);
}

// The pair arguments (sel_ndf, sel_gaf) at `first`, `first + 1`: read by the shared program,
// ignored by a pair's own.
inline void setPairArgs(cl::Kernel& k, int first, int ndf, int gaf) {
  k.setArg(first, ndf);
  k.setArg(first + 1, gaf);
}

}  // namespace brdfbake::runner_detail

namespace brdfbake {

struct KernelRunner::Slot {
  cl::Context context;
  cl::CommandQueue queue;
  explicit Slot(const cl::Device& d) : context(d), queue(context, d) {}
};

struct KernelRunner::Compiled {
  int slot = 0;
  cl::Program program;
  std::vector<std::string> kernels;  // compiled (on a CPU device: work-group function generated)
  bool has(const std::string& k) const { return std::find(kernels.begin(), kernels.end(), k) != kernels.end(); }
};

}  // namespace brdfbake
