#include "bake/error_model.h"
#include "report/convergence.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "bench/bench_util.h"
#include "bench/mc_common.h"
#include "cl/device.h"
#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "common/material.h"
#include "common/models.h"
#include "reference/reference.h"
#include "report/report_page.h"

namespace brdfbake {

namespace {


double rel(double a, double b) { return std::fabs(a - b) / std::max(1.0, std::fabs(b)); }
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

template <class F>
double best3(F f) {
  double b = 1e300;
  for (int k = 0; k < 3; ++k) {
    double t0 = now();
    f();
    b = std::min(b, now() - t0);
  }
  return b;
}

// Common-practice MC: h by the NDF's own CDF (u1 -> v = -log(1 - u1), kernels/brdf/ndf.h), phi =
// pi u2 (the integrand is even in phi), the Hammersley point (k/N, radicalInverse2(k)); the estimate
// of E = (1/pi) int du w int_0^pi dphi H (kernels/integrate/hemisphere.h) is the mean of w H over
// the samples with n.i > 0. Float, as a tool or shader does it. Returns the value, *se the standard
// error.
double mcTexel(int ndf, int gaf, const HemiWeight& hw, double mu, double r, int n, double* se) {
  brdf32::BrdfParams p = brdf32::hemisphere_texel_params(ndf, gaf, static_cast<float>(mu), static_cast<float>(r));
  p.moments = hw.moments;
  p.fresnel = hw.fresnel;
  p.fr_x = hw.x;
  p.fr_y = hw.y;
  float fm = static_cast<float>(mu), s = std::sqrt((1 - fm) * (1 + fm));
  double sum = 0, sum2 = 0;
  for (int k = 0; k < n; ++k) {
    float u1 = static_cast<float>(k) / static_cast<float>(n), u2 = mc::radicalInverse2(static_cast<std::uint32_t>(k));
    float v = -std::log1p(-u1);
    brdf32::BrdfAngle h = brdf32::ndf_angle_of_v(ndf, p, v);
    float sn = std::sqrt(h.s2), cphi = std::cos(3.14159265f * u2);
    float oh = s * sn * cphi + fm * h.c, ni = 2 * oh * h.c - fm;
    double f = 0;
    if (ni > 0 && oh > 0) {
      float fa, fb;
      brdf32::hemi_node(ndf, gaf, p, fm, s, h, sn, cphi, &fa, &fb);
      f = brdf32::ndf_weight(ndf, p, h.c, h.s2) * (hw.moments == HEMI_FRESNEL ? fb : fa + fb);
    }
    sum += f;
    sum2 += f * f;
  }
  double m = sum / n, var = std::max(0.0, sum2 / n - m * m);
  *se = std::sqrt(var / n);
  return m;
}

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

}  // namespace

ConvergenceResult runConvergence(const BakeRequest& req, std::string* pageLine) {
  if (req.ndfs.size() != 1 || req.gafs.size() != 1)
    throw Error(kExitUsage, "convergence measures one pair: give one --ndf and one --gaf");
  const int ndf = req.ndfs[0], gaf = req.gafs[0], n = req.size ? *req.size : 12;
  if (n < 2 || n > 64) throw Error(kExitUsage, "--size for convergence must be in 2..64 (texels per axis), got " + std::to_string(n));
  if (gaf == GAF_NONE) throw Error(kExitUsage, "--gaf none: E grows like 1/mu at grazing; pick a GAF");
  const FresnelChoice& fc = req.fresnel;
  if (fc.channels() != 1) throw Error(kExitUsage, "convergence takes one value per Fresnel parameter, not R,G,B");
  HemiWeight hw;
  reference::Weight rw;
  if (!fc.isOne()) {
    auto [x, y] = fc.kernelParams(0);
    auto [mx, my] = fc.modelParams(0);
    hw = HemiWeight{HEMI_FRESNEL, fc.model, static_cast<float>(x), static_cast<float>(y)};
    rw = reference::Weight{reference::Weight::Fresnel, {fc.model, mx, my}};
  }
  ConvergenceResult res;
  res.table = "albedo of " + ndfNames()[ndf] + "+" + gafNames()[gaf] + ", fresnel " + fc.describe() + ", " +
              std::to_string(n) + "x" + std::to_string(n) + " texel centres";
  auto value = [&](const KernelTable& t, size_t k) { return hw.moments == HEMI_FRESNEL ? t.planes[1][k] : t.planes[2][k]; };

  // the reference at every texel (float coordinates, as the device sees them), on 2 threads
  std::fprintf(stderr, "convergence: reference at %d texels\n", n * n);
  std::vector<double> ref(static_cast<size_t>(n) * n);
  double t0 = now();
  bench::onTwoThreads(ref.size(), [&](size_t k) {
    double mu = static_cast<float>((k % n + 0.5) / n), r = static_cast<float>((k / n + 0.5) / n);
    reference::Moments m = reference::albedo(ndf, gaf, r, mu, rw);
    ref[k] = hw.moments == HEMI_FRESNEL ? m.b : m.e();
  });
  double refSeconds = now() - t0;

  DeviceEntry dev = selectDevice(req.device);
  KernelRunner kr(dev.device);
  kr.prepare(KernelNeed{KernelNeed::Hemisphere, ndf, gaf});
  kr.hemisphere(ndf, gaf, n, n, false, hw);  // warm: the kernel's compile is not timed
  for (int L : req.levels) {
    std::fprintf(stderr, "convergence: quadrature level %d\n", L);
    KernelTable t;
    Rung rg{"quadrature (device, float)", "level " + std::to_string(L), 0, 0, 0};
    rg.seconds = best3([&] { t = kr.hemisphereRange(ndf, gaf, n, n, 0, 1, 0, 1, false, hw, L); });
    for (size_t k = 0; k < ref.size(); ++k) {
      rg.error = std::max(rg.error, rel(value(t, k), ref[k]));
      // + the float arithmetic's share, as the bake claims it (bake/error_model.h)
      double scale = std::max({std::fabs(t.planes[0][k]), std::fabs(t.planes[1][k]), std::fabs(t.planes[2][k])});
      rg.estimate = std::max(rg.estimate, static_cast<double>(t.err[k]) +
                                                   floatArithmeticError(scale, hemiFloatModel(ndf, gaf, !fc.isOne())));
    }
    res.rungs.push_back(rg);
  }
  for (int L : req.levels) {
    std::fprintf(stderr, "convergence: quadrature level %d in double\n", L);
    Rung rg{"quadrature (host, double)", "level " + std::to_string(L), 0, 0, 0};
    std::vector<double> v(ref.size()), e(ref.size());
    rg.seconds = now();
    bench::onTwoThreads(ref.size(), [&](size_t k) {
      double mu = static_cast<float>((k % n + 0.5) / n), r = static_cast<float>((k / n + 0.5) / n);
      brdf64::BrdfParams p = brdf64::hemisphere_texel_params(ndf, gaf, mu, r);
      p.moments = hw.moments, p.fresnel = hw.fresnel, p.fr_x = hw.x, p.fr_y = hw.y;
      brdf64::HemiResult h = brdf64::hemisphere_moments(ndf, gaf, p, mu, L);
      v[k] = hw.moments == HEMI_FRESNEL ? h.b : h.a + h.b;
      e[k] = brdf64::hemi_rel_error(h);
    });
    rg.seconds = now() - rg.seconds;
    for (size_t k = 0; k < ref.size(); ++k) {
      rg.error = std::max(rg.error, rel(v[k], ref[k]));
      rg.estimate = std::max(rg.estimate, e[k]);
    }
    res.rungs.push_back(rg);
  }
  for (int ns : req.samples) {
    std::fprintf(stderr, "convergence: Monte Carlo %d samples\n", ns);
    Rung rg{"Monte Carlo (Hammersley, float)", std::to_string(ns) + " samples", 0, 0, 0};
    std::vector<double> v(ref.size()), se(ref.size());
    rg.seconds = now();
    bench::onTwoThreads(ref.size(), [&](size_t k) {
      v[k] = mcTexel(ndf, gaf, hw, static_cast<float>((k % n + 0.5) / n), static_cast<float>((k / n + 0.5) / n), ns,
                     &se[k]);
    });
    rg.seconds = now() - rg.seconds;
    for (size_t k = 0; k < ref.size(); ++k) {
      rg.error = std::max(rg.error, rel(v[k], ref[k]));
      rg.estimate = std::max(rg.estimate, 3 * se[k] / std::max(1.0, std::fabs(v[k])));
    }
    res.rungs.push_back(rg);
  }

  // per method: order and times to tolerance
  std::vector<std::string> methods;
  for (const Rung& r : res.rungs)
    if (std::find(methods.begin(), methods.end(), r.method) == methods.end()) methods.push_back(r.method);
  char line[512];
  std::snprintf(line, sizeof line, "%-32s  %9s  %14s  %14s  %14s\n", "method", "order", "time to 1e-3", "time to 1e-5",
                "time to 1e-7");
  res.summary = line;
  for (const std::string& m : methods) {
    std::vector<Rung> rs;
    for (const Rung& r : res.rungs)
      if (r.method == m) rs.push_back(r);
    double o = order(rs);
    std::snprintf(line, sizeof line, "%-32s  %9s  %14s  %14s  %14s\n", m.c_str(), std::isnan(o) ? "at floor" : fmt3(o).c_str(),
                  timeTo(rs, 1e-3).c_str(), timeTo(rs, 1e-5).c_str(), timeTo(rs, 1e-7).c_str());
    res.summary += line;
  }
  // the reference's own accuracy: the finest double quadrature is another method on the same integrals
  double agree = 0;
  for (const Rung& r : res.rungs)
    if (r.method == "quadrature (host, double)") agree = r.error;
  res.summary += "order: slope of log(true error) against log(time) while the error falls (\"at floor\": float "
                 "rounding from the first rung). The reference (adaptive Gauss-Kronrod in double in the plain "
                 "angles, host/reference) took " + fmt3(refSeconds) + " s for " + std::to_string(n * n) +
                 " texels; the finest double quadrature, another method, agrees with it to " + fmt3(agree) + "\n";

  ReportPage page("brdfbake convergence");
  page.paragraph(res.table);
  page.preformatted(formatConvergence(res));
  std::string dat;
  for (size_t mi = 0; mi < methods.size(); ++mi) {
    dat += "# " + methods[mi] + ": seconds estimate error\n";
    for (const Rung& r : res.rungs)
      if (r.method == methods[mi]) dat += fmt3(r.seconds) + " " + fmt3(std::max(r.estimate, 1e-17)) + " " + fmt3(std::max(r.error, 1e-17)) + "\n";
    dat += "\n\n";
  }
  page.data("convergence.dat", dat);
  std::string csv = "method,budget,seconds,estimate,error\n";
  for (const Rung& r : res.rungs)
    csv += r.method + "," + r.budget + "," + fmt3(r.seconds) + "," + fmt3(r.estimate) + "," + fmt3(r.error) + "\n";
  page.data("convergence.csv", csv);
  std::string plot = "set title 'error against run time: " + res.table + "' noenhanced\n"
                     "set logscale xy\nset format y '10^{%L}'\nset xlabel 'seconds'\nset ylabel 'max relative error'\n"
                     "set key outside bottom center horizontal maxrows 3\nset grid\nplot ";
  for (size_t mi = 0; mi < methods.size(); ++mi) {
    std::string idx = std::to_string(mi);
    plot += std::string(mi ? ", " : "") + "'convergence.dat' index " + idx + " using 1:3 with linespoints lw 2 lc " +
            std::to_string(mi + 1) + " title '" + methods[mi] + ": true', '' index " + idx +
            " using 1:2 with lines dt 2 lc " + std::to_string(mi + 1) + " title 'estimated'";
  }
  page.plot("convergence", plot, "Solid: true error against the reference; dashed: the method's own estimate.");
  *pageLine = page.write(req.outDir + "/convergence");
  return res;
}

std::string formatConvergence(const ConvergenceResult& r) {
  std::string s = r.table + "\n";
  char line[512];
  std::snprintf(line, sizeof line, "%-32s  %-14s  %10s  %10s  %10s\n", "method", "budget", "seconds", "estimate",
                "true error");
  s += line;
  for (const Rung& g : r.rungs) {
    std::snprintf(line, sizeof line, "%-32s  %-14s  %10.3g  %10.2e  %10.2e\n", g.method.c_str(), g.budget.c_str(),
                  g.seconds, g.estimate, g.error);
    s += line;
  }
  return s + r.summary;
}

}  // namespace brdfbake
