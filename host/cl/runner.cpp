#include "cl/runner.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "cl/device.h"
#include "cl/driver_guard.h"
#include "cl/program_cache.h"
#include "cl/programs.h"
#include "cl/runner_internal.h"
#include "common/brdf_host.h"
#include "common/errors.h"

namespace brdfbake {

using namespace runner_detail;

const char* const kBuildOptions = kProgramBuildOptions;

KernelRunner::KernelRunner(const cl::Device& device) : device_(device) {
  cpu_ = (device_.getInfo<CL_DEVICE_TYPE>() & CL_DEVICE_TYPE_CPU) != 0;
  fp64_ = device_.getInfo<CL_DEVICE_EXTENSIONS>().find("cl_khr_fp64") != std::string::npos;
  slots_.push_back(std::make_unique<Slot>(device_));
  if (onPocl(device_)) {
    driverCache_ = poclCacheDir();
    driverWork_ = std::make_unique<DriverWork>(driverCache_);
  }
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
    k.setArg(11 + kWeightArgs, -1);
    k.setArg(12 + kWeightArgs, 0);
    k.setArg(13 + kWeightArgs, dummy);
    setPairArgs(k, 14 + kWeightArgs, 0, 0);
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

namespace {
// Builds `prog` for `device`; the build log when it fails, "" when it builds.
std::string buildLog(cl::Program& prog, const cl::Device& device, cl_int* rc) {
  std::string log;
  *rc = CL_SUCCESS;
  try {
    *rc = prog.build({device}, kBuildOptions);
  } catch (const cl::BuildError& e) {
    for (auto& l : e.getBuildLog()) log += l.second;
    *rc = e.err();
  } catch (const cl::Error& e) {
    *rc = e.err();
  }
  if (*rc != CL_SUCCESS && log.empty()) log = prog.getBuildInfo<CL_PROGRAM_BUILD_LOG>(device);
  return log;
}
}  // namespace

// A program from its binary in the program cache (cl/program_cache.h) when one matches, else from
// source; a source build's binary is stored once its kernels are compiled (on PoCL the binary
// then holds their work-group functions too).
void KernelRunner::build(Slot& slot, int slotIndex, const Work& w, Compiled* done) {
  auto t0 = std::chrono::steady_clock::now();
  const std::string& driverCache = driverCache_;
  const std::string source = programSource(w.key), name = programName(w.key);
  const std::string identity = programIdentity(device_, name, kBuildOptions, source);
  std::string where;
  bool loaded = false;
  cl::Program prog;
  cl_int rc = CL_SUCCESS;
  if (cacheUse_ == ProgramCacheUse::On)
    if (std::optional<ProgramBinary> bin = loadProgram(identity, &where)) {
      try {
        prog = cl::Program(slot.context, {device_}, cl::Program::Binaries{*bin});
        loaded = buildLog(prog, device_, &rc).empty() && rc == CL_SUCCESS;
      } catch (const cl::Error&) {
        loaded = false;  // a binary the driver refuses: built from source below
      }
    }
  if (!loaded) {
    if (!driverCache.empty()) checkDriverCacheSpace(driverCache);
    prog = cl::Program(slot.context, source);
    std::string log = buildLog(prog, device_, &rc);
    if (rc != CL_SUCCESS)
      throw Error(driverCache.empty() ? kExitSoftware : driverFailureCode(log, driverCache),
                  "OpenCL kernel build failed for " + name + " (" + std::to_string(rc) + "); build log:\n" + log +
                      (driverCache.empty() ? std::string() : driverCacheHint(log, driverCache)));
  }
  done->slot = slotIndex;
  done->program = prog;
  for (const std::string& k : w.kernels) compileKernel(*done, k);
  std::string how = loaded ? "loaded " + where : "built from source";
  bool stored = false;
  if (!loaded && cacheUse_ != ProgramCacheUse::Off) {
    cl::Program::Binaries bins = prog.getInfo<CL_PROGRAM_BINARIES>();
    const std::string dir = cacheUse_ == ProgramCacheUse::Refresh ? cacheDir_ : programCacheWriteDir();
    const std::string why = storeProgram(identity, bins.empty() ? ProgramBinary{} : bins.front(), dir);
    stored = why.empty();
    how += stored ? ", binary stored in " + dir : ", binary not stored: " + why;
  }
  std::lock_guard<std::mutex> lock(eventsMutex_);
  events_.push_back(
      {name, how, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), loaded, stored});
}

void KernelRunner::compileKernel(Compiled& c, const std::string& name) {
  if (c.has(name)) return;
  // the integrators' kernels, and a family's kernels with warm arguments, launch once empty here;
  // a family's other kernels compile at their first launch
  const auto warm = warm_.find(name);
  const bool known = name == kHemisphere || name == kKp || name == "bake_diffuse_albedo" || warm != warm_.end();
  if (cpu_ && known) {
    Slot& s = *slots_[c.slot];
    cl::Kernel k(c.program, name.c_str());
    cl::Buffer dummy(s.context, CL_MEM_READ_WRITE, 64);
    std::vector<cl::Buffer> ins, outs;
    if (warm != warm_.end())
      setLaunchArgs(k, s.context, warm->second, fp64_, &ins, &outs);
    else
      emptyArgs(k, name, dummy);
    bool twoD = name != kKp;
    s.queue.enqueueNDRangeKernel(k, cl::NullRange, twoD ? cl::NDRange(kLocalX, kLocalY) : cl::NDRange(kLocalX),
                                 twoD ? cl::NDRange(kLocalX, kLocalY) : cl::NDRange(kLocalX));
    s.queue.finish();
  }
  c.kernels.push_back(name);
}

// The program's copy that has `kernel` compiled, else the first built; for one pair's integrators
// the shared program when the pair has none of its own.
KernelRunner::Compiled* KernelRunner::find(const ProgramKey& key, const char* kernel) {
  auto it = programs_.find(key);
  if ((it == programs_.end() || it->second.empty()) && key.kind == ProgramKey::Integrators)
    it = programs_.find(ProgramKey::shared());
  if (it == programs_.end() || it->second.empty()) return nullptr;
  if (kernel)
    for (auto& c : it->second)
      if (c->has(kernel)) return c.get();
  return it->second.front().get();
}

namespace {
ProgramKey integrators(int ndf, int gaf) { return {ProgramKey::Integrators, ndf, gaf}; }
}  // namespace

// k_p runs in any built integrators program of its NDF (the lowest GAF, for a fixed choice), else
// in the shared program, else in the NDF + none program.
KernelRunner::Compiled* KernelRunner::kpProgram(int ndf) {
  auto it = programs_.lower_bound(integrators(ndf, 0));
  if (it != programs_.end() && it->first.kind == ProgramKey::Integrators && it->first.ndf == ndf)
    return find(it->first, kKp);
  if (programs_.count(ProgramKey::shared())) return find(ProgramKey::shared(), kKp);
  return nullptr;
}

// The integrators' programs built for single pairs so far.
int KernelRunner::pairPrograms() const {
  int n = 0;
  for (const auto& p : programs_) n += p.first.kind == ProgramKey::Integrators && !p.first.isShared();
  return n;
}

// Where a pair's integrator kernels go when it has no program yet: its own, or the shared one
// (Sharing::Auto: once a runner would hold kSharedFrom pair programs).
bool KernelRunner::shareFor(int newPairs) const {
  if (sharing_ == Sharing::Shared) return true;
  if (sharing_ == Sharing::PerPair) return false;
  return programs_.count(ProgramKey::shared()) || pairPrograms() + newPairs >= kSharedFrom;
}

bool KernelRunner::sharedProgramBuilt() const { return programs_.count(ProgramKey::shared()) > 0; }

KernelRunner::Compiled& KernelRunner::compiled(const ProgramKey& key, const char* kernel) {
  if (!find(key)) {
    if (key.kind == ProgramKey::Integrators && shareFor(1))
      buildHere(ProgramKey::shared());
    else
      buildHere(key);
  }
  Compiled& c = *find(key, kernel);
  compileKernel(c, kernel);
  return c;
}

void KernelRunner::prepare(int ndf, int gaf) {
  if (planned_ || find(integrators(ndf, gaf))) return;
  buildHere(shareFor(1) ? ProgramKey::shared() : integrators(ndf, gaf));
}

// The program, built in the main context on this thread.
void KernelRunner::buildHere(const ProgramKey& key) {
  auto fresh = std::make_unique<Compiled>();
  build(*slots_[0], 0, Work{key, {}}, fresh.get());
  programs_[key].push_back(std::move(fresh));
}

namespace {
// The program and kernel of a need other than the integrators' (which the plan shares or not).
std::pair<ProgramKey, const char*> ownProgram(const KernelNeed& need) {
  switch (need.kernel) {
    case KernelNeed::Own:
      return {{need.program, need.ndf, need.gaf}, need.name};
    case KernelNeed::Hemisphere:
      break;
    case KernelNeed::Kp:
      break;
  }
  return {integrators(need.ndf, need.gaf), kHemisphere};
}
}  // namespace

void KernelRunner::remember(const KernelNeed& need) {
  if (need.kernel == KernelNeed::Own && !need.warm.empty()) warm_[need.name] = need.warm;
}

void KernelRunner::prepare(const KernelNeed& need) {
  remember(need);
  if (need.kernel == KernelNeed::Kp) {
    if (Compiled* c = kpProgram(need.ndf))
      compileKernel(*c, kKp);
    else
      compiled(integrators(need.ndf, GAF_NONE), kKp);
    return;
  }
  auto [key, kernel] = ownProgram(need);
  compiled(key, kernel);
}

// The programs and kernels the tables need, in the tables' order; k_p goes to a program of its
// NDF that is built anyway, else to the NDF + none one. When the tables name kSharedFrom pairs or
// more (counting those built already), one shared program serves all of their integrators.
std::vector<KernelRunner::Work> KernelRunner::plan(const std::vector<KernelNeed>& tables) const {
  std::vector<Work> work;
  auto add = [&](const ProgramKey& key, const char* kernel) {
    auto it = std::find_if(work.begin(), work.end(), [&](const Work& w) { return w.key == key; });
    if (it == work.end()) {
      work.push_back(Work{key, {}});
      it = work.end() - 1;
    }
    if (std::find(it->kernels.begin(), it->kernels.end(), kernel) == it->kernels.end()) it->kernels.push_back(kernel);
  };
  auto builtFor = [&](int ndf) {
    return std::any_of(programs_.begin(), programs_.end(),
                       [&](const auto& p) { return p.first.kind == ProgramKey::Integrators && p.first.ndf == ndf; });
  };
  // the pairs (k_p: its NDF, gaf -1) without an integrators program of their own yet
  std::vector<std::pair<int, int>> fresh;
  for (const KernelNeed& t : tables) {
    if (t.kernel != KernelNeed::Hemisphere && t.kernel != KernelNeed::Kp) continue;
    const bool kp = t.kernel == KernelNeed::Kp;
    std::pair<int, int> pair{t.ndf, kp ? -1 : t.gaf};
    bool built = kp ? builtFor(t.ndf) : programs_.count(integrators(t.ndf, t.gaf)) > 0;
    if (!built && std::find(fresh.begin(), fresh.end(), pair) == fresh.end()) fresh.push_back(pair);
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
    if (t.kernel == KernelNeed::Kp) continue;
    if (t.kernel == KernelNeed::Hemisphere && shared && !programs_.count(integrators(t.ndf, t.gaf))) {
      add(ProgramKey::shared(), kHemisphere);
      continue;
    }
    auto [key, kernel] = ownProgram(t);
    add(key, kernel);
  }
  for (const KernelNeed& t : tables) {
    if (t.kernel != KernelNeed::Kp) continue;
    // the lowest GAF of this NDF among integrators programs already built or about to be
    int gaf = -1;
    for (const auto& p : programs_)
      if (p.first.kind == ProgramKey::Integrators && p.first.ndf == t.ndf && (gaf < 0 || p.first.gaf < gaf))
        gaf = p.first.gaf;
    for (const Work& w : work)
      if (w.key.kind == ProgramKey::Integrators && w.key.ndf == t.ndf && (gaf < 0 || w.key.gaf < gaf)) gaf = w.key.gaf;
    if (gaf >= 0)
      add(integrators(t.ndf, gaf), kKp);
    else if (shared || programs_.count(ProgramKey::shared()))
      add(ProgramKey::shared(), kKp);
    else
      add(integrators(t.ndf, GAF_NONE), kKp);
  }
  return work;
}

void KernelRunner::prepareAll(const std::vector<KernelNeed>& tables) {
  planned_ = true;
  for (const KernelNeed& t : tables) remember(t);  // before the build threads read warm_
  std::vector<Work> work = plan(tables);
  // drop what is compiled already
  std::vector<Work> todo;
  for (Work& w : work) {
    if (Compiled* c = find(w.key)) {
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
      Work rest{most->key, {}};  // the first kernel stays
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
  for (size_t i = 0; i < todo.size(); ++i) programs_[todo[i].key].push_back(std::move(done[i]));
}

void KernelRunner::prepareAll(const std::vector<std::pair<int, int>>& pairs) {
  std::vector<KernelNeed> tables;
  for (auto [ndf, gaf] : pairs)
    for (KernelNeed::Kernel k : {KernelNeed::Hemisphere, KernelNeed::Kp}) tables.push_back({k, ndf, gaf});
  prepareAll(tables);
}

}  // namespace brdfbake
