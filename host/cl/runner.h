// OpenCL jobs: builds the per-pair specialised programs (prelude + embedded sources) and runs the
// bake kernels, one texel (or quadrature node) per work-item.
//
// Cold start. Building a program and, on PoCL, generating each kernel's work-group function at its
// first enqueue take most of a cold bake (tenths of a second each, per pair). So:
//  - prepareAll() builds every program a bake needs at once, on up to hardware_concurrency threads.
//    PoCL serialises builds within one cl_context (one LLVM context and its lock), not across
//    contexts, so on a CPU device each thread builds into its own context and the tables of a
//    program then run in the context that built it; other devices share one context.
//  - On a CPU device every launch of a kernel uses one fixed local size, and prepare() enqueues
//    each kernel once, empty, so that PoCL generates its one work-group function then (in
//    parallel) and never again for another table size or shape.
//  - k_p depends on the NDF alone: it runs in any prepared program of that NDF (its code is the
//    same in all of them), so a bake builds no program for it alone.
#pragma once
#include <CL/opencl.hpp>
#include <array>
#include <cstdint>
#include <cstring>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "common/hash.h"
#include "cl/programs.h"
#include "common/models.h"

namespace brdfbake {

// An argument of KernelRunner::launch: a number, a float4, floats or reals the kernel reads, or
// floats or reals it writes. Reals are the program's `real`: double where the device has fp64
// (KernelRunner::hasDouble), else float.
struct LaunchArg {
  enum Type { Int, Float, Float4, In, InReals, Out, OutReals } type = Int;
  int i = 0;
  float f = 0;
  cl_float4 f4 = {{0, 0, 0, 0}};
  const std::vector<float>* in = nullptr;      // In (nullptr: an empty input)
  const std::vector<double>* reals = nullptr;  // InReals (nullptr: an empty input)
  size_t out = 0;                              // Out, OutReals: how many values
  static LaunchArg of(int v) {
    LaunchArg a(Int);
    a.i = v;
    return a;
  }
  static LaunchArg of(float v) {
    LaunchArg a(Float);
    a.f = v;
    return a;
  }
  static LaunchArg of(cl_float4 v) {
    LaunchArg a(Float4);
    a.f4 = v;
    return a;
  }
  static LaunchArg input(const std::vector<float>& v) {
    LaunchArg a(In);
    a.in = &v;
    return a;
  }
  static LaunchArg inputReals(const std::vector<double>& v) {
    LaunchArg a(InReals);
    a.reals = &v;
    return a;
  }
  // an input with nothing in it (a kernel's warm arguments, KernelNeed::warm)
  static LaunchArg noInput(Type t) { return LaunchArg(t); }
  static LaunchArg output(size_t n) {
    LaunchArg a(Out);
    a.out = n;
    return a;
  }
  static LaunchArg outputReals(size_t n) {
    LaunchArg a(OutReals);
    a.out = n;
    return a;
  }

 private:
  explicit LaunchArg(Type t) : type(t) {}
};

// A kernel a table needs compiled, for an NDF/GAF pair (kp: the NDF alone, gaf ignored). Own: a
// family's own kernel (`name`) in its own program (`program`), launched with KernelRunner::launch.
// `warm`: arguments with which the kernel does nothing (sizes 0, inputs and outputs empty); on a
// CPU device prepare enqueues it so, once, so that PoCL generates its work-group function for the
// tables' local size then, in parallel with the other builds (LaunchShape::Texels). Empty: the kernel
// compiles at its first launch.
struct KernelNeed {
  enum Kernel { Hemisphere, Kp, Own } kernel;
  int ndf, gaf;
  ProgramKey::Kind program = ProgramKey::Integrators;
  const char* name = nullptr;
  std::vector<LaunchArg> warm = {};
};

// How KernelRunner::launch spreads its work-items: gx (x gy; gy = 0: a 1D range), on a CPU device
// either in the tables' fixed local size that prepare compiles (Texels: many short work-items, a
// texel or a point each) or in groups of one (One: long, uneven work-items, an LTC fit at ~3 ms each,
// which groups of one balance over the cores).
struct LaunchShape {
  size_t gx = 1, gy = 0;
  enum Groups { Texels, One } groups = One;
};

// What a launch's Out and OutReals arguments hold, each list in the arguments' order.
struct LaunchOutputs {
  std::vector<std::vector<float>> floats;
  std::vector<std::vector<double>> reals;
};

// What the albedo's two moments are (kernels/brdf/ndf.h BrdfParams): the split-sum pair by
// default; HEMI_FRESNEL with a Fresnel model puts that model's albedo in the second.
struct HemiWeight {
  int moments = 0;  // HEMI_SPLIT, HEMI_FRESNEL, HEMI_F82C
  int fresnel = 0;  // FRESNEL_*
  float x = 0, y = 0;
  float z = 0;  // what float x takes from eta^2 - 1 (kernels/brdf/fresnel.h fresnel_e2m1)
};
// The Fresnel weight of a model with its parameters in double: x and y rounded to float, and for
// the models of eta (dielectric, schlick-tir, conductor) z, so that the kernels see eta^2 - 1 of
// the eta asked for, not of its float neighbour.
HemiWeight fresnelWeight(int model, double x, double y);

struct KernelTable {
  int width = 0, height = 0;
  std::vector<std::vector<float>> planes;  // per kernel output, [y * width + x]
  std::vector<float> err;                  // per texel error bound relative to max(1, |value|)
};

class DriverWork;  // cl/driver_guard.h

class KernelRunner {
 public:
  explicit KernelRunner(const cl::Device& device);
  ~KernelRunner();

