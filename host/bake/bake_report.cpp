// The text a bake prints: its report (one line per file), and `info`'s warning when an energy
// table exceeds 1 by more than its bound.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "bake/bake.h"
#include "common/format.h"
#include "tables/registry.h"

namespace brdfbake {

std::string formatReport(const std::vector<TableReport>& reports) {
  // columns as wide as their longest entry
  size_t wf = 4, wt = 5;
  for (const auto& r : reports) {
    wf = std::max(wf, r.path.size());
    wt = std::max(wt, r.table.size());
  }
  std::string s;
  char line[1024];
  std::snprintf(line, sizeof line, "%-*s  %-*s  %9s  %9s  %7s\n", int(wf), "file", int(wt), "table", "size",
                "max error", "seconds");
  s += line;
  for (const auto& r : reports) {
    std::string size =
        std::to_string(r.width) + "x" + std::to_string(r.height) + (r.depth > 1 ? "x" + std::to_string(r.depth) : "");
    std::snprintf(line, sizeof line, "%-*s  %-*s  %9s  %9.2e  %7.3f\n", int(wf), r.path.c_str(), int(wt),
                  r.table.c_str(), size.c_str(), r.errorBound, r.seconds);
    s += line;
    if (!r.note.empty()) s += "  " + r.note + "\n";
  }
  // what the user also waited for: the seconds column is each table's own kernel time
  if (!reports.empty() && reports[0].buildSeconds > 0) {
    std::snprintf(line, sizeof line, "  + %.3f s making the OpenCL programs ready before the first table%s\n",
                  reports[0].buildSeconds,
                  reports[0].buildHow.empty() ? "" : (" (" + reports[0].buildHow + ")").c_str());
    s += line;
  }
  return s;
}

std::string energyWarnings(const TableImage& t) {
  auto str = [&](const char* k) {
    auto it = t.strings.find(k);
    return it == t.strings.end() ? std::string() : it->second;
  };
  // brdfbake never writes a texel that is not finite: such a file is damaged, or not one of ours,
  // and its maximum says nothing about the model
  size_t bad = 0;
  for (const auto& p : t.planes)
    for (float v : p) bad += !std::isfinite(v);
  if (bad)
    return "warning: " + std::to_string(bad) +
           " texel value(s) are not finite (NaN or Inf): brdfbake never writes one; "
           "the file is damaged or was not written by brdfbake\n";
  // the energy quantity and its channel, as the kind's family describes them (E = A + B in the
  // split sum's B, E in the albedo's R, ...)
  const KindInfo* kind = findKind(str("brdf.table"));
  if (!kind || kind->energy.empty()) return "";
  const std::string &name = kind->energy, &channel = kind->energyChannel;
  for (size_t c = 0; c < t.channels.size(); ++c) {
    if (t.channels[c] != channel) continue;
    float mx = 0;
    for (float v : t.planes[c]) mx = std::max(mx, v);
    double tol = 0;
    auto e = t.floats.find("brdf.error");
    if (e != t.floats.end()) tol = e->second;
    if (mx > 1 + tol) {
      char b[64];
      std::snprintf(b, sizeof b, "%.4g", mx);
      if (str("brdf.material").rfind("merl:", 0) == 0)  // measured data: the file, not a model
        return "warning: " + name + " exceeds 1 (max " + b + "): " + str("brdf.material") +
               " reflects more than it receives (a measurement or calibration error in the data)\n";
      if (!str("brdf.diffuse").empty() && kind->albedo && !kind->average) {  // a diffuse model's albedo
        std::string d = str("brdf.diffuse");
        std::string why = d == "burley" ? " (a known property of Burley's model: rough surfaces at grazing angles)"
                          : d == "oren-nayar"
                              ? " (a property of the qualitative model's A and B: E(0) = A + B/2 > 1 for small sigma)"
                              : " (an erratum of the source documents, kept on purpose)";
        return "warning: " + name + " exceeds 1 (max " + b + "): the " + d + " diffuse model does not conserve energy" +
               why + "; see docs/MODELS.md, \"Diffuse models\"\n";
      }
      if (str("brdf.ndf") == "charlie")
        return "warning: " + name + " exceeds 1 (max " + b + ") at grazing views of smooth sheens: charlie with " +
               str("brdf.gaf") +
               (str("brdf.gaf") == "charlie-smith" ? " (a fitted Lambda, finite at grazing: G/(n.o) grows as mu -> 0)"
                                                   : " (no masking: E(0, r) grows like 1/r)") +
               " does not conserve energy there; clamp 1 - E in albedo scaling; see docs/MODELS.md, \"Sheen\"\n";
      return "warning: " + name + " exceeds 1 (max " + b + "): a single-scattering albedo cannot; " + str("brdf.ndf") +
             " with " + str("brdf.gaf") +
             (str("brdf.gaf") == "none" ? " (G = 1, albedo ~ 1/mu at grazing)"
                                        : " (a Lambda borrowed from Beckmann, not the NDF's own; " + str("brdf.gaf") +
                                              "-exact has the exact one)") +
             " does not conserve energy; see docs/MODELS.md, \"Tables that exceed 1\"\n";
    }
  }
  return "";
}

std::string planHeader(size_t tableWidth, size_t statusWidth) {
  char line[256];
  std::snprintf(line, sizeof line, "  %-*s  %-12s  %10s  %7s  %-*s  %s\n", static_cast<int>(tableWidth), "table",
                "size", "texels", "est. s", static_cast<int>(statusWidth), "status", "file");
  return line;
}

std::string planLine(size_t tableWidth, size_t statusWidth, const std::string& table, const std::string& size,
                     double texels, double seconds, const std::string& status, const std::string& file) {
  char line[256];
  std::snprintf(line, sizeof line, "  %-*s  %-12s  %10.0f  %7s  %-*s  ", static_cast<int>(tableWidth), table.c_str(),
                size.c_str(), texels, fmtSeconds(seconds).c_str(), static_cast<int>(statusWidth), status.c_str());
  return line + file + "\n";  // a path may be longer than any fixed buffer
}

std::string formatPlan(const Plan& plan) {
  std::vector<JobSummary> sums;
  double cost = 0;
  size_t wt = 5;
  for (const Job& j : plan.jobs) {
    sums.push_back(j.family->summary(j));
    cost += sums.back().cost;
    wt = std::max(wt, sums.back().table.size());
  }
  std::string out = "dry run: " + std::to_string(plan.jobs.size()) + " table(s) into " + plan.outDir + "/, about " +
                    fmtSeconds(cost) + " s on 2 cores (estimated); nothing is computed or written\n";
  out += planHeader(wt, 8);
  std::error_code ec;
  for (size_t i = 0; i < plan.jobs.size(); ++i) {
    const JobSummary& s = sums[i];
    const std::vector<std::string> files = s.files.empty() ? std::vector<std::string>{plan.jobs[i].path} : s.files;
    bool there = false;
    std::string names;
    for (const std::string& f : files) {
      there = there || std::filesystem::exists(f, ec);
      names += (names.empty() ? "" : ", ") + f;
    }
    out += planLine(wt, 8, s.table, s.size, s.texels, s.cost, there ? "replaces" : "new", names);
    out += "    " + s.models + "\n";
  }
  return out;
}

}  // namespace brdfbake
