// The integrators' launches (KernelRunner's table methods: the split sum and albedo, their nodes,
// k_p, the diffuse albedo), the fixed CPU local size, the kept results; the families' own kernels'
// launches are host/cl/runner_own.cpp, building the programs host/cl/runner.cpp.
#include <algorithm>
#include <cmath>

#include "cl/runner.h"
#include "cl/runner_internal.h"
#include "common/brdf3d_grid.h"
#include "common/brdf_host.h"
#include "common/errors.h"

namespace brdfbake {

using namespace runner_detail;

// gx x gy work-items (gy = 0: a 1D range); on a CPU device in groups of the one local size.
void KernelRunner::run(Compiled& c, cl::Kernel& k, size_t gx, size_t gy) {
  cl::CommandQueue& q = slots_[c.slot]->queue;
  if (cpu_) {
    if (gy == 0)
      q.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(roundUp(gx, kLocalX)), cl::NDRange(kLocalX));
    else
      q.enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(roundUp(gx, kLocalX), roundUp(gy, kLocalY)),
                             cl::NDRange(kLocalX, kLocalY));
  } else {
    q.enqueueNDRangeKernel(k, cl::NullRange, gy == 0 ? cl::NDRange(gx) : cl::NDRange(gx, gy), cl::NullRange);
  }
}

// As run(), in bands of rows (global offset (0, y0)) with progress after each, when a progress
// callback is set and the table has more than kBandTexels texels: the texels are independent, so
// the values are the same bits either way; the bands cost a queue finish each (a 4096^2 split sum
// runs 256 of them).
void KernelRunner::runRows(Compiled& c, cl::Kernel& k, size_t gx, size_t gy) {
  const size_t n = gx * gy;
  if (!progress_ || gy < 2 || n <= kBandTexels) {
    run(c, k, gx, gy);
    return;
  }
  cl::CommandQueue& q = slots_[c.slot]->queue;
  const size_t rows = std::max<size_t>(1, kBandTexels / gx);
  progress("texels", 0, static_cast<double>(n));
  for (size_t y0 = 0; y0 < gy; y0 += rows) {
    const size_t h = std::min(rows, gy - y0);
    if (cpu_)
      q.enqueueNDRangeKernel(k, cl::NDRange(0, y0), cl::NDRange(roundUp(gx, kLocalX), roundUp(h, kLocalY)),
                             cl::NDRange(kLocalX, kLocalY));
    else
      q.enqueueNDRangeKernel(k, cl::NDRange(0, y0), cl::NDRange(gx, h), cl::NullRange);
    q.finish();
    progress("texels", static_cast<double>((y0 + h) * gx), static_cast<double>(n));
  }
}

HemiWeight fresnelWeight(int model, double x, double y) {
  HemiWeight w{HEMI_FRESNEL, model, static_cast<float>(x), static_cast<float>(y), 0.0f};
  if (model == FRESNEL_DIELECTRIC || model == FRESNEL_SCHLICK_TIR || model == FRESNEL_CONDUCTOR) {
    double xf = w.x;
    w.z = static_cast<float>((x - 1) * (x + 1) - (xf - 1) * (xf + 1));
  }
  return w;
}

KernelTable KernelRunner::hemisphere(int ndf, int gaf, int nx, int ny, bool nodeGrid, const HemiWeight& w,
                                     bool muSqrt) {
  return hemisphereRange(ndf, gaf, nx, ny, 0.0f, 1.0f, 0.0f, 1.0f, nodeGrid, w, -1, muSqrt);
}

namespace {
// The grid arguments the 2D kernels share, from index `first`: nx, ny, the x range, the y range,
// node grid or texel centres.
void setGridArgs(cl::Kernel& k, int first, int nx, int ny, float xLo, float xHi, float yLo, float yHi, bool nodeGrid) {
  k.setArg(first, nx);
  k.setArg(first + 1, ny);
  k.setArg(first + 2, xLo);
  k.setArg(first + 3, xHi);
  k.setArg(first + 4, yLo);
  k.setArg(first + 5, yHi);
  k.setArg(first + 6, nodeGrid ? 1 : 0);
}
}  // namespace

namespace {
// A launch's arguments as bytes, the reuse key (setReuse): the kernel's tag, then each value.
template <class... T>
std::string launchKey(char tag, const T&... v) {
  std::string k(1, tag);
  (k.append(reinterpret_cast<const char*>(&v), sizeof v), ...);
  return k;
}
std::string weightKey(const HemiWeight& w) { return launchKey('w', w.moments, w.fresnel, w.x, w.y, w.z); }
}  // namespace

const std::vector<std::vector<float>>* KernelRunner::reused(const std::string& key) const {
  if (!reuse_) return nullptr;
  for (const Kept& k : kept_)
    if (k.key == key) return &k.planes;
  return nullptr;
}

