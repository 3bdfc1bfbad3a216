#include "cl/runner.h"

#include "cl/embedded_kernels.h"
#include "common/errors.h"
#include "common/models.h"

namespace brdfbake {

namespace {
const char* embedded(const std::string& path) {
  for (const auto& f : kEmbeddedKernelSources)
    if (path == f.path) return f.text;
  throw Error(kExitSoftware, "internal: OpenCL source " + path + " is not embedded (CMakeLists.txt)");
}
void append(std::string& src, const std::string& path) {
  src += "#line 1 \"" + path + "\"\n";
  src += embedded(path);
  src += "\n";
}
}  // namespace

// The program for one model pair: the prelude fixing the pair, then the shared code in dependency
// order. The pointwise functions (models and integrand) are compiled twice, for one value and for
// a lane vector of values (kernels/brdf/compat.h explains the lanes).
std::string kernelSource(int ndf, int gaf) {
  std::string src = "/* brdfbake prelude: " + ndfNames()[ndf] + " + " + gafNames()[gaf] + " */\n";
  src += "#define BRDF_NDF " + std::to_string(ndf) + "\n#define BRDF_GAF " + std::to_string(gaf) + "\n";
  const char* pointwise[] = {"kernels/brdf/ndf.h", "kernels/brdf/gaf.h", "kernels/brdf/fresnel.h",
                             "kernels/integrate/integrand.h"};
  append(src, "kernels/brdf/compat.h");
  for (const char* f : pointwise) append(src, f);
  src += "#define BRDF_LANE_PASS 1\n#undef real\n#define real lane_t\n";
  for (const char* f : pointwise) append(src, f);
  src += "#undef BRDF_LANE_PASS\n#undef real\n#define real float\n";
  for (const char* f : {"kernels/integrate/quadrature.h", "kernels/integrate/hemisphere.h", "kernels/bake.cl"})
    append(src, f);
  return src;
}

// -w: without AVX-512, Clang warns about every float16 argument ("changes the ABI"), harmless
// here (PoCL compiles the kernel and its library for one CPU) but enough to bury a real error
// in the build log that a failed build prints.
const char* const kBuildOptions = "-cl-std=CL1.2 -w";

KernelRunner::KernelRunner(const cl::Device& device)
    : device_(device), context_(device), queue_(context_, device) {}

cl::Program& KernelRunner::program(int ndf, int gaf) {
  auto key = std::make_pair(ndf, gaf);
  auto it = programs_.find(key);
  if (it != programs_.end()) return it->second;
  cl::Program prog(context_, kernelSource(ndf, gaf));
  cl_int rc = CL_SUCCESS;
  try {
    rc = prog.build({device_}, kBuildOptions);
  } catch (const cl::BuildError& e) {
    std::string log;
    for (auto& l : e.getBuildLog()) log += l.second;
    throw Error(kExitSoftware, "OpenCL kernel build failed for " + ndfNames()[ndf] + " + " + gafNames()[gaf] +
                                   " (" + std::to_string(e.err()) + "); build log:\n" + log);
  } catch (const cl::Error& e) {
    rc = e.err();
  }
  if (rc != CL_SUCCESS) {
    std::string log = prog.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device_);
    throw Error(kExitSoftware, "OpenCL kernel build failed for " + ndfNames()[ndf] + " + " + gafNames()[gaf] +
                                   " (" + std::to_string(rc) + "); build log:\n" + log);
  }
  return programs_.emplace(key, prog).first->second;
}

namespace {
cl::Buffer outBuffer(const cl::Context& ctx, size_t n) { return cl::Buffer(ctx, CL_MEM_WRITE_ONLY, n * sizeof(float)); }
std::vector<float> readBack(cl::CommandQueue& q, const cl::Buffer& b, size_t n) {
  std::vector<float> v(n);
  q.enqueueReadBuffer(b, CL_TRUE, 0, n * sizeof(float), v.data());
  return v;
}
}  // namespace

KernelTable KernelRunner::hemisphere(int ndf, int gaf, int nx, int ny, bool nodeGrid) {
  size_t n = static_cast<size_t>(nx) * ny;
  cl::Buffer a = outBuffer(context_, n), b = outBuffer(context_, n), e = outBuffer(context_, n),
             err = outBuffer(context_, n);
  cl::Kernel k(program(ndf, gaf), "bake_hemisphere");
  k.setArg(0, a);
  k.setArg(1, b);
  k.setArg(2, e);
  k.setArg(3, err);
  k.setArg(4, nx);
  k.setArg(5, ny);
  k.setArg(6, 0.0f);
  k.setArg(7, 1.0f);
  k.setArg(8, 0.0f);
  k.setArg(9, 1.0f);
  k.setArg(10, nodeGrid ? 1 : 0);
  queue_.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(nx, ny), cl::NullRange);
  KernelTable t;
  t.width = nx;
  t.height = ny;
  t.planes = {readBack(queue_, a, n), readBack(queue_, b, n), readBack(queue_, e, n)};
  t.err = readBack(queue_, err, n);
  return t;
}

KernelTable KernelRunner::run1D(const char* kernel, int ndf, int gaf, int n, bool nodeGrid) {
  cl::Buffer v = outBuffer(context_, n), err = outBuffer(context_, n);
  cl::Kernel k(program(ndf, gaf), kernel);
  k.setArg(0, v);
  k.setArg(1, err);
  k.setArg(2, n);
  k.setArg(3, 0.0f);
  k.setArg(4, 1.0f);
  k.setArg(5, nodeGrid ? 1 : 0);
  queue_.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(n), cl::NullRange);
  KernelTable t;
  t.width = n;
  t.height = 1;
  t.planes = {readBack(queue_, v, n)};
  t.err = readBack(queue_, err, n);
  return t;
}

KernelTable KernelRunner::albedoAvg(int ndf, int gaf, int n, bool nodeGrid) {
  return run1D("bake_albedo_avg", ndf, gaf, n, nodeGrid);
}

KernelTable KernelRunner::kp(int ndf, int n, bool nodeGrid) { return run1D("bake_kp", ndf, 0, n, nodeGrid); }

}  // namespace brdfbake
