#include "tables/error_model.h"
#include "report/verify.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <vector>
#include <random>

#include "cl/device.h"
#include "cl/runner.h"
#include "tables/dielectric/dielectric_bake.h"
#include "brdfbake/brdfbake.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "brdfbake/table_kind.h"
#include "common/models.h"
#include "reference/reference.h"
#include "report/furnace_figure.h"
#include "report/report_page.h"

namespace brdfbake {

namespace {

constexpr double kAllowance = 1e-6;        // the dielectric kernels' float arithmetic (host/bake)
constexpr double kWeakFurnaceTol = 1e-6;   // |W(mu)/mu - 1| for an exact Smith pairing
constexpr double kNormTol = 1e-6;          // |int D (n.h) dw - 1|
constexpr double kReciprocityTol = 1e-12;  // relative, in double
constexpr int kReciprocityPairs = 2000;

std::string pairName(int ndf, int gaf) { return ndfNames()[ndf] + "+" + gafNames()[gaf]; }
std::string fileStem(int ndf, int gaf) { return ndfNames()[ndf] + "_" + gafNames()[gaf]; }

bool isSmith(int gaf) { return gafNames()[gaf].rfind("smith", 0) == 0; }

// White furnace: E(mu, r) <= 1 + bound everywhere; node grid (texel centres for gaf none, whose E
// is infinite at mu = 0). Writes the heat map data.
VerifyCheck whiteFurnace(const Table& t, int n, bool node, ReportPage& page, int ndf, int gaf) {
  VerifyCheck c{"white furnace", true, true, 0, "", ""};
  double maxE = -1;
  std::string csv = "# mu r E bound\n";
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      size_t k = static_cast<size_t>(j) * n + i;
      double mu = node ? i / (n - 1.0) : (i + 0.5) / n, r = node ? j / (n - 1.0) : (j + 0.5) / n;
      // the bake's own claim for the texel, relative to max(1, |E|)
      double e = t.planes[0][k], bound = t.texelBounds[k] * std::max(1.0, std::fabs(e));
      csv += fmt4(mu) + " " + fmt4(r) + " " + std::to_string(e) + " " + fmt4(bound) + "\n";
      if (e > maxE) {
        maxE = e;
        c.where = "mu=" + fmt4(mu) + " r=" + fmt4(r);
      }
      if (e > 1 + bound) {
        c.pass = false;
        c.worst = std::max(c.worst, e - 1);
      }
    }
    csv += "\n";
  }
  c.detail = "max E = " + std::to_string(maxE) + " at " + c.where;
  std::string stem = fileStem(ndf, gaf);
  page.data("furnace_" + stem + ".dat", csv);
  // the colour scale always reaches E = 1 and marks it; red texels (and their legend entry) only
  // where a texel is over its bound, so that a passing pair's map shows no sign of failure
  // gnuplot draws each node as a pixel centred on it and does not clip the image to the axes: on
  // the node grid the range reaches half a node past 0 and 1, so that the map stays inside its box
  // (seen in Chromium's screenshot of the page)
  const double half = node ? 0.5 / (n - 1) : 0.0;
  const std::string range = fmt4(-half) + ":" + fmt4(1 + half);
  const std::string over = c.pass ? std::string()
                                  : ", '' using 1:($3 > 1 + $4 ? $2 : 1/0) with points pt 5 ps 0.5 lc rgb 'red' "
                                    "title 'E > 1 + bound'";
  page.plot("furnace_" + stem,
            "set title '" + pairName(ndf, gaf) + ": directional albedo E(mu, r)" +
                (c.pass ? "" : "; red: E > 1 + bound") +
                "'\n"
                "set xlabel 'mu = n.o'\nset ylabel 'r (perceptual roughness)'\nset cblabel 'E'\n"
                "set xrange [" +
                range + "]\nset yrange [" + range + "]\nset cbrange [0:" + fmt4(std::max(1.0, maxE)) +
                "]\n"
                "set cbtics add ('E = 1' 1)\n"
                "set palette defined (0 '#081d58', 0.4 '#225ea8', 0.7 '#41b6c4', 0.9 '#c7e9b4', 1 '#ffffd9')\n"
                "plot 'furnace_" +
                stem + ".dat' using 1:2:3 with image notitle" + over,
            "White furnace of " + pairName(ndf, gaf) + ": " + c.detail + ".");
  return c;
}