  // Builds the pair's program now (its kernels compile at their first use), unless prepareAll()
  // has run: then it does nothing (what the plan did not name is built at its first use).
  void prepare(int ndf, int gaf);
  // Compiles one kernel (for kp: in a program of that NDF, the pair's if none is built).
  void prepare(const KernelNeed& need);
  // Builds and compiles all the given kernels, concurrently (see above). Call it once, before the
  // first table; later prepare() calls for the same kernels are no-ops.
  void prepareAll(const std::vector<KernelNeed>& needs);
  // Every table of each pair (and k_p of each pair's NDF).
  void prepareAll(const std::vector<std::pair<int, int>>& pairs);

  // A, B, E over (mu, r), nx x ny.
  // muSqrt: the x axis is u = sqrt(mu) over [0, 1] (texel i holds mu = u_i^2), else mu.
  KernelTable hemisphere(int ndf, int gaf, int nx, int ny, bool nodeGrid, const HemiWeight& w = {},
                         bool muSqrt = false);
  // The same over mu in [muLo, muHi] and r in [rLo, rHi] (a 1 x 1 node grid evaluates one point).
  // level >= 0: that budget at every texel (0 default, 1 refined, 2.. finer) instead of the bake's
  // adaptive choice.
  KernelTable hemisphereRange(int ndf, int gaf, int nx, int ny, float muLo, float muHi, float rLo, float rHi,
                              bool nodeGrid, const HemiWeight& w = {}, int level = -1, bool muSqrt = false);
  // E_avg over r: GK31 panels over mu, halved where the bound is largest until it meets the
  // target (host/cl/runner_avg.cpp); E at every node on the device (one work-item per node), the
  // weighted sums and bounds here in double. With a Fresnel weight, the average of that model's
  // albedo.
  KernelTable albedoAvg(int ndf, int gaf, int n, bool nodeGrid, const HemiWeight& w = {}, float rLo = 0.0f,
                        float rHi = 1.0f);
  static constexpr double kAvgGoal = 8e-6;  // an entry's bound (relative to max(1, E_avg)), as a texel's
  // charlie's: its E(mu) rises within mu ~ 0.05 at small r, where one more halving brings the bound
  // from ~3e-6 to ~4e-8 (neubelt, r = 1/64); the microfacet NDFs' bounds are far under either goal
  static constexpr double kAvgGoalSheen = 3e-7;
  // The hemisphere kernel at arbitrary points: nodes[k] = (mu, r, refinement target, unused);
  // planes {the value (E, or with a Fresnel weight that model's albedo), its absolute bound, A, B}.
  // bare: the bound is the rule's estimate alone (kernels/integrate/hemisphere.h
  // hemisphere_moments_chosen), without the floor and the tabulated Lambda's error.
  std::vector<std::vector<float>> hemisphereNodes(int ndf, int gaf, const std::vector<cl_float4>& nodes,
                                                  const HemiWeight& w = {}, bool bare = false);
  // k_p over r.
  KernelTable kp(int ndf, int n, bool nodeGrid, float rLo = 0.0f, float rHi = 1.0f);

