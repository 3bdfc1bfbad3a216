#include "cl/runner.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>

#include "cl/embedded_kernels.h"
#include "common/brdf_host.h"
#include "common/errors.h"

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

const char* const kHemisphere = "bake_hemisphere";
const char* const kAlbedoNodes = "bake_albedo_nodes";
const char* const kKp = "bake_kp";

// On a CPU device (PoCL) every launch uses these local sizes: PoCL generates one work-group
// function per kernel and local size, a few tenths of a second each, so one size per kernel keeps
// it to one. Small groups balance the uneven texel costs over the threads.
constexpr size_t kLocalX = 8, kLocalY = 1;
size_t roundUp(size_t n, size_t m) { return (n + m - 1) / m * m; }
}  // namespace

// The program for one model pair: the prelude fixing the pair, then the shared code in dependency
// order. The pointwise functions (models and integrand) are compiled twice, for one value and for
// a lane vector of values (kernels/brdf/compat.h explains the lanes).
std::string kernelSource(int ndf, int gaf) {
  std::string src = "/* brdfbake prelude: " + ndfNames()[ndf] + " + " + gafNames()[gaf] + " */\n";
  src += "#define BRDF_NDF " + std::to_string(ndf) + "\n#define BRDF_GAF " + std::to_string(gaf) + "\n";
  const char* pointwise[] = {"kernels/brdf/smith_tables.h", "kernels/brdf/ndf.h", "kernels/brdf/gaf.h", "kernels/brdf/fresnel.h",
                             "kernels/brdf/diffuse.h", "kernels/integrate/integrand.h"};
  append(src, "kernels/brdf/compat.h");
  for (const char* f : pointwise) append(src, f);
  src += "#define BRDF_LANE_PASS 1\n#undef real\n#define real lane_t\n";
  for (const char* f : pointwise) append(src, f);
  src += "#undef BRDF_LANE_PASS\n#undef real\n#define real float\n";
  for (const char* f : {"kernels/integrate/quadrature.h", "kernels/integrate/hemisphere.h",
                        "kernels/integrate/albedo_avg.h", "kernels/integrate/diffuse_albedo.h",
                        "kernels/bake.cl"})
    append(src, f);
  return src;
}

// -w: without AVX-512, Clang warns about every float16 argument ("changes the ABI"), harmless
// here (PoCL compiles the kernel and its library for one CPU) but enough to bury a real error
// in the build log that a failed build prints.
const char* const kBuildOptions = "-cl-std=CL1.2 -w";

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

KernelRunner::KernelRunner(const cl::Device& device) : device_(device) {
  cpu_ = (device_.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_CPU) != 0;
  slots_.push_back(std::make_unique<Slot>(device_));
}

KernelRunner::~KernelRunner() = default;

namespace {
// The weight arguments (moments, fresnel, fr_x, fr_y) from index `first` on.
void setWeightArgs(cl::Kernel& k, int first, const HemiWeight& w) {
  k.setArg(first, w.moments);
  k.setArg(first + 1, w.fresnel);
  k.setArg(first + 2, w.x);
  k.setArg(first + 3, w.y);
}
// A kernel's arguments for a launch that does nothing (n = 0): PoCL compiles it at the first
// enqueue, so an empty one moves that compile into prepare.
void emptyArgs(cl::Kernel& k, const std::string& name, const cl::Buffer& dummy) {
  if (name == kHemisphere) {
    for (int i = 0; i < 4; ++i) k.setArg(i, dummy);
    k.setArg(4, 0);
    k.setArg(5, 0);
    for (int i = 6; i < 10; ++i) k.setArg(i, 0.0f);
    k.setArg(10, 0);
    setWeightArgs(k, 11, {});
  } else {
    k.setArg(0, dummy);
    k.setArg(1, dummy);
    k.setArg(2, 0);
    k.setArg(3, 0.0f);
    k.setArg(4, 0.0f);
    k.setArg(5, 0);
    if (name == kAlbedoNodes) setWeightArgs(k, 6, {});
  }
}
}  // namespace

void KernelRunner::build(Slot& slot, int slotIndex, const Work& w, Compiled* done) {
  cl::Program prog(slot.context, kernelSource(w.ndf, w.gaf));
  cl_int rc = CL_SUCCESS;
  std::string log;
  try {
    rc = prog.build({device_}, kBuildOptions);
  } catch (const cl::BuildError& e) {
    for (auto& l : e.getBuildLog()) log += l.second;
    rc = e.err();
  } catch (const cl::Error& e) {
    rc = e.err();
  }
  if (rc != CL_SUCCESS) {
    if (log.empty()) log = prog.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device_);
    throw Error(kExitSoftware, "OpenCL kernel build failed for " + ndfNames()[w.ndf] + " + " + gafNames()[w.gaf] +
                                   " (" + std::to_string(rc) + "); build log:\n" + log);
  }
  done->slot = slotIndex;
  done->program = prog;
  for (const std::string& k : w.kernels) compileKernel(*done, k);
}

