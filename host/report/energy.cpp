#include "tables/error_model.h"
#include "report/energy.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cl/device.h"
#include "cl/runner.h"
#include "tables/dielectric/dielectric_bake.h"
#include "brdfbake/brdfbake.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "common/material.h"
#include "brdfbake/table_kind.h"
#include "common/models.h"
#include "report/furnace_figure.h"
#include "report/report_page.h"

namespace brdfbake {

namespace {

// The diffuse and dielectric kernels' float arithmetic, as in the bake (host/tables/table2d.cpp,
// host/tables/dielectric/dielectric_bake.cpp): once per lobe; the specular lobe's is modelled per texel
// (tables/error_model.h).
constexpr double kAllowance = 1e-6;
constexpr size_t kWorstShown = 5;

// Node i of n on [lo, hi] (the checks include the grid's edges).
double node(int i, int n, double lo, double hi) { return n > 1 ? lo + (hi - lo) * i / (n - 1.0) : lo; }

// Shirley's diffuse forms take the specular's reflectance at normal incidence: the Fresnel's own.
double normalReflectance(const FresnelChoice& f, int c) {
  auto [x, y] = f.modelParams(c);
  switch (f.model) {
    case FRESNEL_SCHLICK:
    case FRESNEL_F82_TINT:
      return x;
    case FRESNEL_DIELECTRIC:
    case FRESNEL_SCHLICK_TIR:
      return (x - 1) * (x - 1) / ((x + 1) * (x + 1));
    case FRESNEL_CONDUCTOR:
      return ((x - 1) * (x - 1) + y * y) / ((x + 1) * (x + 1) + y * y);
    default:
      return 1;  // F = 1: everything is reflected specularly
  }
}

}  // namespace

std::vector<EnergyResult> checkEnergy(const BakeRequest& req, const EnergyOptions& opts) {
  const int n = req.size ? *req.size : 33;
  if (n < 2)
    throw Error(kExitUsage, "--size must be at least 2 for energy (grid nodes per axis), got " + std::to_string(n));
  DeviceEntry dev = selectDevice(req.device);
  KernelRunner runner(dev.device);
  const FresnelChoice& fc = fresnelOf(req);
  const int d = req.diffuse;
  const bool shirley = d == DIFFUSE_SHIRLEY || d == DIFFUSE_ASHIKHMIN_SHIRLEY || d == DIFFUSE_SHIRLEY_AS_PRINTED;
  const bool orenNayar = d == DIFFUSE_OREN_NAYAR || d == DIFFUSE_OREN_NAYAR_AS_PRINTED;
  std::vector<EnergyResult> out;
  for (int ndf : req.ndfs)
    for (int gaf : req.gafs) {
      if (gaf == GAF_NONE)
        throw Error(kExitUsage, "--gaf none: G = 1 has infinite albedo at mu = 0, the grid's edge; energy needs a GAF");
      EnergyResult res;
      res.material = ndfNames()[ndf] + "+" + gafNames()[gaf] + ", fresnel " + fc.describe() + ", diffuse " +
                     (d >= 0 ? diffuseNames()[d] : std::string("none")) +
                     (orenNayar && req.sigma ? " sigma=" + fmtG(*req.sigma) : "") + ", coupling " + opts.coupling;
      std::vector<EnergyPoint> pts;
      // the node grid (edges included), or texel centres for the sheen GAFs, whose albedo is
      // infinite at mu = 0 (as verify's white furnace samples them)
      const bool nodes = !isSheenGaf(gaf);
      auto at = [nodes](int i, int count, double lo, double hi) {
        return nodes ? node(i, count, lo, hi) : lo + (hi - lo) * (i + 0.5) / count;
      };
      if (opts.transmission) {
        // rough glass: reflected plus transmitted albedo at the material's eta, node grid of (mu, r)
        if ((ndf != NDF_GGX && ndf != NDF_BECKMANN) || (gaf != GAF_SMITH && gaf != GAF_SMITH_CORRELATED))
          throw Error(kExitUsage,
                      "--transmission: the rough dielectric takes --ndf ggx or beckmann with --gaf smith or "
                      "smith-correlated, not " +
                          ndfNames()[ndf] + "+" + gafNames()[gaf]);
        res.secondLobe = "E_T";
        res.material = ndfNames()[ndf] + "+" + gafNames()[gaf] + ", rough glass (transmission), " + fc.describe();
        for (int c = 0; c < fc.channels(); ++c) {
          double eta = fc.modelParams(c).first;
          auto t = dielectricSlab(runner, ndf, gaf, n, n, {eta}, true, 2e-6f);
          for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
              size_t k = static_cast<size_t>(j) * n + i;
              double er = t[0][k], et = t[1][k];
              pts.push_back({node(i, n, 0, 1), node(j, n, 0, 1), NAN, c, er, et, er + et, t[2][k] + kAllowance});
            }
        }
      }
      // the specular lobe's albedo with its Fresnel over (mu, r) on the node grid, as `brdfbake bake
      // --table albedo --fresnel ...` makes it, with the table's per-texel claims
      Table spec;
      if (!opts.transmission) {
        BakeRequest b;
        b.ndfs = {ndf};
        b.gafs = {gaf};
        b.tables = {TableKind::Albedo};
        b.size = n;
        b.nodeGrid = nodes;
        b.fresnel = req.fresnel;
        b.device = req.device;
        spec = std::move(bake(b).at(0));
      }
      for (int c = 0; c < (opts.transmission ? 0 : fc.channels()); ++c) {
        // the diffuse lobe's albedo over (mu, its parameter): burley follows r, oren-nayar sigma
        // (swept unless --sigma), the Shirley forms the Fresnel's F0 (swept when F = 1)
        KernelTable dif;
        int np = 1;
        double plo = 0, phi = 0;
        if (d >= 0) {
          if (d == DIFFUSE_BURLEY || d == DIFFUSE_LAMBERT) {
            np = n, plo = 0, phi = 1;
          } else if (orenNayar) {
            if (req.sigma)
              plo = phi = *req.sigma;
            else
              np = n, plo = 0, phi = diffuseAxis(d).hi, res.paramName = "sigma";
          } else if (shirley) {
            if (!fc.isOne())
              plo = phi = normalReflectance(fc, c);
            else
              np = n, plo = 0, phi = 1, res.paramName = "F0";
          }
          dif = runner.diffuseAlbedo(d, n, np, static_cast<float>(plo), static_cast<float>(phi), nodes);
          // the diffuse lobe on its own: Burley's and Oren-Nayar's exceed 1 by themselves
          size_t worst = 0;
          for (size_t k = 0; k < dif.planes[0].size(); ++k)
            if (dif.planes[0][k] > dif.planes[0][worst]) worst = k;
          double ed = dif.planes[0][worst];
          std::string where = "mu=" + fmtG(at(static_cast<int>(worst % n), n, 0, 1), 4) +
                              (np > 1 ? " " + (res.paramName.empty() ? std::string("r") : res.paramName) + "=" +
                                            fmtG(at(static_cast<int>(worst / n), np, plo, phi), 4)
                                      : "");
          if (c == 0)
            res.diffuseAlone = "diffuse " + diffuseNames()[d] + " alone: largest albedo " + fmtG(ed) + " at " + where +
                               (ed > 1 + dif.err[worst] + kAllowance
                                    ? ", above 1 by " + fmtG(ed - 1, 3) + " (a property of the model itself)"
                                    : ", at most 1");
        }
        bool followsR = d == DIFFUSE_BURLEY || d == DIFFUSE_LAMBERT;
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i) {
            size_t k = static_cast<size_t>(j) * n + i;
            double es = spec.planes[static_cast<size_t>(c)][k], bs = spec.texelBounds[k] * std::max(1.0, std::fabs(es));
            int q0 = followsR ? j : 0, q1 = followsR ? j + 1 : np;
            for (int q = d >= 0 ? q0 : 0; q < (d >= 0 ? q1 : 1); ++q) {
              double ed = 0, bd = 0;
              if (d >= 0) {
                size_t kd = static_cast<size_t>(q) * n + i;
                ed = dif.planes[0][kd];
                bd = dif.err[kd] * std::max(1.0, std::fabs(ed)) + kAllowance;
              }
              // sum: the lobes add (each diffuse model's paper; Shirley's carries its 1 - F0);
              // albedo-scaling: the diffuse lobe gets what the specular left, (1 - E_spec) f_d
              double w = opts.coupling == "albedo-scaling" ? 1 - es : 1;
              double total = es + w * ed;
              double bound = bs * (1 + (opts.coupling == "albedo-scaling" ? std::fabs(ed) : 0)) + std::fabs(w) * bd;
              double param = res.paramName.empty() ? NAN : at(q, np, plo, phi);
              pts.push_back({at(i, n, 0, 1), at(j, n, 0, 1), param, c, es, w * ed, total, bound});
            }
          }
      }
      std::sort(pts.begin(), pts.end(), [](const EnergyPoint& a, const EnergyPoint& b) {
        return a.total - a.bound > b.total - b.bound || (a.total - a.bound == b.total - b.bound && a.total > b.total);
      });
      for (const EnergyPoint& p : pts) {
        if (!std::isfinite(p.total)) throw Error(kExitSoftware, "internal error: a non-finite albedo in energy");
        if (p.total > 1 + p.bound) res.violates = true;
      }
      res.channels = fc.channels();
      for (int c = 0; c < fc.channels(); ++c)
        res.fresnelAvg.push_back(fresnelAverage(fc, c, nullptr, &res.fresnelAvgHow));
      pts.resize(std::min(pts.size(), kWorstShown));
      res.worst = pts;
      out.push_back(res);
    }
  return out;
}