// The energy a single-scattering lobe loses, 1 - E, against r: at mu = 1, 1/2, 1/8 and averaged.
void energyLoss(const Table& t, const Table& avg, int n, bool node, ReportPage& page, int ndf, int gaf) {
  auto col = [&](double mu) {
    int i = static_cast<int>(std::lround(node ? mu * (n - 1) : mu * n - 0.5));
    return std::clamp(i, 0, n - 1);
  };
  std::string csv = "# r 1-E_avg 1-E(mu=1) 1-E(mu=0.5) 1-E(mu=0.125)\n";
  for (int j = 0; j < n; ++j) {
    double r = node ? j / (n - 1.0) : (j + 0.5) / n;
    csv += fmt4(r) + " " + fmt4(1 - avg.planes[0][j]);
    for (double mu : {1.0, 0.5, 0.125}) csv += " " + fmt4(1 - t.planes[0][static_cast<size_t>(j) * n + col(mu)]);
    csv += "\n";
  }
  std::string stem = fileStem(ndf, gaf);
  page.data("loss_" + stem + ".dat", csv);
  page.plot("loss_" + stem,
            "set title '" + pairName(ndf, gaf) +
                ": energy lost by single scattering, 1 - E'\n"
                "set xlabel 'r (perceptual roughness)'\nset ylabel '1 - E'\nset key outside right top\nset grid\n"
                "plot 'loss_" +
                stem +
                ".dat' using 1:2 with lines lw 2 title '1 - E_{avg}', "
                "'' using 1:3 with lines title 'mu = 1', '' using 1:4 with lines title 'mu = 1/2', "
                "'' using 1:5 with lines title 'mu = 1/8'",
            "Energy lost by " + pairName(ndf, gaf) + " (negative: the lobe gains energy it should not).");
}

// Weak white furnace (Heitz 2014): int G1(o) max(0, o.h) D dw_h = mu for an exact Smith G1, with
// the GAF's own Lambda (smith/smith-correlated: Beckmann's for blinn-phong and the gaussian;
// the -exact variants: the NDF's own).
VerifyCheck weakFurnace(int ndf, int gaf) {
  VerifyCheck c{"weak furnace", true, isSmith(gaf), 0, "", ""};
  if (!c.applies) {
    c.detail = "not a Smith GAF";
    return c;
  }
  for (double r : {0.2, 0.4, 0.6, 0.8, 1.0})
    for (double mu : {0.05, 0.1, 0.25, 0.5, 0.75, 1.0}) {
      double d = std::fabs(reference::weakFurnace(ndf, gaf, r, mu) / mu - 1);
      if (d > c.worst) {
        c.worst = d;
        c.where = "mu=" + fmt4(mu) + " r=" + fmt4(r);
      }
    }
  c.pass = c.worst <= kWeakFurnaceTol;
  c.detail = "max |W(mu)/mu - 1| = " + fmt4(c.worst) + " at " + c.where + " (tolerance " + fmt4(kWeakFurnaceTol) + ")";
  return c;
}

// int D (n.h) dw = 1 with the kernels' own normalisation (numeric 1/k_p for the gaussian).
VerifyCheck normalisation(int ndf, int gaf) {
  VerifyCheck c{"k_p normalisation", true, true, 0, "", ""};
  for (double r : {0.05, 0.1, 0.3, 0.5, 0.7, 1.0}) {
    brdf64::BrdfParams p = brdf64::brdf_params(ndf, gaf, r);
    double d = std::fabs(reference::normalisation(ndf, r, p.inv_kp) - 1);
    if (d > c.worst) {
      c.worst = d;
      c.where = "r=" + fmt4(r);
    }
  }
  c.pass = c.worst <= kNormTol;
  c.detail = "max |int D (n.h) dw - 1| = " + fmt4(c.worst) + " at " + c.where;
  return c;
}

// f(i, o) = f(o, i) at random pairs: D G / (4 (n.i)(n.o)) from the kernels' code in double.
VerifyCheck reciprocity(int ndf, int gaf) {
  VerifyCheck c{"reciprocity", true, true, 0, "", ""};
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> u(0, 1);
  for (int t = 0; t < kReciprocityPairs; ++t) {
    double r = 0.05 + 0.95 * u(rng), ni = 0.02 + 0.98 * u(rng), no = 0.02 + 0.98 * u(rng), phi = 3.14159265 * u(rng);
    brdf64::BrdfParams p = brdf64::brdf_params(ndf, gaf, r);
    double si = std::sqrt(1 - ni * ni), so = std::sqrt(1 - no * no);
    double ix = si * std::cos(phi), iy = si * std::sin(phi);  // o = (so, 0, no)
    double hx = ix + so, hy = iy, hz = ni + no, hl = std::sqrt(hx * hx + hy * hy + hz * hz);
    double nh = hz / hl, oh = (so * hx + no * hz) / hl, s2h = (hx * hx + hy * hy) / (hl * hl);
    double D = brdf64::ndf_D(ndf, p, nh, s2h);
    double fio = D * brdf64::gaf_G_over_no(gaf, ndf, p, ni, no, nh, oh, si * si, so * so) / (4 * ni);
    double foi = D * brdf64::gaf_G_over_no(gaf, ndf, p, no, ni, nh, oh, so * so, si * si) / (4 * no);
    double d = std::fabs(fio - foi) / std::max(std::fabs(fio), 1e-300);
    if (d > c.worst) {
      c.worst = d;
      c.where = "n.i=" + fmt4(ni) + " n.o=" + fmt4(no) + " r=" + fmt4(r);
    }
  }
  c.pass = c.worst <= kReciprocityTol;
  c.detail = "max |f(i,o) - f(o,i)|/f = " + fmt4(c.worst) + " over " + std::to_string(kReciprocityPairs) + " pairs";
  return c;
}