void KernelRunner::compileKernel(Compiled& c, const std::string& name) {
  if (c.has(name)) return;
  if (cpu_) {
    Slot& s = *slots_[c.slot];
    cl::Kernel k(c.program, name.c_str());
    cl::Buffer dummy(s.context, CL_MEM_READ_WRITE, 64);
    emptyArgs(k, name, dummy);
    bool twoD = name != kKp;
    s.queue.enqueueNDRangeKernel(k, cl::NullRange, twoD ? cl::NDRange(kLocalX, kLocalY) : cl::NDRange(kLocalX),
                                 twoD ? cl::NDRange(kLocalX, kLocalY) : cl::NDRange(kLocalX));
    s.queue.finish();
  }
  c.kernels.push_back(name);
}

// The pair's program: the copy that has `kernel` compiled, else the first built.
KernelRunner::Compiled* KernelRunner::find(int ndf, int gaf, const char* kernel) {
  auto it = programs_.find({ndf, gaf});
  if (it == programs_.end() || it->second.empty()) return nullptr;
  if (kernel)
    for (auto& c : it->second)
      if (c->has(kernel)) return c.get();
  return it->second.front().get();
}

// k_p runs in any built program of its NDF (the lowest GAF, for a fixed choice), else in the
// NDF + none program.
KernelRunner::Compiled* KernelRunner::kpProgram(int ndf) {
  auto it = programs_.lower_bound({ndf, 0});
  if (it != programs_.end() && it->first.first == ndf) return find(ndf, it->first.second, kKp);
  return nullptr;
}

KernelRunner::Compiled& KernelRunner::compiled(int ndf, int gaf, const char* kernel) {
  if (!find(ndf, gaf)) buildHere(ndf, gaf);
  Compiled& c = *find(ndf, gaf, kernel);
  compileKernel(c, kernel);
  return c;
}

void KernelRunner::prepare(int ndf, int gaf) {
  if (!planned_ && !find(ndf, gaf)) buildHere(ndf, gaf);
}

// The pair's program, built in the main context on this thread.
void KernelRunner::buildHere(int ndf, int gaf) {
  auto fresh = std::make_unique<Compiled>();
  build(*slots_[0], 0, Work{ndf, gaf, {}}, fresh.get());
  programs_[{ndf, gaf}].push_back(std::move(fresh));
}

void KernelRunner::prepare(TableKind kind, int ndf, int gaf) {
  switch (kind) {
    case TableKind::SplitSum:
    case TableKind::Albedo:
      compiled(ndf, gaf, kHemisphere);
      break;
    case TableKind::AlbedoAvg:
      compiled(ndf, gaf, kAlbedoNodes);
      break;
    case TableKind::Kp:
      if (Compiled* c = kpProgram(ndf)) compileKernel(*c, kKp);
      else compiled(ndf, GAF_NONE, kKp);
      break;
    case TableKind::FresnelAvg:  // computed on the host
      break;
  }
}

// The programs and kernels the tables need, in the tables' order; k_p goes to a program of its
// NDF that is built anyway, else to the NDF + none one.
std::vector<KernelRunner::Work> KernelRunner::plan(const std::vector<TableNeed>& tables) const {
  std::vector<Work> work;
  auto add = [&](int ndf, int gaf, const char* kernel) {
    auto it = std::find_if(work.begin(), work.end(), [&](const Work& w) { return w.ndf == ndf && w.gaf == gaf; });
    if (it == work.end()) {
      work.push_back(Work{ndf, gaf, {}});
      it = work.end() - 1;
    }
    if (std::find(it->kernels.begin(), it->kernels.end(), kernel) == it->kernels.end()) it->kernels.push_back(kernel);
  };
  for (const TableNeed& t : tables) {
    if (t.kind == TableKind::SplitSum || t.kind == TableKind::Albedo) add(t.ndf, t.gaf, kHemisphere);
    if (t.kind == TableKind::AlbedoAvg) add(t.ndf, t.gaf, kAlbedoNodes);
  }
  for (const TableNeed& t : tables) {
    if (t.kind != TableKind::Kp) continue;
    // the lowest GAF of this NDF among programs already built or about to be
    int gaf = -1;
    for (const auto& p : programs_)
      if (p.first.first == t.ndf && (gaf < 0 || p.first.second < gaf)) gaf = p.first.second;
    for (const Work& w : work)
      if (w.ndf == t.ndf && (gaf < 0 || w.gaf < gaf)) gaf = w.gaf;
    add(t.ndf, gaf < 0 ? GAF_NONE : gaf, kKp);
  }
  return work;
}