std::string formatEnergy(const std::vector<EnergyResult>& results) {
  std::string s;
  char line[512];
  for (const EnergyResult& r : results) {
    const EnergyPoint& w = r.worst.front();
    if (r.violates)
      std::snprintf(line, sizeof line,
                    "VIOLATES: %s: total albedo %.6g at mu=%.4g r=%.4g exceeds 1 by %.3g (bound %.2g)\n",
                    r.material.c_str(), w.total, w.mu, w.r, w.total - 1, w.bound);
    else
      std::snprintf(line, sizeof line, "conserves: %s: largest total albedo %.6g at mu=%.4g r=%.4g (bound %.2g)\n",
                    r.material.c_str(), w.total, w.mu, w.r, w.bound);
    s += line;
    if (!r.diffuseAlone.empty()) s += "  " + r.diffuseAlone + "\n";
    s += "  F_avg (2 int F mu dmu, " + r.fresnelAvgHow + "):";
    for (double f : r.fresnelAvg) s += " " + fmtG(f);
    s += "\n";
    std::snprintf(line, sizeof line, "  %6s  %6s  %8s  %7s  %10s  %10s  %10s  %9s\n", "mu", "r",
                  r.paramName.empty() ? "" : r.paramName.c_str(), "channel", r.secondLobe == "E_T" ? "E_R" : "E_spec",
                  r.secondLobe.c_str(), "total", "bound");
    s += line;
    for (const EnergyPoint& p : r.worst) {
      char param[32] = "";
      if (!std::isnan(p.param)) std::snprintf(param, sizeof param, "%.4g", p.param);
      std::snprintf(line, sizeof line, "  %6.4g  %6.4g  %8s  %7s  %10.6g  %10.6g  %10.6g  %9.2g\n", p.mu, p.r, param,
                    r.channels == 1 ? "-" : std::string(1, "RGB"[p.channel]).c_str(), p.spec, p.diffuse, p.total,
                    p.bound);
      s += line;
    }
  }
  return s;
}

