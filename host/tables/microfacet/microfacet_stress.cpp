// The microfacet family's stress points (brdfbake stress): the albedo, its Fresnel and diffuse forms,
// k_p, E_avg and the sheen lobe through their stiff and extreme cases, against the independent
// reference and the expected limits.
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "common/brdf_host.h"
#include "common/format.h"
#include "common/models.h"
#include "reference/diffuse_reference.h"
#include "reference/reference.h"
#include "reference/sheen_reference.h"
#include "tables/error_model.h"
#include "tables/family.h"
#include "tables/microfacet/microfacet.h"

namespace brdfbake {

namespace {

// The diffuse kernel's float arithmetic, as the bake allows it (host/tables/table2d.cpp); the hemisphere
// estimators' and k_p's are modelled per value (tables/error_model.h).
constexpr double kDiffuseAllowance = 1e-6;

// The largest magnitude among a one-texel kernel result's planes: the float model's scale.
double scaleOf(const KernelTable& t) {
  double s = 0;
  for (const auto& p : t.planes) s = std::max(s, std::fabs(static_cast<double>(p[0])));
  return s;
}
// The reference approaches mu = 0 and the corner from inside (reference.h): it agrees with the
// kernels' limits there to ~1e-7 (tests/tables/microfacet/accuracy_test.cpp); elsewhere to its 1e-9.
constexpr double kLimitSlack = 1e-7;
constexpr double kPi = 3.14159265358979323846;

double rel(double a, double b) { return std::fabs(a - b) / std::max(1.0, std::fabs(b)); }

// r from a Blinn-Phong exponent (e = 2/alpha^2 - 2) or a gaussian c (c = 1/alpha), alpha = r^2.
double rOfExponent(double e) { return std::sqrt(std::sqrt(2 / (e + 2))); }
double rOfGaussianC(double c) { return std::sqrt(1 / c); }

struct Recorder {
  KernelRunner& k;
  std::vector<StressPoint>& out;

  // One point of a kernel result against the reference, with an optional limit (|value - limit| <= tol).
  // relBound: the kernel's estimate; arith: its float arithmetic's share (the claim is their sum, as
  // in the bake).
  void add(const std::string& sweep, const std::string& label, double v, double relBound, double arith, double ref,
           double slack, const std::string& limitText = "", double limit = NAN, double tol = 0) {
    StressPoint p;
    p.sweep = sweep;
    p.label = label;
    p.value = v;
    p.reference = ref;
    p.finite = std::isfinite(v) && std::isfinite(relBound);
    p.error = rel(v, ref);
    p.bound = relBound + arith;
    p.withinBound = p.finite && p.error <= p.bound + slack;
    if (!limitText.empty()) {
      p.limit = limitText;
      p.limitMet = p.finite && std::fabs(v - limit) <= tol;
    }
    out.push_back(p);
    std::fprintf(stderr, "stress: %zu %s, %s\n", out.size(), sweep.c_str(), label.c_str());
  }

  // E (or a Fresnel albedo) at one (mu, r).
  void specular(const std::string& sweep, int ndf, int gaf, double mu, double r, const reference::Weight& w,
                const std::string& limitText = "", double limit = NAN, double tol = 0) {
    HemiWeight hw;
    if (w.kind == reference::Weight::Fresnel) hw = fresnelWeight(w.f.model, w.f.x, w.f.y);
    float fm = static_cast<float>(mu), fr = static_cast<float>(r);
    KernelTable t = k.hemisphereRange(ndf, gaf, 1, 1, fm, fm, fr, fr, true, hw);
    bool fres = w.kind == reference::Weight::Fresnel;
    double v = fres ? t.planes[1][0] : t.planes[2][0];
    reference::Moments m = reference::albedo(ndf, gaf, fr, fm, w);
    add(sweep, ndfNames()[ndf] + "+" + gafNames()[gaf] + " mu=" + fmt4(fm) + " r=" + fmt4(fr), v, t.err[0],
        floatArithmeticError(scaleOf(t)), fres ? m.b : m.e(), fm == 0 || fr == 0 ? kLimitSlack : 3e-9, limitText, limit,
        tol);
  }