void KernelRunner::prepareAll(const std::vector<TableNeed>& tables) {
  planned_ = true;
  std::vector<Work> work = plan(tables);
  // drop what is compiled already
  std::vector<Work> todo;
  for (Work& w : work) {
    if (Compiled* c = find(w.ndf, w.gaf)) {
      for (const std::string& k : w.kernels) compileKernel(*c, k);
    } else {
      todo.push_back(w);
    }
  }
  if (todo.empty()) return;
  int threads = buildThreads_ > 0 ? buildThreads_ : static_cast<int>(std::thread::hardware_concurrency());
  // Fewer programs than threads (the default set is one): on a CPU device, their kernels are
  // compiled in separate copies of the program, one context each; a copy costs one more build,
  // less than the kernel compile it takes off the critical path.
  if (cpu_)
    while (static_cast<int>(todo.size()) < threads) {
      auto most = std::max_element(todo.begin(), todo.end(),
                                   [](const Work& a, const Work& b) { return a.kernels.size() < b.kernels.size(); });
      if (most->kernels.size() < 2) break;
      Work rest{most->ndf, most->gaf, {}};  // the first kernel stays (the split-sum's), k_p is cheap
      rest.kernels.assign(most->kernels.begin() + 1, most->kernels.end());
      most->kernels.resize(1);
      todo.push_back(rest);
    }
  threads = std::max(1, std::min(threads, static_cast<int>(todo.size())));
  // one context per thread on a CPU device (PoCL's per-context compiler lock), else the main one
  int firstSlot = static_cast<int>(slots_.size());
  if (cpu_ && threads > 1)
    for (int t = 0; t < threads; ++t) slots_.push_back(std::make_unique<Slot>(device_));
  std::vector<std::unique_ptr<Compiled>> done(todo.size());
  std::vector<std::exception_ptr> errors(todo.size());
  std::atomic<size_t> next{0};
  auto worker = [&](int t) {
    int slot = cpu_ && threads > 1 ? firstSlot + t : 0;
    for (size_t i; (i = next++) < todo.size();) {
      try {
        done[i] = std::make_unique<Compiled>();
        build(*slots_[slot], slot, todo[i], done[i].get());
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  if (threads == 1) {
    worker(0);
  } else {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(worker, t);
    for (auto& th : pool) th.join();
  }
  for (size_t i = 0; i < todo.size(); ++i)  // the first failure in table order
    if (errors[i]) std::rethrow_exception(errors[i]);
  for (size_t i = 0; i < todo.size(); ++i) programs_[{todo[i].ndf, todo[i].gaf}].push_back(std::move(done[i]));
}

void KernelRunner::prepareAll(const std::vector<std::pair<int, int>>& pairs) {
  std::vector<TableNeed> tables;
  for (auto [ndf, gaf] : pairs)
    for (TableKind k : {TableKind::SplitSum, TableKind::AlbedoAvg, TableKind::Kp}) tables.push_back({k, ndf, gaf});
  prepareAll(tables);
}

namespace {
cl::Buffer outBuffer(const cl::Context& ctx, size_t n) { return cl::Buffer(ctx, CL_MEM_WRITE_ONLY, n * sizeof(float)); }
std::vector<float> readBack(cl::CommandQueue& q, const cl::Buffer& b, size_t n) {
  std::vector<float> v(n);
  q.enqueueReadBuffer(b, CL_TRUE, 0, n * sizeof(float), v.data());
  return v;
}
}  // namespace

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

KernelTable KernelRunner::hemisphere(int ndf, int gaf, int nx, int ny, bool nodeGrid, const HemiWeight& w) {
  Compiled& c = compiled(ndf, gaf, kHemisphere);
  Slot& s = *slots_[c.slot];
  size_t n = static_cast<size_t>(nx) * ny;
  cl::Buffer a = outBuffer(s.context, n), b = outBuffer(s.context, n), e = outBuffer(s.context, n),
             err = outBuffer(s.context, n);
  cl::Kernel k(c.program, kHemisphere);
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
  setWeightArgs(k, 11, w);
  run(c, k, nx, ny);
  KernelTable t;
  t.width = nx;
  t.height = ny;
  t.planes = {readBack(s.queue, a, n), readBack(s.queue, b, n), readBack(s.queue, e, n)};
  t.err = readBack(s.queue, err, n);
  return t;
}

namespace {
// The arguments the kernels over r share: (values, bounds, n, r range [0, 1], grid).
void setRArgs(cl::Kernel& k, const cl::Buffer& values, const cl::Buffer& bounds, int n, bool nodeGrid) {
  k.setArg(0, values);
  k.setArg(1, bounds);
  k.setArg(2, n);
  k.setArg(3, 0.0f);
  k.setArg(4, 1.0f);
  k.setArg(5, nodeGrid ? 1 : 0);
}
}  // namespace

KernelTable KernelRunner::albedoAvg(int ndf, int gaf, int n, bool nodeGrid, const HemiWeight& w) {
  Compiled& c = compiled(ndf, gaf, kAlbedoNodes);
  Slot& s = *slots_[c.slot];
  const int m = AVG_NODES;
  size_t count = static_cast<size_t>(m) * n;
  cl::Buffer e = outBuffer(s.context, count), err = outBuffer(s.context, count);
  cl::Kernel k(c.program, kAlbedoNodes);
  setRArgs(k, e, err, n, nodeGrid);
  setWeightArgs(k, 6, w);
  run(c, k, m, n);
  std::vector<float> ev = readBack(s.queue, e, count), errv = readBack(s.queue, err, count);
  // The rule (kernels/integrate/albedo_avg.h) in double: weights from the double tables, mu as
  // the device evaluated it (the float node).
  KernelTable t;
  t.width = n;
  t.height = 1;
  t.planes = {std::vector<float>(n)};
  t.err.resize(n);
  for (int j = 0; j < n; ++j) {
    double sum = 0, diff = 0, inner = 0;
    for (int i = 0; i < m; ++i) {
      double mu = static_cast<float>(brdf64::AVG_MU[i]);
      size_t x = static_cast<size_t>(j) * m + i;
      double f = 2 * mu * ev[x];
      sum += brdf64::AVG_WK[i] * f;
      diff += brdf64::AVG_WD[i] * f;
      inner += brdf64::AVG_WK[i] * 2 * mu * errv[x];
    }
    t.planes[0][j] = static_cast<float>(sum);
    t.err[j] = static_cast<float>((std::fabs(diff) + inner) / std::max(1.0, std::fabs(sum)));
  }
  return t;
}

KernelTable KernelRunner::kp(int ndf, int n, bool nodeGrid) {
  Compiled* pc = kpProgram(ndf);
  Compiled& c = pc ? *pc : compiled(ndf, GAF_NONE, kKp);
  compileKernel(c, kKp);
  Slot& s = *slots_[c.slot];
  cl::Buffer v = outBuffer(s.context, n), err = outBuffer(s.context, n);
  cl::Kernel k(c.program, kKp);
  setRArgs(k, v, err, n, nodeGrid);
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
KernelTable KernelRunner::diffuseAlbedo(int model, int nx, int ny, float pLo, float pHi, bool nodeGrid) {
  static const char* const kDiffuse = "bake_diffuse_albedo";
  Compiled* pc = programs_.empty() ? nullptr : find(programs_.begin()->first.first, programs_.begin()->first.second);
  if (!pc) {
    buildHere(NDF_GGX, GAF_SMITH_CORRELATED);
    pc = find(NDF_GGX, GAF_SMITH_CORRELATED);
  }
  Compiled& c = *pc;
  Slot& s = *slots_[c.slot];
  size_t n = static_cast<size_t>(nx) * ny;
  cl::Buffer e = outBuffer(s.context, n), err = outBuffer(s.context, n);
  cl::Kernel k(c.program, kDiffuse);
  k.setArg(0, e);
  k.setArg(1, err);
  k.setArg(2, nx);
  k.setArg(3, ny);
  k.setArg(4, 0.0f);
  k.setArg(5, 1.0f);
  k.setArg(6, pLo);
  k.setArg(7, pHi);
  k.setArg(8, nodeGrid ? 1 : 0);
  k.setArg(9, model);
  run(c, k, nx, ny);
  KernelTable t;
  t.width = nx;
  t.height = ny;
  t.planes = {readBack(s.queue, e, n)};
  t.err = readBack(s.queue, err, n);
  return t;
}

}  // namespace brdfbake