void KernelRunner::keep(const std::string& key, const std::vector<std::vector<float>>& planes) {
  if (!reuse_) return;
  size_t bytes = key.size();
  for (const auto& p : planes) bytes += p.size() * sizeof(float);
  if (bytes > kReuseBytes) return;
  while (!kept_.empty() && keptBytes_ + bytes > kReuseBytes) {
    keptBytes_ -= kept_.front().bytes;
    kept_.pop_front();
  }
  kept_.push_back(Kept{key, planes, bytes});
  keptBytes_ += bytes;
}

KernelTable KernelRunner::hemisphereRange(int ndf, int gaf, int nx, int ny, float muLo, float muHi, float rLo,
                                          float rHi, bool nodeGrid, const HemiWeight& w, int level, bool muSqrt) {
  const std::string key =
      launchKey('h', ndf, brdf64::gaf_canonical(ndf, gaf), nx, ny, muLo, muHi, rLo, rHi, nodeGrid, level, muSqrt) +
      weightKey(w);
  if (const auto* kept = reused(key)) {
    KernelTable t;
    t.width = nx;
    t.height = ny;
    t.planes = {(*kept)[0], (*kept)[1], (*kept)[2]};
    t.err = (*kept)[3];
    return t;
  }
  Compiled& c = compiled({ProgramKey::Integrators, ndf, gaf}, kHemisphere);
  Slot& s = *slots_[c.slot];
  size_t n = static_cast<size_t>(nx) * ny;
  cl::Buffer a = outBuffer(s.context, n), b = outBuffer(s.context, n), e = outBuffer(s.context, n),
             err = outBuffer(s.context, n);
  cl::Kernel k(c.program, kHemisphere);
  k.setArg(0, a);
  k.setArg(1, b);
  k.setArg(2, e);
  k.setArg(3, err);
  setGridArgs(k, 4, nx, ny, muLo, muHi, rLo, rHi, nodeGrid);
  if (muSqrt) k.setArg(10, (nodeGrid ? 1 : 0) | 2);  // x is sqrt(mu) (bake.cl)
  setWeightArgs(k, 11, w);
  k.setArg(11 + kWeightArgs, level);
  k.setArg(12 + kWeightArgs, 0);  // the grid's mu, not a list
  k.setArg(13 + kWeightArgs, a);  // (unread)
  setPairArgs(k, 14 + kWeightArgs, ndf, gaf);
  runRows(c, k, nx, ny);
  KernelTable t;
  t.width = nx;
  t.height = ny;
  t.planes = {readBack(s.queue, a, n), readBack(s.queue, b, n), readBack(s.queue, e, n)};
  t.err = readBack(s.queue, err, n);
  keep(key, {t.planes[0], t.planes[1], t.planes[2], t.err});
  return t;
}

namespace {
// The arguments the kernels over r share: (values, bounds, n, r range [0, 1], grid).
void setRArgs(cl::Kernel& k, const cl::Buffer& values, const cl::Buffer& bounds, int n, bool nodeGrid, float rLo,
              float rHi) {
  k.setArg(0, values);
  k.setArg(1, bounds);
  k.setArg(2, n);
  k.setArg(3, rLo);
  k.setArg(4, rHi);
  k.setArg(5, nodeGrid ? 1 : 0);
}
}  // namespace

// Quadrature nodes (mu, r, target) for the hemisphere kernel: planes {value, absolute bound}
// (bake.cl, mu_list = 1, or 2 for bare estimates). The average albedo's rule that chooses them is
// host/cl/runner_avg.cpp.
std::vector<std::vector<float>> KernelRunner::hemisphereNodes(int ndf, int gaf, const std::vector<cl_float4>& nodes,
                                                              const HemiWeight& w, bool bare) {
  const std::string launch = launchKey('n', ndf, brdf64::gaf_canonical(ndf, gaf), bare) + weightKey(w);
  uint32_t id = 0;
  while (id < pointLaunches_.size() && pointLaunches_[id] != launch) ++id;
  if (reuse_ && id == pointLaunches_.size()) pointLaunches_.push_back(launch);
  auto pointKey = [&](const cl_float4& p) {
    PointKey k{id, {}};
    std::memcpy(k.bits, &p, sizeof k.bits);
    return k;
  };
  // the points not computed before in this bake (all of them without reuse), in their order
  std::vector<cl_float4> todo;
  std::vector<const std::array<float, 4>*> known(nodes.size(), nullptr);
  for (size_t k = 0; k < nodes.size(); ++k) {
    auto it = reuse_ ? points_.find(pointKey(nodes[k])) : points_.end();
    if (it != points_.end())
      known[k] = &it->second;
    else
      todo.push_back(nodes[k]);
  }
  std::vector<std::vector<float>> out =
      todo.empty() ? std::vector<std::vector<float>>(4) : nodesLaunch(ndf, gaf, todo, w, bare);
  // kept for later launches (element references stay valid as the map grows: `known` holds them)
  for (size_t k = 0; reuse_ && k < todo.size() && points_.size() < kReusePoints; ++k)
    points_.emplace(pointKey(todo[k]), std::array<float, 4>{out[0][k], out[1][k], out[2][k], out[3][k]});
  if (todo.size() == nodes.size()) return out;
  std::vector<std::vector<float>> all(4, std::vector<float>(nodes.size()));
  size_t next = 0;
  for (size_t k = 0; k < nodes.size(); ++k) {
    for (int q = 0; q < 4; ++q) all[q][k] = known[k] ? (*known[k])[q] : out[q][next];
    if (!known[k]) ++next;
  }
  return all;
}