  // The sheen albedo (charlie) at one (mu, r), against the incident-direction reference.
  // At mu = 0 the closed form is the reference (the incident-direction quadrature needs minutes
  // there: its integrand is singular along the whole horizon).
  void sheen(const std::string& sweep, int gaf, double mu, double r, const std::string& limitText = "",
             double limit = NAN, double tol = 0) {
    float fm = static_cast<float>(mu), fr = static_cast<float>(r);
    KernelTable t = k.hemisphereRange(NDF_CHARLIE, gaf, 1, 1, fm, fm, fr, fr, true);
    double ref = fm == 0 && !std::isnan(limit) ? limit : reference::sheenAlbedo(gaf, fr, fm);
    add(sweep, "charlie+" + gafNames()[gaf] + " mu=" + fmt4(fm) + " r=" + fmt4(fr), t.planes[2][0], t.err[0],
        floatArithmeticError(scaleOf(t), hemiFloatModel(NDF_CHARLIE, gaf)), ref,
        fm == 0 || fr == 0 ? kLimitSlack : 3e-9, limitText, limit, tol);
  }
};

// charlie's E(0, r) in closed form (docs/MODELS.md "Sheen"), e = 1 + 1/(2 alpha): neubelt
// (e/pi) B(e + 1/2, 1/2), implicit e/(2 (e + 1)).
double sheenGrazing(int gaf, double r) {
  double e = 1 + 0.5 / (r * r);
  if (gaf == GAF_IMPLICIT) return e / (2 * (e + 1));
  return e / kPi * std::exp(std::lgamma(e + 0.5) + std::lgamma(0.5) - std::lgamma(e + 1));
}

}  // namespace

void microfacetStress(KernelRunner& kr, std::vector<StressPoint>& pts) {
  Recorder run{kr, pts};
  const reference::Weight one{};
  const int ggx = NDF_GGX, sc = GAF_SMITH_CORRELATED;

  // alpha -> 0 and exactly 0: with Smith, E -> 1 (the mirror reflects everything), A + B = E
  for (double r : {0.1, 0.03, 0.01, 0.0})
    for (int ndf : {NDF_GGX, NDF_BECKMANN})
      run.specular("alpha -> 0, albedo", ndf, sc, 0.5, r, one, "E -> 1 (mirror)", 1.0,
                   r == 0     ? 1e-7
                   : r > 0.05 ? 0.05
                              : 1e-3);
  // Blinn-Phong exponents to 1e9 and beyond: the lobe is a mirror, E -> 1
  for (double e : {1e3, 1e6, 1e9, 1e12})
    run.specular("blinn-phong exponent " + fmt4(e), NDF_BLINN_PHONG, sc, 0.5, rOfExponent(e), one, "E -> 1 (mirror)",
                 1.0, e >= 1e6 ? 1e-3 : 0.05);
  // gaussian c to 1e3
  for (double c : {10.0, 100.0, 1000.0})
    run.specular("gaussian c " + fmt4(c), NDF_GAUSSIAN, sc, 0.5, rOfGaussianC(c), one, "E -> 1 (mirror)", 1.0,
                 c >= 1000 ? 2e-3 : 0.2);
  // mu down to 1e-6 and exactly 0: continuous into the grazing limit (E(0, r) = 1 for ggx + smith-correlated)
  // (E changes on the scale mu ~ alpha: the limit is met once mu << alpha)
  for (double mu : {1e-3, 1e-6, 0.0})
    for (double r : {0.5, 0.05}) {
      if (mu > 1e-4 * r * r)
        run.specular("mu -> 0, albedo", ggx, sc, mu, r, one);
      else
        run.specular("mu -> 0, albedo", ggx, sc, mu, r, one, "E(0, r) = 1 (weak furnace ratio)", 1.0,
                     mu == 0 ? 1e-5 : 1e-3);
    }
  run.specular("corner", ggx, sc, 0.0, 0.0, one, "lim E(0, r -> 0) = 1", 1.0, 1e-5);
  // eta near 1: the dielectric reflects almost nothing (F0 = ((eta-1)/(eta+1))^2), exactly nothing at 1
  for (double eta : {1.01, 1.0001, 1.0}) {
    reference::Weight w{reference::Weight::Fresnel, {FRESNEL_DIELECTRIC, eta, 0}};
    run.specular("dielectric eta " + fmtG(eta), ggx, sc, 0.5, 0.5, w, "E_F -> 0 as eta -> 1", 0.0,
                 eta > 1.001 ? 1e-3 : 1e-6);
    run.specular("dielectric eta " + fmtG(eta), ggx, sc, 0.0, 0.5, w);
  }
  // eta below 1 across the critical angle: total internal reflection
  for (double eta : {0.95, 1 / 1.5, 0.3}) {
    reference::Weight w{reference::Weight::Fresnel, {FRESNEL_DIELECTRIC, eta, 0}};
    for (double mu : {0.0, 0.25, 1.0}) run.specular("dielectric eta " + fmt4(eta) + " (TIR)", ggx, sc, mu, 0.5, w);
  }
  // The stiff corner: a narrow lobe at a grazing view (the 32^2 table's texel mu = 1/64, r = 3/64)
  // on Fresnel's steep layer next to eta = 1, where float eta alone moved the albedo by 1.7e-4
  // (kernels/brdf/fresnel.h fresnel_e2m1); tests/tables/microfacet/fresnel_edge_test.cpp checks every corner texel.
  // Just below eta = 1 the view sits next to the critical cosine (0.0141 at eta = 0.9999).
  for (auto [model, eta, kk] : {std::tuple{FRESNEL_DIELECTRIC, 1.000001, 0.0},
                                {FRESNEL_DIELECTRIC, 1.0001, 0.0},
                                {FRESNEL_DIELECTRIC, 1.01, 0.0},
                                {FRESNEL_DIELECTRIC, 0.9999, 0.0},
                                {FRESNEL_DIELECTRIC, 0.999, 0.0},
                                {FRESNEL_DIELECTRIC, 0.99, 0.0},
                                {FRESNEL_DIELECTRIC, 0.2, 0.0},
                                {FRESNEL_DIELECTRIC, 5.0, 0.0},
                                {FRESNEL_SCHLICK_TIR, 0.9999, 0.0},
                                {FRESNEL_SCHLICK_TIR, 1.0001, 0.0},
                                {FRESNEL_CONDUCTOR, 0.9999, 1e-4}}) {
    reference::Weight w{reference::Weight::Fresnel, {model, eta, kk}};
    char name[96];
    std::snprintf(name, sizeof name, kk > 0 ? "stiff corner, %s eta %.7g k %.3g" : "stiff corner, %s eta %.7g",
                  fresnelNames()[model].c_str(), eta, kk);
    for (double r : {3.0 / 64, 15.0 / 64}) run.specular(name, ggx, sc, 1.0 / 64, r, w);
  }
  // conductors with large k: F -> 1, so E_F -> E
  for (double kk : {10.0, 50.0, 100.0}) {
    reference::Weight w{reference::Weight::Fresnel, {FRESNEL_CONDUCTOR, 1.5, kk}};
    double e = reference::albedo(ggx, sc, 0.5, 0.5).e();
    run.specular("conductor k " + fmt4(kk), ggx, sc, 0.5, 0.5, w, "E_F -> E as k -> inf", e, 6 * 1.5 / (kk * kk));
  }
  // Oren-Nayar sigma to pi/2, mu to 0: E(0) = A + B/2
  for (double sigma : {1.0, kPi / 2})
    for (double mu : {0.5, 1e-6, 0.0}) {
      float fs = static_cast<float>(sigma), fm = static_cast<float>(mu);
      KernelTable t = kr.diffuseAlbedo(DIFFUSE_OREN_NAYAR, 1, 1, fs, fs, true, fm, fm);
      double s2 = double(fs) * fs, A = 1 - 0.5 * s2 / (s2 + 0.33), B = 0.45 * s2 / (s2 + 0.09);
      run.add("oren-nayar sigma " + fmt4(sigma), "mu=" + fmt4(fm), t.planes[0][0], t.err[0], kDiffuseAllowance,
              reference::diffuseAlbedo(DIFFUSE_OREN_NAYAR, fs, fm), 3e-9, mu == 0 ? "E(0) = A + B/2" : "", A + B / 2,
              1e-5);
    }
  // Burley at r = 1, grazing: 785/504
  {
    KernelTable t = kr.diffuseAlbedo(DIFFUSE_BURLEY, 1, 1, 1.0f, 1.0f, true, 0.0f, 0.0f);
    run.add("burley r 1", "mu=0", t.planes[0][0], t.err[0], kDiffuseAllowance,
            reference::diffuseAlbedo(DIFFUSE_BURLEY, 1.0, 0.0), 3e-9, "E(0) = 785/504", 785.0 / 504, 1e-5);
  }
  // k_p at small alpha: pi alpha^2 (ggx, beckmann), 2 pi/(e+2) (blinn-phong); 0 at r = 0
  for (int ndf : {NDF_GGX, NDF_BLINN_PHONG})
    for (double r : {0.01, 0.0}) {
      float fr = static_cast<float>(r);
      KernelTable t = kr.kp(ndf, 1, true, fr, fr);
      double a = double(fr) * fr, closed = ndf == NDF_GGX ? kPi * a * a : (a > 0 ? kPi * a * a : 0);
      run.add("k_p small alpha", ndfNames()[ndf] + " r=" + fmt4(fr), t.planes[0][0], t.err[0],
              floatArithmeticError(scaleOf(t), kKpFloat), reference::kp(ndf, fr), 3e-9, "k_p = pi alpha^2", closed,
              1e-6 * std::max(1e-12, closed) + 1e-15);
    }
  // average albedo at r -> 0: 1 for smith-correlated
  for (double r : {0.01, 0.0}) {
    float fr = static_cast<float>(r);
    KernelTable t = kr.albedoAvg(ggx, sc, 1, true, {}, fr, fr);
    run.add("albedo-avg r -> 0", "ggx+smith-correlated r=" + fmt4(fr), t.planes[0][0], t.err[0],
            avgFloatArithmeticError(scaleOf(t), ggx, sc), reference::albedoAvg(ggx, sc, fr), 1e-7, "E_avg -> 1", 1.0,
            r == 0 ? 1e-6 : 1e-3);
  }

  // sheen (charlie): alpha -> 0 puts the lobe on the horizon, below every incident direction: E -> 0
  for (int gaf : {GAF_CHARLIE_SMITH, GAF_NEUBELT})
    for (double r : {0.1, 0.03, 0.01, 0.0})
      run.sheen("charlie alpha -> 0", gaf, 0.5, r, "E -> 0 (lobe on the horizon)", 0.0,
                r == 0     ? 1e-12
                : r >= 0.1 ? 1e-2
                           : 1e-3);  // neubelt still holds 1.4e-3 at r = 0.1
  // grazing views: E grows (neubelt and implicit to their closed forms at mu = 0; charlie-smith like 1/(mu Lambda(mu)))
  for (double r : {0.5, 0.05})
    for (double mu : {1e-3, 1e-6}) run.sheen("charlie mu -> 0", GAF_CHARLIE_SMITH, mu, r);
  for (int gaf : {GAF_NEUBELT, GAF_IMPLICIT})
    for (double r : {1.0, 0.5, 0.05}) {
      double fr = static_cast<float>(r);
      run.sheen("charlie mu -> 0", gaf, 1e-6, r);
      run.sheen("charlie mu -> 0", gaf, 0.0, r, "E(0, r) closed form", sheenGrazing(gaf, fr),
                1e-5 * sheenGrazing(gaf, fr));
    }
  run.sheen("charlie corner", GAF_IMPLICIT, 0.0, 0.0, "lim E(0, r -> 0) = 1/2", 0.5, 1e-5);
  // charlie's k_p = 2 pi alpha/(1 + 2 alpha), closed form (Estevez and Kulla 2017's normalisation)
  for (double r : {1.0, 0.01, 0.0}) {
    float fr = static_cast<float>(r);
    KernelTable t = kr.kp(NDF_CHARLIE, 1, true, fr, fr);
    double a = double(fr) * fr, closed = 2 * kPi * a / (1 + 2 * a);
    run.add("k_p charlie", "charlie r=" + fmt4(fr), t.planes[0][0], t.err[0],
            floatArithmeticError(scaleOf(t), kKpFloat), closed, 3e-9, "k_p = 2 pi alpha/(1 + 2 alpha)", closed,
            1e-6 * closed + 1e-15);
  }
}

}  // namespace brdfbake