// The rough dielectric (--table dielectric): E_R + E_T <= 1 + bound on a node grid of (mu, r), edges
// included, over etas from TIR-dominated to dense glass and around 1; every value finite.
VerifyCheck dielectricEnergy(KernelRunner* runner, int ndf, int gaf) {
  VerifyCheck c{"dielectric energy", true, (ndf == NDF_GGX || ndf == NDF_BECKMANN) && isSmith(gaf), 0, "", ""};
  if (!c.applies) {
    c.detail = "no rough dielectric for this pair";
    return c;
  }
  const int n = 9;
  const std::vector<double> etas = {0.2, 0.6667, 0.99, 0.9999, 1.0, 1.0001, 1.01, 1.5, 2.5, 5.0};
  auto t = dielectricSlab(*runner, ndf, gaf, n, n, etas, true, 2e-6f);
  double maxSum = -1;
  for (size_t k = 0; k < t[0].size(); ++k) {
    size_t x = k % n, y = (k / n) % n, z = k / (static_cast<size_t>(n) * n);
    double sum = static_cast<double>(t[0][k]) + t[1][k];
    std::string at = "mu=" + fmt4(x / (n - 1.0)) + " r=" + fmt4(y / (n - 1.0)) + " eta=" + fmt4(etas[z]);
    if (!std::isfinite(sum) || !std::isfinite(t[2][k])) {
      c.pass = false;
      c.where = at + " (not finite)";
      maxSum = std::numeric_limits<double>::infinity();
      break;
    }
    if (sum > maxSum) {
      maxSum = sum;
      c.where = at;
    }
    if (sum > 1 + t[2][k] + kAllowance) {
      c.pass = false;
      c.worst = std::max(c.worst, sum - 1);
    }
  }
  c.detail = "max E_R + E_T = " + std::to_string(maxSum) + " at " + c.where + " (" + std::to_string(n) + "x" +
             std::to_string(n) + " nodes of (mu, r) x " + std::to_string(etas.size()) + " etas in [0.2, 5])";
  return c;
}

}  // namespace

bool VerifyResult::pass() const {
  for (const auto& c : checks)
    if (c.applies && !c.pass) return false;
  return true;
}

std::string VerifyResult::summary() const {
  std::string s = (pass() ? "pass  " : "FAIL  ") + pairName(ndf, gaf) + ":";
  for (const auto& c : checks) {
    if (!c.applies) continue;
    if (c.pass)
      s += " " + c.name + " ok;";
    else
      s += " " + c.name + " FAILS (" + c.detail + ");";
  }
  s.pop_back();
  return s + "\n";
}

