// What the families share: the bake context, the 2D tables' files and report lines, their scene keys.
#include "tables/family.h"

#include <algorithm>
#include <cmath>

#include "formats/format_outputs.h"
#include "cl/device.h"

namespace brdfbake {

BakeContext::~BakeContext() = default;

KernelRunner& BakeContext::runner() {
  if (!runner_) runner_ = std::make_unique<KernelRunner>(selectDevice(device_).device);
  return *runner_;
}

StressPoint stressPoint(const std::string& sweep, const std::string& label, double value, double reference,
                        double bound, double slack) {
  StressPoint p;
  p.sweep = sweep;
  p.label = label;
  p.value = value;
  p.reference = reference;
  p.bound = bound;
  p.finite = std::isfinite(value) && std::isfinite(bound);
  p.error = std::fabs(value - reference) / std::max(1.0, std::fabs(reference));
  p.withinBound = p.finite && p.error <= bound + slack;
  return p;
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
  for (PlannedFile& pf : tableOutputs(FileSpec{tj.path, tj.formats, tj.precision, tj.half, tj.layout, tj.layoutName}, t.image, set.keep)) {
    r.path = pf.file.path;
    r.errorBound = pf.errorBound;
    set.reports.push_back(r);
    set.files.push_back(std::move(pf.file));
  }
}

void applyFormats(const BakeRequest& req, TableJob& job) {
  job.precision = req.precision ? *req.precision : req.half ? Precision::Float16 : Precision::Float32;
  job.formats = req.formats.empty() ? std::vector<FileFormat>{FileFormat::Exr} : req.formats;
  job.layout = req.layout;
  job.layoutName = job.layout.identity() && !req.layoutPreset ? "" : layoutName(req.layoutPreset, req.layout);
}

std::string tableJobKey(const TableJob& j) {
  return "table=" + tableName(j.kind) + ";ndf=" + std::to_string(j.ndf) + ";gaf=" + std::to_string(j.gaf) +
         ";size=" + std::to_string(j.width) + "x" + std::to_string(j.height) + ";grid=" + (j.nodeGrid ? "node" : "texel") +
         ";half=" + (j.half ? "1" : "0") + ";fresnel=" + j.fresnel.describe() + ";diffuse=" + std::to_string(j.diffuse) +
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
