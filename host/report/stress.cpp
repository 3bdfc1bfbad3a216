#include "report/stress.h"

#include <cmath>
#include <cstdio>
#include <functional>

#include "common/errors.h"
#include "common/format.h"
#include "common/models.h"
#include "report/furnace_figure.h"
#include "report/report_page.h"
#include "tables/registry.h"

namespace brdfbake {

std::vector<StressPoint> runStress(const BakeRequest& req, std::string* pageLine) {
  BakeContext ctx(req.device);
  std::vector<StressPoint> pts;
  for (const TableFamily* f : families()) f->stress(ctx, pts);

  // the page: the table, the data, a plot of error and bound per point
  ReportPage page("brdfbake stress");
  size_t bad = 0;
  for (const StressPoint& p : pts) bad += !p.pass();
  page.verdict(bad ? ReportPage::Outcome::Fail : ReportPage::Outcome::Pass,
               bad ? std::to_string(bad) + " of " + std::to_string(pts.size()) +
                         " points fail (marked in the table and the plot)"
                   : "all " + std::to_string(pts.size()) + " points pass: finite, within their bounds, limits met");
  page.paragraph(
      "Each point: the kernel's value, its error against the independent reference (relative to "
      "max(1, |value|)), the claimed bound (the kernel's estimate + its float arithmetic, as the bake claims it), and "
      "the expected limit.");
  page.preformatted(formatStress(pts));
  std::string dat = "# index error bound pass\n";
  for (size_t i = 0; i < pts.size(); ++i)
    dat += std::to_string(i + 1) + " " + fmt4(std::max(pts[i].error, 1e-17)) + " " + fmt4(pts[i].bound) + " " +
           (pts[i].pass() ? "1" : "0") + "\n";
  page.data("stress.dat", dat);
  std::string csv = "sweep,point,value,reference,error,bound,finite,within_bound,limit,limit_met\n";
  for (const auto& p : pts)
    csv += "\"" + p.sweep + "\",\"" + p.label + "\"," + fmt4(p.value) + "," + fmt4(p.reference) + "," + fmt4(p.error) +
           "," + fmt4(p.bound) + "," + (p.finite ? "1" : "0") + "," + (p.withinBound ? "1" : "0") + ",\"" + p.limit +
           "\"," + (p.limitMet ? "1" : "0") + "\n";
  page.data("stress.csv", csv);
  page.plot(
      "stress",
      "set title 'stress: error against the reference, and the claimed bound, per point'\n"
      "set logscale y\nset format y '10^{%L}'\nset xlabel 'point (see the table)'\nset ylabel 'relative error'\n"
      "set key outside bottom center horizontal\nset grid\n"
      "plot 'stress.dat' using 1:3 with steps lw 2 title 'claimed bound', "
      "'' using 1:2 with points pt 7 title 'error'" +
          std::string(bad ? ", '' using 1:($4 < 1 ? $2 : 1/0) with points pt 6 ps 2 lc rgb 'red' title 'failing point'"
                          : ""),
      bad ? "Errors below the steps are within their claim; red circles mark the failing points."
          : "Errors below the steps are within their claim; no point fails.");
  // the white furnace of the request's pairs, as `brdfbake render` draws it
  FurnaceFigures figures(req.device);
  for (int ndf : req.ndfs)
    for (int gaf : req.gafs)
      if (pairSupported(ndf, gaf)) figures.add(page, ndf, gaf);
  *pageLine = page.write(req.outDir + "/stress");
  return pts;
}

std::string formatStress(const std::vector<StressPoint>& pts) {
  std::string s;
  char line[512];
  std::snprintf(line, sizeof line, "%3s  %-34s  %-38s  %12s  %9s  %9s  %s\n", "#", "sweep", "point", "value", "error",
                "bound", "limit");
  s += line;
  for (size_t i = 0; i < pts.size(); ++i) {
    const StressPoint& p = pts[i];
    std::string lim = p.limit.empty() ? "" : p.limit + (p.limitMet ? " (met)" : " (MISSED)");
    std::snprintf(line, sizeof line, "%3zu  %-34s  %-38s  %12.9g  %9.2e  %9.2e  %s%s%s\n", i + 1, p.sweep.c_str(),
                  p.label.c_str(), p.value, p.error, p.bound, p.finite ? "" : "NOT FINITE ",
                  p.withinBound ? "" : "OVER BOUND ", lim.c_str());
    s += line;
  }
  size_t bad = 0;
  for (const auto& p : pts) bad += !p.pass();
  s += bad ? std::to_string(bad) + " of " + std::to_string(pts.size()) + " points FAIL\n"
           : "all " + std::to_string(pts.size()) + " points pass: finite, within their bounds, limits met\n";
  return s;
}

}  // namespace brdfbake