  // A family's own kernel: `kernel` of the pair's program of kind `program` (kernels/<its .cl>),
  // its work-items spread as `shape` says, its arguments in order; returns what the Out and OutReals
  // arguments hold. The kernel compiles at its first launch unless prepare has (KernelNeed::warm).
  LaunchOutputs launch(ProgramKey::Kind program, int ndf, int gaf, const char* kernel, const LaunchShape& shape,
                       const std::vector<LaunchArg>& args);
  // The same, gx work-items in groups of one: what each Out argument holds.
  std::vector<std::vector<float>> launch(ProgramKey::Kind program, int ndf, int gaf, const char* kernel, size_t gx,
                                         const std::vector<LaunchArg>& args) {
    return launch(program, ndf, gaf, kernel, LaunchShape{gx, 0, LaunchShape::One}, args).floats;
  }

  // Whether the device has cl_khr_fp64 (the 3D and dielectric programs then compute in double).
  bool hasDouble() const { return fp64_; }

  // Reuse within a bake: hemisphereRange and hemisphereNodes (and so hemisphere, albedoAvg and the
  // interpolation probes) keep their results, and a later launch with the same arguments, the GAF
  // taken through gaf_canonical (kernels/brdf/gaf.h), returns them instead of running again: the
  // tables of ggx + smith-exact are those of ggx + smith. hemisphereNodes keeps each point's and
  // launches only the points it has not seen. At most kReuseBytes of tables (the oldest dropped
  // first) and kReusePoints points (about 20 MiB; later points are not kept) are kept. Off by
  // default: timings and ladders run their launches again on purpose.
  static constexpr size_t kReuseBytes = size_t(64) << 20;
  static constexpr size_t kReusePoints = size_t(1) << 18;
  void setReuse(bool on) {
    reuse_ = on;
    if (!on) kept_.clear(), keptBytes_ = 0, points_.clear(), pointLaunches_.clear();
  }

  // Which program the integrator kernels (split sum, albedo, albedo-avg, k_p) of a pair run in:
  // Auto (default) builds each pair its own specialised program until a runner would hold
  // kSharedFrom of them, then one program for every pair, the pair an argument (builds in about
  // the time of two pair programs and runs ~8% slower: for a plan of many pairs it saves most of
  // the build time). The values are the same bits either way (tests/kernel_test.cpp).
  enum class Sharing { Auto, PerPair, Shared };
  static constexpr int kSharedFrom = 3;
  void setSharing(Sharing s) { sharing_ = s; }
  // Whether the shared program has been built (the tables of several pairs have run in it).
  bool sharedProgramBuilt() const;

  // Threads prepareAll uses (default: hardware_concurrency; 1 = in order on this thread).
  void setBuildThreads(int n) { buildThreads_ = n; }
  // Long launches report progress (done of total units) through `fn`, for the table named by
  // setProgressLabel; a 2D table of more than kBandTexels texels then runs in bands of rows.
  using Progress = std::function<void(const std::string& what, const std::string& unit, double done, double total)>;
  void setProgress(Progress fn) { progress_ = std::move(fn); }
  void setProgressLabel(std::string what) { progressLabel_ = std::move(what); }
  // Reports progress of the labelled table (no-op without a callback); 3D tables call it per slab.
  void progress(const std::string& unit, double done, double total) const {
    if (progress_) progress_(progressLabel_, unit, done, total);
  }
  static constexpr size_t kBandTexels = 1 << 16;

  // How programs use the program cache (cl/program_cache.h): On (default) loads a matching binary
  // and stores a source build's; Off neither; Refresh builds from source and stores the binary in
  // `dir` (`brdfbake devices --prepare DIR`).
  enum class ProgramCacheUse { On, Off, Refresh };
  void setProgramCache(ProgramCacheUse use, std::string dir = "") {
    cacheUse_ = use;
    cacheDir_ = std::move(dir);
  }

  // A program made ready: loaded from a cached binary or built from source, and what it cost
  // (wall seconds, kernels' first compile included), in the order they finished.
  struct ProgramEvent {
    std::string program, how;
    double seconds = 0;
    bool loaded = false;
    bool stored = false;  // built, and its binary kept for the next run
  };
  std::vector<ProgramEvent> programEvents() const {
    std::lock_guard<std::mutex> lock(eventsMutex_);
    return events_;
  }
  // Directional albedo E(mu) of diffuse model `model` (kernels/brdf/diffuse.h, DIFFUSE_*) over
  // mu in [0, 1] (x, nx) and its parameter in [pLo, pHi] (y, ny); planes {E}, err relative to
  // max(1, |E|). Runs in any built program (the kernel is in all), else builds ggx + smith-correlated.
  KernelTable diffuseAlbedo(int model, int nx, int ny, float pLo, float pHi, bool nodeGrid, float muLo = 0.0f,
                            float muHi = 1.0f);