std::vector<VerifyResult> runVerify(const BakeRequest& req, std::string* pageLine) {
  const int n = req.size ? *req.size : 33;
  if (n < 2)
    throw Error(kExitUsage, "--size must be at least 2 for verify (grid nodes per axis), got " + std::to_string(n));
  std::vector<std::pair<int, int>> pairs;
  for (int ndf : req.ndfs)
    for (int gaf : req.gafs) pairs.push_back({ndf, gaf});
  // E(mu, r) and E_avg(r) as `brdfbake bake --table albedo,albedo-avg` makes them, with their
  // per-texel claims: on the node grid (edges included), or on texel centres where E(0, r) is
  // infinite (gaf none) or the sheen's grid starts (sheen GAFs). One library bake per grid.
  auto onNodes = [](int gaf) { return gaf != GAF_NONE && !isSheenGaf(gaf); };
  std::map<std::pair<int, int>, Table> albedo, avg;
  std::fprintf(stderr, "verify: baking the albedo tables of %zu pair(s)\n", pairs.size());
  for (bool node : {true, false}) {
    BakeRequest b;
    b.ndfs = req.ndfs;
    for (int gaf : req.gafs)
      if (onNodes(gaf) == node) b.gafs.push_back(gaf);
    if (b.gafs.empty()) continue;
    b.tables = {TableKind::Albedo, TableKind::AlbedoAvg};
    b.size = n;
    b.nodeGrid = node;
    b.device = req.device;
    for (Table& t : bake(b)) {
      std::pair<int, int> pair{ndfId(t.metadata.at("brdf.ndf")), gafId(t.metadata.at("brdf.gaf"))};
      (t.kind == tableName(TableKind::Albedo) ? albedo : avg)[pair] = std::move(t);
    }
  }
  std::unique_ptr<KernelRunner> runner;  // the rough dielectric's check, for the pairs that have one
  ReportPage page("brdfbake verify");
  const std::string checksText =
      ("White furnace (E <= 1 + bound), weak white furnace for Smith GAFs (|W(mu)/mu - 1| <= 1e-6), "
       "NDF normalisation (|int D (n.h) dw - 1| <= 1e-6), reciprocity (relative 1e-12 at " +
       std::to_string(kReciprocityPairs) +
       " random pairs), energy lost (1 - E), the rough dielectric's E_R + E_T <= 1 + "
       "bound (ggx, beckmann with smith GAFs). Grid: " +
       std::to_string(n) + " x " + std::to_string(n) + " nodes of (mu, r), edges included.");
  // the checks first, then the page: the summary opens it, the pairs' sections follow
  std::vector<VerifyResult> out;
  ReportPage scratch("");  // whiteFurnace's plot goes to the page in the second pass
  size_t done = 0;
  for (auto [ndf, gaf] : pairs) {
    std::fprintf(stderr, "verify: %s (%zu/%zu)\n", pairName(ndf, gaf).c_str(), ++done, pairs.size());
    VerifyResult res{ndf, gaf, {}};
    res.checks.push_back(whiteFurnace(albedo.at({ndf, gaf}), n, onNodes(gaf), scratch, ndf, gaf));
    res.checks.push_back(weakFurnace(ndf, gaf));
    res.checks.push_back(normalisation(ndf, gaf));
    res.checks.push_back(reciprocity(ndf, gaf));
    if (!runner && (ndf == NDF_GGX || ndf == NDF_BECKMANN) && isSmith(gaf))
      runner = std::make_unique<KernelRunner>(selectDevice(req.device).device);
    res.checks.push_back(dielectricEnergy(runner.get(), ndf, gaf));
    out.push_back(res);
  }
  std::string summary;
  int failed = 0;
  for (const auto& r : out) {
    summary += r.summary();
    failed += !r.pass();
  }
  page.verdict(failed ? ReportPage::Outcome::Fail : ReportPage::Outcome::Pass,
               failed ? std::to_string(failed) + " of " + std::to_string(out.size()) + " pair(s) fail a check (below)"
                      : "all " + std::to_string(out.size()) + " pair(s) pass every check");
  page.preformatted(summary);
  page.paragraph(checksText);
  FurnaceFigures figures(req.device);
  for (size_t i = 0; i < out.size(); ++i) {
    const VerifyResult& res = out[i];
    page.heading(pairName(res.ndf, res.gaf));
    const std::pair<int, int> pair{res.ndf, res.gaf};
    whiteFurnace(albedo.at(pair), n, onNodes(res.gaf), page, res.ndf, res.gaf);
    energyLoss(albedo.at(pair), avg.at(pair), n, onNodes(res.gaf), page, res.ndf, res.gaf);
    std::string lines;
    for (const auto& c : res.checks)
      lines += (c.applies ? (c.pass ? "pass  " : "FAIL  ") : "n/a   ") + c.name + ": " + c.detail + "\n";
    page.preformatted(lines);
    std::fprintf(stderr, "verify: rendering %s's white furnace (%zu/%zu)\n", pairName(res.ndf, res.gaf).c_str(), i + 1,
                 out.size());
    figures.add(page, res.ndf, res.gaf);
  }
  std::string csv = "ndf,gaf,check,applies,pass,worst,where\n";
  for (const auto& r : out)
    for (const auto& c : r.checks)
      csv += ndfNames()[r.ndf] + "," + gafNames()[r.gaf] + "," + c.name + "," + (c.applies ? "1" : "0") + "," +
             (c.pass ? "1" : "0") + "," + fmt4(c.worst) + "," + c.where + "\n";
  page.data("verify.csv", csv);
  *pageLine = page.write(req.outDir + "/verify");
  return out;
}

}  // namespace brdfbake
