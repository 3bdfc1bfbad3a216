// What the families share: the bake context, the 2D tables' files and report lines, their scene keys.
#include "tables/family.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "formats/format_outputs.h"
#include "cl/device.h"

namespace brdfbake {

std::vector<TableKind> TableFamily::kinds() const {
  std::vector<TableKind> v;
  for (const KindInfo& k : describe()) v.push_back(k.kind);
  return v;
}

BakeContext::~BakeContext() = default;

KernelRunner& BakeContext::runner() {
  if (runner_) return *runner_;
  auto t0 = std::chrono::steady_clock::now();
  DeviceEntry dev = selectDevice(device_);
  runner_ = std::make_unique<KernelRunner>(dev.device);
  runner_->setReuse(reuse_);
  if (observer_) {
    // the platforms' share apart: loading the driver is most of the stage on PoCL
    char platform[64];
    std::snprintf(platform, sizeof platform, " (platforms listed in %.3f s)", dev.platformSeconds);
    observer_->stage("device", dev.platform + ": " + dev.name + platform,
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    // progress at most every 0.2 s, and always the last; seconds since the table's first report
    struct Clock {
      std::string what;
      std::chrono::steady_clock::time_point start, last;
    };
    auto clock = std::make_shared<Clock>();
    BakeObserver* obs = observer_.get();
    runner_->setProgress([obs, clock](const std::string& what, const std::string& unit, double done, double total) {
      auto now = std::chrono::steady_clock::now();
      if (what != clock->what) {
        *clock = Clock{what, now, now - std::chrono::seconds(1)};
      }
      if (done < total && now - clock->last < std::chrono::milliseconds(200)) return;
      clock->last = now;
      obs->progress(what, unit, done, total, std::chrono::duration<double>(now - clock->start).count());
    });
  }
  return *runner_;
}

void BakeContext::working(const std::string& what) {
  if (runner_) runner_->setProgressLabel(what);
}

TableReport reportOf(const TableJob& job) {
  TableReport r;
  r.table = tableName(job.kind);
  r.ndf = job.ndf >= 0 ? ndfNames()[job.ndf] : "";
  r.gaf = job.gaf >= 0 ? gafNames()[job.gaf] : "";
  r.width = job.width;
  r.height = job.height;
  return r;
}

void TableFamily::addFiles(BakeContext& ctx, const Job& job, FileSet& set) const {
  addBakedFiles(job, set.baked.emplace_back(compute(ctx, job)), set);
}

void TableFamily::addBakedFiles(const Job& job, BakedTable& t, FileSet& set) const {
  const TableJob tj = job.get<TableJob>();
  auto it = set.extraStrings.find(job.path);
  if (it != set.extraStrings.end())
    for (const auto& [k, v] : it->second) t.image.strings[k] = v;
  TableReport r = reportOf(tj);
  r.seconds = t.seconds;
  for (PlannedFile& pf : tableOutputs(FileSpec{tj.path, tj.formats, tj.precision, tj.half, tj.layout, tj.layoutName},
                                      t.image, set.keep)) {
    r.path = pf.file.path;
    r.errorBound = pf.errorBound;
    set.reports.push_back(r);
    set.files.push_back(std::move(pf.file));
  }
}

void applyFormats(const BakeRequest& req, TableJob& job) {
  job.precision = req.precision.value_or(Precision::Float32);
  job.formats = req.formats.empty() ? std::vector<FileFormat>{FileFormat::Exr} : req.formats;
  job.layout = req.layout;
  job.layoutName = job.layout.identity() && !req.layoutPreset ? "" : layoutName(req.layoutPreset, req.layout);
}

std::string tableJobKey(const TableJob& j) {
  return "table=" + tableName(j.kind) + ";ndf=" + std::to_string(j.ndf) + ";gaf=" + std::to_string(j.gaf) +
         ";size=" + std::to_string(j.width) + "x" + std::to_string(j.height) +
         ";grid=" + (j.nodeGrid ? "node" : "texel") + ";half=" + (j.half ? "1" : "0") +
         ";fresnel=" + j.fresnel.describe() + ";diffuse=" + std::to_string(j.diffuse) +
         ";texture=" + std::to_string(j.texture);
}

JobSummary tableJobSummary(const TableJob& j) {
  JobSummary s;
  s.table = tableName(j.kind);
  s.size = std::to_string(j.width) + "x" + std::to_string(j.height);
  s.texels = static_cast<double>(j.width) * j.height;
  s.cost = s.texels * 1e-6;
  return s;
}

}  // namespace brdfbake