 private:
  struct Slot;      // a context and its queue
  struct Compiled;  // a built program, the slot it lives in, the kernels compiled so far
  struct Work {     // one program to build and the kernels to compile in it
    ProgramKey key;
    std::vector<std::string> kernels;
  };

  Compiled& compiled(const ProgramKey& key, const char* kernel);
  Compiled* find(const ProgramKey& key, const char* kernel = nullptr);
  Compiled* kpProgram(int ndf);
  void build(Slot& slot, int slotIndex, const Work& w, Compiled* done);
  void buildHere(const ProgramKey& key);
  void compileKernel(Compiled& c, const std::string& kernel);
  void remember(const KernelNeed& need);
  std::vector<Work> plan(const std::vector<KernelNeed>& needs) const;
  int pairPrograms() const;
  bool shareFor(int newPairs) const;
  void run(Compiled& c, cl::Kernel& k, size_t gx, size_t gy);
  // the kept results of a launch (setReuse), by its arguments
  const std::vector<std::vector<float>>* reused(const std::string& key) const;
  void keep(const std::string& key, const std::vector<std::vector<float>>& planes);
  void runRows(Compiled& c, cl::Kernel& k, size_t gx, size_t gy);
  // hemisphereNodes' launch of the points given, all of them
  std::vector<std::vector<float>> nodesLaunch(int ndf, int gaf, const std::vector<cl_float4>& nodes,
                                              const HemiWeight& w, bool bare);

  cl::Device device_;
  // PoCL writes into its kernel cache while it builds and first launches kernels: its failures
  // there are said as such for the runner's life (cl/driver_guard.h).
  std::unique_ptr<DriverWork> driverWork_;
  std::string driverCache_;  // PoCL's kernel cache directory; "" on other drivers
  bool cpu_ = false;
  bool fp64_ = false;     // the device has cl_khr_fp64: the 3D tables' programs compute in double
  bool planned_ = false;  // prepareAll() has run
  // the warm arguments of the families' kernels named in prepare (KernelNeed::warm), by kernel name;
  // written before builds start, read by the build threads
  std::map<std::string, std::vector<LaunchArg>> warm_;
  int buildThreads_ = 0;
  Sharing sharing_ = Sharing::Auto;
  std::vector<std::unique_ptr<Slot>> slots_;  // [0]: the main context
  // per program: in one context, or in several with different kernels compiled
  std::map<ProgramKey, std::vector<std::unique_ptr<Compiled>>> programs_;
  ProgramCacheUse cacheUse_ = ProgramCacheUse::On;
  Progress progress_;
  std::string progressLabel_;
  std::string cacheDir_;            // Refresh: where binaries go
  mutable std::mutex eventsMutex_;  // builds run on several threads (prepareAll)
  std::vector<ProgramEvent> events_;
  bool reuse_ = false;
  struct Kept {
    std::string key;
    std::vector<std::vector<float>> planes;
    size_t bytes;
  };
  std::deque<Kept> kept_;
  size_t keptBytes_ = 0;
  // hemisphereNodes' results point by point (setReuse), by the launch's arguments and the point:
  // the albedo table's probes are mostly points of the split sum's (the same layer points on every
  // fourth row), and a point's values do not depend on the others in its launch. A key is the
  // launch's index in pointLaunches_ and the point's bits: keyed by a string of the arguments'
  // bytes per point, every pair's bake spends 0.15 s of its 6 s building and hashing them (perf).
  struct PointKey {
    uint32_t launch;
    uint32_t bits[4];
    bool operator==(const PointKey& o) const {
      return launch == o.launch && std::memcmp(bits, o.bits, sizeof bits) == 0;
    }
  };
  struct PointHash {
    size_t operator()(const PointKey& k) const {
      uint64_t h = kFnvSeed ^ k.launch;
      for (uint32_t b : k.bits) h = fnvMix(h, b);
      return static_cast<size_t>(h ^ (h >> 29));
    }
  };
  std::vector<std::string> pointLaunches_;
  std::unordered_map<PointKey, std::array<float, 4>, PointHash> points_;
};

}  // namespace brdfbake
