// OpenCL jobs: builds the per-pair specialised program (prelude + embedded sources) once and runs
// the bake kernels, one texel per work-item.
#pragma once
#include <CL/opencl.hpp>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace brdfbake {

// The full device source for one NDF/GAF pair: a #define prelude, then the embedded files.
std::string kernelSource(int ndf, int gaf);

struct KernelTable {
  int width = 0, height = 0;
  std::vector<std::vector<float>> planes;  // per kernel output, [y * width + x]
  std::vector<float> err;                  // per texel error bound relative to max(1, |value|)
};

class KernelRunner {
 public:
  explicit KernelRunner(const cl::Device& device);

  // Builds the pair's program now (kernel compile time is then kept out of the timed runs).
  void prepare(int ndf, int gaf) { program(ndf, gaf); }

  // A, B, E over (mu, r), nx x ny.
  KernelTable hemisphere(int ndf, int gaf, int nx, int ny, bool nodeGrid);
  // E_avg over r.
  KernelTable albedoAvg(int ndf, int gaf, int n, bool nodeGrid);
  // k_p over r.
  KernelTable kp(int ndf, int n, bool nodeGrid);

 private:
  cl::Program& program(int ndf, int gaf);
  KernelTable run1D(const char* kernel, int ndf, int gaf, int n, bool nodeGrid);

  cl::Device device_;
  cl::Context context_;
  cl::CommandQueue queue_;
  std::map<std::pair<int, int>, cl::Program> programs_;
};

}  // namespace brdfbake
