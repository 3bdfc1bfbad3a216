// A table family: everything brdfbake knows about one group of table kinds, in one module (as a
// renderer has one plugin per BSDF). The registry (tables/registry.h) lists the families; nothing
// outside a family switches over its table kinds.
//
// A family turns a request into jobs (with their file names and checks), says which OpenCL kernels
// the jobs need, computes a job's table in memory (values, per-texel claims, metadata), adds its
// files to the bake's all-or-nothing set, and describes each job to scenes (what its values depend
// on, its cost).
#pragma once
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "formats/output_set.h"
#include "cl/runner.h"
#include "formats/exr/table_file.h"
#include "tables/job.h"
#include "tables/kind_info.h"
#include "tables/measures.h"
#include "brdfbake/report.h"
#include "brdfbake/request.h"

namespace brdfbake {

// A table computed in memory.
struct BakedTable {
  TableImage image;                        // values and metadata (3D tables: the header, planes empty)
  std::vector<double> texelBounds;         // each texel's claim (2D tables), in texel order
  std::vector<std::vector<float>> volume;  // 3D tables: one plane per channel, [(z * ny + y) * nx + x]
  int depth = 1;
  double seconds = 0;  // compute time
};

// Data a family keeps for the length of a bake (BakeContext::cache).
struct FamilyData {
  virtual ~FamilyData() = default;
};

// What a bake shares between its jobs: the device (made on first use), data read once, the
// request's observer (stages and progress, brdfbake/observer.h).
class BakeContext {
 public:
  explicit BakeContext(std::string device, std::shared_ptr<BakeObserver> observer = nullptr)
      : device_(std::move(device)), observer_(std::move(observer)) {}
  ~BakeContext();
  // The runner on the request's device; selected and created on first use (a "device" stage).
  KernelRunner& runner();
  bool hasRunner() const { return runner_ != nullptr; }
  BakeObserver* observer() const { return observer_.get(); }
  // The table the runner's long launches report progress for (its file).
  void working(const std::string& what);
  // A bake's launches that repeat an earlier one return its results (KernelRunner::setReuse); the
  // reports' and ladders' contexts leave it off, as they time their launches.
  void reuseLaunches() {
    reuse_ = true;
    if (runner_) runner_->setReuse(true);
  }
  // Data a family reads once per bake (a MERL file), keyed by the family; each family's type
  // derives from FamilyData.
  std::map<std::string, std::shared_ptr<const FamilyData>> cache;

 private:
  std::string device_;
  std::shared_ptr<BakeObserver> observer_;
  std::unique_ptr<KernelRunner> runner_;
  bool reuse_ = false;
};

// The files a bake lands together, and their report lines.
struct FileSet {
  std::deque<TableImage> keep;   // images and per-format metadata the files point into
  std::deque<BakedTable> baked;  // tables the files point into
  std::vector<OutputFile> files;
  std::vector<TableReport> reports;
  std::vector<std::function<void()>> afterCommit;  // e.g. streamed tables' kernel time into their reports
  std::map<std::string, std::map<std::string, std::string>> extraStrings;  // per path (scenes)
};

class TableFamily {
 public:
  virtual ~TableFamily() = default;
  virtual std::string name() const = 0;
  // The table kinds it defines, each described once (tables/kind_info.h); the registry gathers them.
  virtual std::vector<KindInfo> describe() const { return {}; }
  // The table kinds it bakes (--table names): those it describes, unless it bakes kinds another
  // family defines (a measured material's).
  virtual std::vector<TableKind> kinds() const;
  // The request's jobs of this family (none when the request asks for none of its kinds). Throws
  // Error(kExitUsage) naming the option for a request it cannot honour.
  virtual std::vector<Job> plan(const BakeRequest& req) const = 0;
  // The kernels a job needs built before the first table (built together, in parallel).
  virtual std::vector<KernelNeed> kernels(const Job&) const { return {}; }
  // Whether a job runs on the OpenCL device at all (host-only families: false).
  virtual bool usesDevice(const Job& job) const { return !kernels(job).empty(); }
  // Checks over all of the plan's jobs of this family before anything runs, or data read once (a MERL file) into
  // ctx.cache.
  virtual void preflight(BakeContext& /*ctx*/, const std::string& /*outDir*/,
                         const std::vector<const Job*>& /*jobs*/) const {}
  // The job's table in memory.
  virtual BakedTable compute(BakeContext& ctx, const Job& job) const = 0;
  // The job's files, one per format, and their report lines. Default: compute(), then the 2D
  // formats of a TableJob (formats/format_outputs.h). Families whose tables are too large to hold
  // bake while the set writes.
  virtual void addFiles(BakeContext& ctx, const Job& job, FileSet& set) const;
  // The files of a table compute() made, which `set` keeps (its baked deque) until they land.
  // Default: a TableJob's 2D formats.
  virtual void addBakedFiles(const Job& job, BakedTable& table, FileSet& set) const;
  // Whether the family bakes a request's `kind`: a measured material (--brdf merl:) goes to the
  // measured family, every other request to the family that lists the kind.
  virtual bool takes(const BakeRequest& req) const { return req.merl.empty(); }
  // The convergence ladder of `kind` for a request of one pair (its size, models, Fresnel), climbing
  // `budgets`:
  // each method the baker or common practice offers, at rising budgets, against the independent
  // reference. Throws Error(kExitUsage) for requests it cannot measure.
  virtual Ladder convergence(BakeContext& ctx, const BakeRequest& req, TableKind kind,
                             const LadderBudgets& budgets) const = 0;
  // Its tables' values at the stiff and extreme cases (brdfbake stress), appended to `out`.
  virtual void stress(BakeContext& /*ctx*/, std::vector<StressPoint>& /*out*/) const {}
  // Scenes: everything the job's values and header depend on, as text (content hashes).
  virtual std::string key(const Job& job) const = 0;
  virtual JobSummary summary(const Job& job) const = 0;
};

// The report line of a TableJob before its files are known.
TableReport reportOf(const TableJob& job);
// The request's formats, precision and layout on a 2D job.
void applyFormats(const BakeRequest& req, TableJob& job);
// A TableJob's scene key (every field its values and header depend on) and summary (table, size, texels).
std::string tableJobKey(const TableJob& j);
JobSummary tableJobSummary(const TableJob& j);

}  // namespace brdfbake
