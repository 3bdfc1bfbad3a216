#include "report/convergence.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/errors.h"
#include "common/format.h"
#include "common/models.h"
#include "report/furnace_figure.h"
#include "report/report_page.h"
#include "tables/registry.h"

namespace brdfbake {

namespace {

// Log-log interpolation of the time at which a method's true error first reaches `tol`.
std::string timeTo(const std::vector<Rung>& rs, double tol) {
  for (size_t i = 0; i < rs.size(); ++i) {
    if (rs[i].error > tol) continue;
    if (i == 0) return "<= " + fmt3(rs[0].seconds) + " s";
    double x0 = std::log(rs[i - 1].seconds), x1 = std::log(rs[i].seconds);
    double y0 = std::log(std::max(rs[i - 1].error, 1e-300)), y1 = std::log(std::max(rs[i].error, 1e-300));
    double t = y1 == y0 ? 1 : (std::log(tol) - y0) / (y1 - y0);
    return fmt3(std::exp(x0 + t * (x1 - x0))) + " s";
  }
  return "not reached";
}

// Least-squares slope of log(error) against log(time) over the first rungs while the error keeps
// falling (by 20% or more per rung); NaN when the method sits at its floor from the first rung
// (errors within a factor 3: float rounding, or the reference's own accuracy).
double order(const std::vector<Rung>& rs) {
  double lo = 1e300, hi = 0;
  for (const Rung& r : rs) lo = std::min(lo, r.error), hi = std::max(hi, r.error);
  if (hi < 3 * lo) return NAN;
  std::vector<std::pair<double, double>> pts;
  for (size_t i = 0; i < rs.size(); ++i) {
    if (i > 0 && rs[i].error > rs[i - 1].error / 1.2) break;
    pts.push_back({std::log(rs[i].seconds), std::log(std::max(rs[i].error, 1e-300))});
  }
  if (pts.size() < 2) return NAN;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = static_cast<double>(pts.size());
  for (auto [x, y] : pts) sx += x, sy += y, sxx += x * x, sxy += x * y;
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

// A method's name inside gnuplot's single quotes (a quote ends the string: dropped).
std::string plotTitle(std::string s) {
  s.erase(std::remove(s.begin(), s.end(), '\''), s.end());
  return s;
}

}  // namespace

ConvergenceResult runConvergence(const BakeRequest& req, const LadderBudgets& budgets, std::string* pageLine) {
  if (req.tables.size() != 1)
    throw Error(kExitUsage, "--table: convergence measures one table kind (" + joinNames(tableNames()) + ")");
  const TableKind kind = req.tables.front();
  BakeContext ctx(req.device);
  Ladder ladder = familyFor(req, kind).convergence(ctx, req, kind, budgets);
  ConvergenceResult res;
  res.table = ladder.table;
  res.rungs = ladder.rungs;
  for (Rung& r : res.rungs) r.seconds = std::max(r.seconds, 1e-6);  // log axes: a rung under the clock's tick

  // per method: order and times to tolerance
  std::vector<std::string> methods;
  for (const Rung& r : res.rungs)
    if (std::find(methods.begin(), methods.end(), r.method) == methods.end()) methods.push_back(r.method);
  char line[512];
  std::snprintf(line, sizeof line, "%-40s  %9s  %14s  %14s  %14s\n", "method", "order", "time to 1e-3", "time to 1e-5",
                "time to 1e-7");
  res.summary = line;
  for (const std::string& m : methods) {
    std::vector<Rung> rs;
    for (const Rung& r : res.rungs)
      if (r.method == m) rs.push_back(r);
    double o = order(rs);
    std::snprintf(line, sizeof line, "%-40s  %9s  %14s  %14s  %14s\n", m.c_str(),
                  std::isnan(o) ? "at floor" : fmt3(o).c_str(), timeTo(rs, 1e-3).c_str(), timeTo(rs, 1e-5).c_str(),
                  timeTo(rs, 1e-7).c_str());
    res.summary += line;
  }
  res.summary +=
      "order: slope of log(true error) against log(time) while the error falls (\"at floor\": float "
      "rounding or the reference's accuracy from the first rung). " +
      ladder.note;

  ReportPage page("brdfbake convergence");
  {
    // the bake's method (the ladder's first): its finest rung, and how often its estimate covers the truth
    std::vector<Rung> rs;
    for (const Rung& r : res.rungs)
      if (r.method == methods.front()) rs.push_back(r);
    size_t covered = 0;
    for (const Rung& r : rs) covered += r.estimate >= r.error;
    page.verdict(ReportPage::Outcome::Measured,
                 methods.front() + ": true error " + fmt3(rs.back().error) + " in " + fmt3(rs.back().seconds) +
                     " s at its finest rung; its own estimate is at or above the true error at " +
                     std::to_string(covered) + " of " + std::to_string(rs.size()) + " rungs");
  }
  page.paragraph(res.table);
  page.preformatted(formatConvergence(res));
  std::string dat;
  for (size_t mi = 0; mi < methods.size(); ++mi) {
    dat += "# " + methods[mi] + ": seconds estimate error\n";
    for (const Rung& r : res.rungs)
      if (r.method == methods[mi])
        dat += fmt3(r.seconds) + " " + fmt3(std::max(r.estimate, 1e-17)) + " " + fmt3(std::max(r.error, 1e-17)) + "\n";
    dat += "\n\n";
  }
  page.data("convergence.dat", dat);
  std::string csv = "method,budget,seconds,estimate,error\n";
  for (const Rung& r : res.rungs)
    csv += r.method + "," + r.budget + "," + fmt3(r.seconds) + "," + fmt3(r.estimate) + "," + fmt3(r.error) + "\n";
  page.data("convergence.csv", csv);
  std::string plot = "set title 'error against run time: " + res.table +
                     "' noenhanced\n"
                     "set logscale xy\nset format y '10^{%L}'\nset xlabel 'seconds'\nset ylabel 'max relative error'\n"
                     "set key outside bottom center horizontal maxrows 3\nset grid\nplot ";
  for (size_t mi = 0; mi < methods.size(); ++mi) {
    std::string idx = std::to_string(mi);
    plot += std::string(mi ? ", " : "") + "'convergence.dat' index " + idx + " using 1:3 with linespoints lw 2 lc " +
            std::to_string(mi + 1) + " title '" + plotTitle(methods[mi]) + ": true', '' index " + idx +
            " using 1:2 with lines dt 2 lc " + std::to_string(mi + 1) + " title 'estimated'";
  }
  page.plot("convergence", plot, "Solid: true error against the reference; dashed: the method's own estimate.");
  // the white furnace of the measured pair, as `brdfbake render` draws it, for the tables it
  // samples (the split sum, the albedos, the rough dielectric's)
  if (furnaceSamples(tableName(kind)) && req.merl.empty() && req.ndfs.size() == 1 && req.gafs.size() == 1 &&
      pairSupported(req.ndfs[0], req.gafs[0]))
    FurnaceFigures(req.device).add(page, req.ndfs[0], req.gafs[0]);
  *pageLine = page.write(req.outDir + "/convergence");
  return res;
}

std::string formatConvergence(const ConvergenceResult& r) {
  std::string s = r.table + "\n";
  char line[512];
  std::snprintf(line, sizeof line, "%-40s  %-22s  %10s  %10s  %10s\n", "method", "budget", "seconds", "estimate",
                "true error");
  s += line;
  for (const Rung& g : r.rungs) {
    std::snprintf(line, sizeof line, "%-40s  %-22s  %10.3g  %10.2e  %10.2e\n", g.method.c_str(), g.budget.c_str(),
                  g.seconds, g.estimate, g.error);
    s += line;
  }
  return s + r.summary;
}

}  // namespace brdfbake
