#include "cl/runner.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>

#include "cl/embedded_kernels.h"
#include "cl/runner_internal.h"
#include "common/brdf_host.h"
#include "common/errors.h"

namespace brdfbake {

using namespace runner_detail;

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
// The 3D table's program: only the models and kernels/brdf3d.cl, in double where the device has it
// (compat.h BRDF_DEVICE_DOUBLE), without the integrators: it builds in a fraction of the time.
std::string volumeKernelSource(int ndf, int gaf) {
  std::string src = "/* brdfbake prelude (3D tables): " + ndfNames()[ndf] + " + " + gafNames()[gaf] + " */\n";
  src += "#define BRDF_NDF " + std::to_string(ndf) + "\n#define BRDF_GAF " + std::to_string(gaf) +
         "\n#define BRDF_DEVICE_DOUBLE 1\n";
  for (const char* f : {"kernels/brdf/compat.h", "kernels/brdf/smith_tables.h", "kernels/brdf/ndf.h", "kernels/brdf/gaf.h",
                        "kernels/brdf/fresnel.h", "kernels/brdf/diffuse.h", "kernels/brdf/brdf.h", "kernels/brdf3d.cl"})
    append(src, f);
  return src;
}

// The rough dielectric's program: the models, the rule tables, btdf.h and its estimator, in double
// where the device has it (like the 3D tables'), one value per work-item, no lanes.
std::string dielectricKernelSource(int ndf, int gaf) {
  std::string src = "/* brdfbake prelude (rough dielectric): " + ndfNames()[ndf] + " + " + gafNames()[gaf] + " */\n";
  src += "#define BRDF_NDF " + std::to_string(ndf) + "\n#define BRDF_GAF " + std::to_string(gaf) +
         "\n#define BRDF_DEVICE_DOUBLE 1\n";
  for (const char* f : {"kernels/brdf/compat.h", "kernels/brdf/smith_tables.h", "kernels/brdf/ndf.h", "kernels/brdf/gaf.h",
                        "kernels/brdf/fresnel.h", "kernels/brdf/diffuse.h", "kernels/brdf/brdf.h",
                        "kernels/integrate/quadrature.h", "kernels/integrate/albedo_avg.h", "kernels/brdf/btdf.h",
                        "kernels/integrate/dielectric.h", "kernels/dielectric.cl"})
    append(src, f);
  return src;
}

std::string kernelSource(int ndf, int gaf) {
  if (gaf >= kDielectricProgram) return dielectricKernelSource(ndf, gaf - kDielectricProgram);
  if (gaf >= kVolumeProgram) return volumeKernelSource(ndf, gaf - kVolumeProgram);
  std::string src;
  if (ndf == kSharedProgram) {  // the pair is the kernels' sel_ndf, sel_gaf arguments (kernels/bake.cl)
    src = "/* brdfbake prelude: every pair */\n#define BRDF_NDF sel_ndf\n#define BRDF_GAF sel_gaf\n";
  } else {
    src = "/* brdfbake prelude: " + ndfNames()[ndf] + " + " + gafNames()[gaf] + " */\n";
    src += "#define BRDF_NDF " + std::to_string(ndf) + "\n#define BRDF_GAF " + std::to_string(gaf) + "\n";
  }
  const char* pointwise[] = {"kernels/brdf/smith_tables.h", "kernels/brdf/ndf.h", "kernels/brdf/gaf.h", "kernels/brdf/fresnel.h",
                             "kernels/brdf/diffuse.h", "kernels/integrate/integrand.h"};
  append(src, "kernels/brdf/compat.h");
  for (const char* f : pointwise) append(src, f);
  src += "#define BRDF_LANE_PASS 1\n#undef real\n#define real lane_t\n";
  for (const char* f : pointwise) append(src, f);
  src += "#undef BRDF_LANE_PASS\n#undef real\n#define real float\n";
  for (const char* f : {"kernels/brdf/brdf.h", "kernels/integrate/quadrature.h", "kernels/integrate/azimuth.h",
                        "kernels/integrate/hemisphere.h", "kernels/integrate/hemisphere_texel.h",
                        "kernels/integrate/sheen.h", "kernels/integrate/albedo_avg.h",
                        "kernels/integrate/diffuse_albedo.h", "kernels/bake.cl"})
    append(src, f);
  return src;
}

// -w: without AVX-512, Clang warns about every float16 argument ("changes the ABI"), harmless
// here (PoCL compiles the kernel and its library for one CPU) but enough to bury a real error
// in the build log that a failed build prints.
const char* const kBuildOptions = "-cl-std=CL1.2 -w";


KernelRunner::KernelRunner(const cl::Device& device) : device_(device) {
  cpu_ = (device_.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_CPU) != 0;
  fp64_ = device_.getInfo<CL_DEVICE_EXTENSIONS>().find("cl_khr_fp64") != std::string::npos;
  slots_.push_back(std::make_unique<Slot>(device_));
}

KernelRunner::~KernelRunner() = default;

namespace {
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
    k.setArg(15, -1);
    k.setArg(16, 0);
    k.setArg(17, dummy);
    setPairArgs(k, 18, 0, 0);
  } else if (name == kDielectric || name == kDielectricNodes) {
    // (out, etas, nx, ny, zn, grid, target) or (out, mus, rs, etas, n, target)
    int bufs = name == kDielectric ? 2 : 4, ints = name == kDielectric ? 4 : 1;
    for (int i = 0; i < bufs; ++i) k.setArg(i, dummy);
    for (int i = bufs; i < bufs + ints; ++i) k.setArg(i, 0);
    k.setArg(bufs + ints, 0.0f);
  } else if (name == kBrdf3d) {
    k.setArg(0, dummy);
    k.setArg(1, dummy);
    for (int i = 2; i < 8; ++i) k.setArg(i, 0);
    k.setArg(8, 0.5f);
    k.setArg(9, 0.0f);
    k.setArg(10, 0);
    cl_float4 zero = {{0, 0, 0, 0}};
    k.setArg(11, zero);
    k.setArg(12, zero);
    k.setArg(13, -1);
    k.setArg(14, 0.0f);
    k.setArg(15, zero);
    k.setArg(16, 0);
  } else {
    k.setArg(0, dummy);
    k.setArg(1, dummy);
    k.setArg(2, 0);
    k.setArg(3, 0.0f);
    k.setArg(4, 0.0f);
    k.setArg(5, 0);
    setPairArgs(k, 6, 0, 0);
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
    throw Error(kExitSoftware, "OpenCL kernel build failed for " +
                                   (w.ndf == kSharedProgram ? std::string("every pair (the shared program)")
                                                            : ndfNames()[w.ndf] + " + " + gafNames()[w.gaf % kVolumeProgram]) +
                                   (w.gaf >= kDielectricProgram ? " (rough dielectric)"
                                    : w.gaf >= kVolumeProgram   ? " (3D tables)"
                                                                : "") +
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

// The pair's program: the copy that has `kernel` compiled, else the first built; for the
// integrators (gaf < kVolumeProgram) the shared program when the pair has none of its own.
KernelRunner::Compiled* KernelRunner::find(int ndf, int gaf, const char* kernel) {
  auto it = programs_.find({ndf, gaf});
  if ((it == programs_.end() || it->second.empty()) && gaf < kVolumeProgram)
    it = programs_.find({kSharedProgram, kSharedProgram});
  if (it == programs_.end() || it->second.empty()) return nullptr;
  if (kernel)
    for (auto& c : it->second)
      if (c->has(kernel)) return c.get();
  return it->second.front().get();
}

// k_p runs in any built program of its NDF (the lowest GAF, for a fixed choice), else in the
// shared program, else in the NDF + none program.
KernelRunner::Compiled* KernelRunner::kpProgram(int ndf) {
  auto it = programs_.lower_bound({ndf, 0});
  if (it != programs_.end() && it->first.first == ndf && it->first.second < kVolumeProgram)
    return find(ndf, it->first.second, kKp);
  if (programs_.count({kSharedProgram, kSharedProgram})) return find(kSharedProgram, kSharedProgram, kKp);
  return nullptr;
}

// The integrators' programs built for single pairs so far.
int KernelRunner::pairPrograms() const {
  int n = 0;
  for (const auto& p : programs_) n += p.first.first >= 0 && p.first.second < kVolumeProgram;
  return n;
}

// Where a pair's integrator kernels go when it has no program yet: its own, or the shared one
// (Sharing::Auto: once a runner would hold kSharedFrom pair programs).
bool KernelRunner::shareFor(int newPairs) const {
  if (sharing_ == Sharing::Shared) return true;
  if (sharing_ == Sharing::PerPair) return false;
  return programs_.count({kSharedProgram, kSharedProgram}) || pairPrograms() + newPairs >= kSharedFrom;
}

KernelRunner::Compiled& KernelRunner::compiled(int ndf, int gaf, const char* kernel) {
  if (!find(ndf, gaf)) {
    if (gaf < kVolumeProgram && shareFor(1)) buildHere(kSharedProgram, kSharedProgram);
    else buildHere(ndf, gaf);
  }
  Compiled& c = *find(ndf, gaf, kernel);
  compileKernel(c, kernel);
  return c;
}

void KernelRunner::prepare(int ndf, int gaf) {
  if (planned_ || find(ndf, gaf)) return;
  if (shareFor(1)) buildHere(kSharedProgram, kSharedProgram);
  else buildHere(ndf, gaf);
}

// The pair's program, built in the main context on this thread.
void KernelRunner::buildHere(int ndf, int gaf) {
  auto fresh = std::make_unique<Compiled>();
  build(*slots_[0], 0, Work{ndf, gaf, {}}, fresh.get());
  programs_[{ndf, gaf}].push_back(std::move(fresh));
}

void KernelRunner::prepare(const KernelNeed& need) {
  const int ndf = need.ndf, gaf = need.gaf;
  switch (need.kernel) {
    case KernelNeed::Hemisphere:
      compiled(ndf, gaf, kHemisphere);
      break;
    case KernelNeed::Kp:
      if (Compiled* c = kpProgram(ndf)) compileKernel(*c, kKp);
      else compiled(ndf, GAF_NONE, kKp);
      break;
    case KernelNeed::Brdf3d:
      compiled(ndf, gaf + kVolumeProgram, kBrdf3d);
      break;
    case KernelNeed::Dielectric:
      compiled(ndf, gaf + kDielectricProgram, kDielectric);
      break;
    case KernelNeed::DielectricNodes:
      compiled(ndf, gaf + kDielectricProgram, kDielectricNodes);
      break;
  }
}

// The programs and kernels the tables need, in the tables' order; k_p goes to a program of its
// NDF that is built anyway, else to the NDF + none one. When the tables name kSharedFrom pairs or
// more (counting those built already), one shared program serves all of their integrators.
std::vector<KernelRunner::Work> KernelRunner::plan(const std::vector<KernelNeed>& tables) const {
  std::vector<Work> work;
  auto add = [&](int ndf, int gaf, const char* kernel) {
    auto it = std::find_if(work.begin(), work.end(), [&](const Work& w) { return w.ndf == ndf && w.gaf == gaf; });
    if (it == work.end()) {
      work.push_back(Work{ndf, gaf, {}});
      it = work.end() - 1;
    }
    if (std::find(it->kernels.begin(), it->kernels.end(), kernel) == it->kernels.end()) it->kernels.push_back(kernel);
  };
  auto integrator = [](KernelNeed::Kernel k) { return k == KernelNeed::Hemisphere || k == KernelNeed::Kp; };
  // the pairs (k_p: its NDF) without a program of their own yet
  std::vector<std::pair<int, int>> fresh;
  for (const KernelNeed& t : tables) {
    if (!integrator(t.kernel)) continue;
    std::pair<int, int> key = t.kernel == KernelNeed::Kp ? std::make_pair(t.ndf, -1) : std::make_pair(t.ndf, t.gaf);
    bool built = t.kernel == KernelNeed::Kp ? std::any_of(programs_.begin(), programs_.end(),
                                                       [&](const auto& p) { return p.first.first == t.ndf && p.first.second < kVolumeProgram; })
                                         : programs_.count(key) > 0;
    if (!built && std::find(fresh.begin(), fresh.end(), key) == fresh.end()) fresh.push_back(key);
  }
  // a k_p whose NDF has a pair in the plan needs no program of its own
  fresh.erase(std::remove_if(fresh.begin(), fresh.end(),
                             [&](const std::pair<int, int>& k) {
                               return k.second < 0 && std::any_of(fresh.begin(), fresh.end(), [&](const auto& o) {
                                        return o.first == k.first && o.second >= 0;
                                      });
                             }),
              fresh.end());
  bool shared = !fresh.empty() && shareFor(static_cast<int>(fresh.size()));
  for (const KernelNeed& t : tables) {
    if (t.kernel == KernelNeed::Hemisphere) {
      if (shared && !programs_.count({t.ndf, t.gaf})) add(kSharedProgram, kSharedProgram, kHemisphere);
      else add(t.ndf, t.gaf, kHemisphere);
    }
    if (t.kernel == KernelNeed::Brdf3d) add(t.ndf, t.gaf + kVolumeProgram, kBrdf3d);
    if (t.kernel == KernelNeed::Dielectric) add(t.ndf, t.gaf + kDielectricProgram, kDielectric);
    if (t.kernel == KernelNeed::DielectricNodes) add(t.ndf, t.gaf + kDielectricProgram, kDielectricNodes);
  }
  for (const KernelNeed& t : tables) {
    if (t.kernel != KernelNeed::Kp) continue;
    // the lowest GAF of this NDF among programs already built or about to be
    int gaf = -1;
    for (const auto& p : programs_)
      if (p.first.first == t.ndf && p.first.second < kVolumeProgram && (gaf < 0 || p.first.second < gaf))
        gaf = p.first.second;
    for (const Work& w : work)
      if (w.ndf == t.ndf && w.gaf < kVolumeProgram && (gaf < 0 || w.gaf < gaf)) gaf = w.gaf;
    if (gaf >= 0) add(t.ndf, gaf, kKp);
    else if (shared || programs_.count({kSharedProgram, kSharedProgram})) add(kSharedProgram, kSharedProgram, kKp);
    else add(t.ndf, GAF_NONE, kKp);
  }
  return work;
}

void KernelRunner::prepareAll(const std::vector<KernelNeed>& tables) {
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
      // k_p alone is not worth a second build (it compiles in a tenth of the split-sum's time)
      if (most->kernels.size() < 2 || (most->kernels.size() == 2 && most->kernels[1] == kKp)) break;
      Work rest{most->ndf, most->gaf, {}};  // the first kernel stays
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
  std::vector<KernelNeed> tables;
  for (auto [ndf, gaf] : pairs)
    for (KernelNeed::Kernel k : {KernelNeed::Hemisphere, KernelNeed::Kp}) tables.push_back({k, ndf, gaf});
  prepareAll(tables);
}

}  // namespace brdfbake