std::string writeEnergyPage(const BakeRequest& req, const std::vector<EnergyResult>& results) {
  ReportPage page("brdfbake energy");
  int violating = 0;
  for (const EnergyResult& r : results) violating += r.violates;
  page.verdict(violating ? ReportPage::Outcome::Fail : ReportPage::Outcome::Pass,
               violating ? std::to_string(violating) + " of " + std::to_string(results.size()) +
                               " material(s) violate energy conservation"
                         : "all " + std::to_string(results.size()) + " material(s) conserve energy");
  page.preformatted(formatEnergy(results));
  std::string csv = "material,mu,r,param,channel,lobe1,lobe2,total,bound\n";
  for (const EnergyResult& r : results)
    for (const EnergyPoint& p : r.worst)
      csv += "\"" + r.material + "\"," + fmt4(p.mu) + "," + fmt4(p.r) + "," +
             (std::isnan(p.param) ? "" : fmt4(p.param)) + "," + std::to_string(p.channel) + "," + fmt4(p.spec) + "," +
             fmt4(p.diffuse) + "," + fmt4(p.total) + "," + fmt4(p.bound) + "\n";
  page.data("energy.csv", csv);
  // the white furnace of each pair the materials use, as `brdfbake render` draws it
  FurnaceFigures figures(req.device);
  for (int ndf : req.ndfs)
    for (int gaf : req.gafs)
      if (pairSupported(ndf, gaf)) {
        page.heading(ndfNames()[static_cast<size_t>(ndf)] + "+" + gafNames()[static_cast<size_t>(gaf)] +
                     ": the white furnace");
        figures.add(page, ndf, gaf);
      }
  return page.write(req.outDir + "/energy");
}

}  // namespace brdfbake