std::vector<std::vector<float>> KernelRunner::nodesLaunch(int ndf, int gaf, const std::vector<cl_float4>& nodes,
                                                          const HemiWeight& w, bool bare) {
  Compiled& c = compiled({ProgramKey::Integrators, ndf, gaf}, kHemisphere);
  Slot& s = *slots_[c.slot];
  size_t count = nodes.size();
  cl::Buffer a = outBuffer(s.context, count), b = outBuffer(s.context, count), e = outBuffer(s.context, count),
             err = outBuffer(s.context, count);
  cl::Buffer in(s.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, count * sizeof(cl_float4),
                const_cast<cl_float4*>(nodes.data()));
  cl::Kernel k(c.program, kHemisphere);
  k.setArg(0, a);
  k.setArg(1, b);
  k.setArg(2, e);
  k.setArg(3, err);
  setGridArgs(k, 4, static_cast<int>(count), 1, 0.0f, 1.0f, 0.0f, 1.0f, false);
  setWeightArgs(k, 11, w);
  k.setArg(11 + kWeightArgs, -1);
  k.setArg(12 + kWeightArgs, bare ? 2 : 1);  // (mu, r, target) from the list
  k.setArg(13 + kWeightArgs, in);
  setPairArgs(k, 14 + kWeightArgs, ndf, gaf);
  run(c, k, count, 1);
  return {readBack(s.queue, e, count), readBack(s.queue, err, count), readBack(s.queue, a, count),
          readBack(s.queue, b, count)};
}

KernelTable KernelRunner::kp(int ndf, int n, bool nodeGrid, float rLo, float rHi) {
  Compiled* pc = kpProgram(ndf);
  Compiled& c = pc ? *pc : compiled({ProgramKey::Integrators, ndf, GAF_NONE}, kKp);
  compileKernel(c, kKp);
  Slot& s = *slots_[c.slot];
  cl::Buffer v = outBuffer(s.context, n), err = outBuffer(s.context, n);
  cl::Kernel k(c.program, kKp);
  setRArgs(k, v, err, n, nodeGrid, rLo, rHi);
  setPairArgs(k, 6, ndf, GAF_NONE);
  run(c, k, n, 0);
  KernelTable t;
  t.width = n;
  t.height = 1;
  t.planes = {readBack(s.queue, v, n)};
  t.err = readBack(s.queue, err, n);
  return t;
}

// The diffuse kernel has its own arguments: it is created here and launched by run() (the fixed
// local size on a CPU device), not pre-compiled by compileKernel()/emptyArgs().
KernelTable KernelRunner::diffuseAlbedo(int model, int nx, int ny, float pLo, float pHi, bool nodeGrid, float muLo,
                                        float muHi) {
  static const char* const kDiffuse = "bake_diffuse_albedo";
  // the first integrators program (the map orders them first), else ggx + smith-correlated's
  Compiled* pc = nullptr;
  if (!programs_.empty() && programs_.begin()->first.kind == ProgramKey::Integrators)
    pc = find(programs_.begin()->first);
  if (!pc) {
    const ProgramKey fallback{ProgramKey::Integrators, NDF_GGX, GAF_SMITH_CORRELATED};
    buildHere(fallback);
    pc = find(fallback);
  }
  Compiled& c = *pc;
  Slot& s = *slots_[c.slot];
  size_t n = static_cast<size_t>(nx) * ny;
  cl::Buffer e = outBuffer(s.context, n), err = outBuffer(s.context, n);
  cl::Kernel k(c.program, kDiffuse);
  k.setArg(0, e);
  k.setArg(1, err);
  setGridArgs(k, 2, nx, ny, muLo, muHi, pLo, pHi, nodeGrid);
  k.setArg(9, model);
  runRows(c, k, nx, ny);
  KernelTable t;
  t.width = nx;
  t.height = ny;
  t.planes = {readBack(s.queue, e, n)};
  t.err = readBack(s.queue, err, n);
  return t;
}

}  // namespace brdfbake
