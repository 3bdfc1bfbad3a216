#include "reference/reference.h"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <complex>
#include <glm/glm.hpp>
#include <vector>

#include "common/brdf_host.h"
#include "reference/adaptive.h"
#include "reference/sheen_reference.h"
#include "reference/smith_exact_reference.h"

namespace brdfbake::reference {
namespace {

using glm::dvec3;
constexpr double kPi = 3.14159265358979323846;
constexpr double kTol = 1e-11;  // absolute, per integral
constexpr unsigned kDepth = 18;

// The two split-sum moments (E, B) integrated together: the same nodes serve both.
using detail::Pair;

using detail::adapt;

// Over [a, b], split first at the given interior points.
template <class F>
auto integrate(F f, double a, double b, std::vector<double> breaks, unsigned depth = kDepth, double tol = kTol,
               double rel = 1e-10) -> decltype(f(a)) {
  return detail::adaptPieces(f, a, b, std::move(breaks), tol, depth, rel);
}

using detail::lobeBreaks;

// ---- the models, written here from the papers (only D comes from kernels/brdf) -----------------

struct Model {
  int ndf, gaf;
  double r, alpha;
  double k;               // Schlick's k
  brdf64::BrdfParams dp;  // for D only (alpha, and 1/k_p of the gaussian)
  double oc = -1;         // o.h where the weight has a kink (Fresnel's critical angle), or -1
  bool direct = false;    // exact Lambda by quadrature at each call, not from the per-r cache
};

// Schlick's k: Schlick 1994 with m = alpha (k = alpha sqrt(2/pi)); Karis 2013: alpha/2 for image
// based lighting, (r + 1)^2/8 for analytic lights.
double schlickK(int gaf, double r) {
  double alpha = r * r;
  switch (gaf) {
    case GAF_SCHLICK_BECKMANN:
      return alpha * std::sqrt(2 / kPi);
    case GAF_SCHLICK_GGX:
      return alpha / 2;
    case GAF_SCHLICK_GGX_DIRECT:
      return (r + 1) * (r + 1) / 8;
    default:
      return 0;
  }
}

Model model(int ndf, int gaf, double r) {
  Model m{ndf, gaf, r, r * r, schlickK(gaf, r), {}};
  m.dp.r = r;
  m.dp.alpha = m.alpha;
  m.dp.inv_kp = (ndf == NDF_GAUSSIAN && m.alpha > 0) ? 1 / kp(ndf, r) : 0;
  return m;
}

// Smith Lambda of a direction with cosine c to the normal (0 < c <= 1).
// GGX, Heitz 2014 eq. 72: (-1 + sqrt(1 + alpha^2 tan^2))/2. Beckmann, Heitz 2014 eq. 71 with
// a = 1/(alpha tan): (erf(a) - 1)/2 + exp(-a^2)/(2 a sqrt(pi)). Blinn-Phong and the gaussian use
// Beckmann's with the same alpha (docs/MODELS.md).
double smithLambda(const Model& m, double c) {
  double t2 = (1 - c) * (1 + c) / (c * c);
  if (t2 <= 0 || m.alpha <= 0) return 0;
  if (m.ndf == NDF_GGX) return (std::sqrt(1 + m.alpha * m.alpha * t2) - 1) / 2;
  double a = 1 / (m.alpha * std::sqrt(t2));
  return -std::erfc(a) / 2 + std::exp(-a * a) / (2 * a * std::sqrt(kPi));
}

double smithLambdaExact(const Model& m, double c) {
  if (m.ndf != NDF_BLINN_PHONG && m.ndf != NDF_GAUSSIAN) return smithLambda(m, c);
  return (m.direct ? detail::cLambdaQuad(m.ndf, m.dp, c) : detail::cLambdaTabled(m.ndf, m.dp, c)) / c;
}

double gafOf(const Model& m, const dvec3& i, const dvec3& o, const dvec3& h) {
  double ni = i.z, no = o.z, nh = h.z, oh = glm::dot(o, h), ih = glm::dot(i, h);
  if (ni <= 0 || no <= 0 || oh <= 0 || ih <= 0) return 0;  // chi+
  switch (m.gaf) {
    case GAF_NONE:
      return 1;  // Ward
    case GAF_IMPLICIT:
      return ni * no;  // Blinn-Phong's implicit G
    case GAF_COOK_TORRANCE:
      return std::min({1.0, 2 * nh * no / oh, 2 * nh * ni / ih});  // Cook-Torrance 1982
    case GAF_KELEMEN:
      return ni * no / (oh * ih);  // Kelemen, Szirmay-Kalos 2001
    case GAF_NEUMANN:
      return ni * no / std::max(ni, no);  // Neumann et al. 1999
    case GAF_ASHIKHMIN_PREMOZE:           // Ashikhmin, Premoze 2007
    case GAF_NEUBELT:
      return ni * no / (ni + no - ni * no);  // Neubelt, Pettineo 2013: the same G
    case GAF_CHARLIE_SMITH:                  // Estevez, Kulla 2017
      return 1 / (1 + charlieLambda(m.r, ni) + charlieLambda(m.r, no));
    case GAF_SCHLICK_BECKMANN:
    case GAF_SCHLICK_GGX:
    case GAF_SCHLICK_GGX_DIRECT: {  // Schlick 1994
      auto g = [&](double x) { return x / (x * (1 - m.k) + m.k); };
      return g(ni) * g(no);
    }
    case GAF_SMITH:
      return 1 / ((1 + smithLambda(m, ni)) * (1 + smithLambda(m, no)));  // separable
    case GAF_SMITH_EXACT:
      return 1 / ((1 + smithLambdaExact(m, ni)) * (1 + smithLambdaExact(m, no)));
    case GAF_SMITH_CORRELATED_EXACT:
      return 1 / (1 + smithLambdaExact(m, ni) + smithLambdaExact(m, no));
    default:
      return 1 / (1 + smithLambda(m, ni) + smithLambda(m, no));  // height-correlated, Heitz 2014
  }
}

// The branch differences of the min/max GAFs: G has a kink where one of these changes sign (and
// nowhere else). The integrators split there; the locations are found by root finding.
int branchDifferences(const Model& m, const dvec3& i, const dvec3& o, const dvec3& h, double* d) {
  double ni = i.z, no = o.z, nh = h.z, oh = glm::dot(o, h);
  int n = 0;
  if (m.gaf == GAF_NEUMANN) d[n++] = ni - no;
  if (m.gaf == GAF_COOK_TORRANCE) {
    d[n++] = 2 * nh * no - oh;
    d[n++] = 2 * nh * ni - oh;
    d[n++] = ni - no;
  }
  if (m.oc > 0) d[n++] = oh - m.oc;  // the weight's kink (Fresnel)
  return n;
}
bool hasBranches(const Model& m) { return m.gaf == GAF_NEUMANN || m.gaf == GAF_COOK_TORRANCE || m.oc > 0; }

// The half vector at (theta, phi), the view o = (s, 0, mu) and the mirror direction i.
struct Geometry {
  dvec3 o, h, i;
};
Geometry geometry(double mu, double s, double th, double phi) {
  Geometry g;
  g.o = dvec3(s, 0, mu);
  g.h = dvec3(std::sin(th) * std::cos(phi), std::sin(th) * std::sin(phi), std::cos(th));
  g.i = 2 * glm::dot(g.o, g.h) * g.h - g.o;
  return g;
}

// Roots of the branch differences along x in [lo, hi], sampled at `xs` (sorted, inside [lo, hi])
// and refined by TOMS 748 where a difference changes sign between samples.
template <class At>
void branchRoots(const Model& m, At at, const std::vector<double>& xs, std::vector<double>& roots) {
  if (!hasBranches(m)) return;
  auto diffs = [&](double x, double* d) {
    Geometry g = at(x);
    return branchDifferences(m, g.i, g.o, g.h, d);
  };
  double prev[4], cur[4];
  int nd = diffs(xs[0], prev);
  for (size_t j = 1; j < xs.size(); ++j) {
    diffs(xs[j], cur);
    for (int k = 0; k < nd; ++k) {
      if ((prev[k] < 0) != (cur[k] < 0) && prev[k] != 0 && cur[k] != 0) {
        boost::uintmax_t iters = 200;
        auto f = [&](double x) {
          double d[4];
          diffs(x, d);
          return d[k];
        };
        auto r = boost::math::tools::toms748_solve(f, xs[j - 1], xs[j], prev[k], cur[k],
                                                   boost::math::tools::eps_tolerance<double>(52), iters);
        roots.push_back(0.5 * (r.first + r.second));
      }
      prev[k] = cur[k];
    }
  }
}

// cos(phimax): the mirror direction is above the surface (n.i > 0) for cos(phi) > c0, with
// n.i = 2 (o.h) cos(theta) - mu and o.h = s sin(theta) cos(phi) + mu cos(theta).
double cosPhiLimit(double mu, double s, double th) { return -mu * std::cos(2 * th) / (s * std::sin(2 * th)); }

Moments albedoInside(int ndf, int gaf, double r, double mu, const Weight& wt) {
  Model m = model(ndf, gaf, r);
  m.oc = weightKink(wt);
  double s = std::sqrt((1 - mu) * (1 + mu));
  // E = int sin(th) dth 2 int_0^phimax dphi D (G/no) F (o.h), the h-space form of the albedo
  // (dw_i = 4 (o.h) dw_h, phi folded). E and B (F = (1 - o.h)^5) are integrated together.
  double th1 = std::atan(mu / (1 + s)), th2 = std::atan2(1 + s, mu);
  auto phiEnd = [&](double th) { return th <= th1 ? kPi : std::acos(std::clamp(cosPhiLimit(mu, s, th), -1.0, 1.0)); };
  auto outer = [&](double th) {
    double sn = std::sin(th), c = std::cos(th);
    double D = brdf64::ndf_D(ndf, m.dp, c, sn * sn);
    double phimax = phiEnd(th);
    // delta: o.h - oc to full relative precision where the caller has it, NaN elsewhere
    auto innerAt = [&](double phi, double delta) {
      Geometry g = geometry(mu, s, th, phi);
      double oh = glm::dot(g.o, g.h);
      double G = gafOf(m, g.i, g.o, g.h);
      double H = G / mu * oh;
      return Pair{H, H * (std::isnan(delta) ? weightAt(wt, oh) : weightNearKink(wt, oh, delta))};
    };
    auto inner = [&](double phi) { return innerAt(phi, std::nan("")); };
    double w = 2 * sn * D;
    if (phimax <= 0 || !(w > 0)) return Pair{};
    // the kinks of min/max GAFs in phi, by root finding on 65 samples
    std::vector<double> br, xs;
    for (int k = 0; k <= 64; ++k) xs.push_back(phimax * k / 64.0);
    Model noKink = m;
    noKink.oc = -1;
    branchRoots(
        noKink, [&](double phi) { return geometry(mu, s, th, phi); }, xs, br);
    // inner far tighter than outer: its rounding must not look like structure to the outer rule.
    // Its absolute tolerance applies to the weighted value w * inner.
    const double tol = std::max(1e-14, 1e-14 / w);
    // Next to the weight's kink (o.h = oc) F has a square-root end, and o.h - oc must keep its
    // relative precision there (weightNearKink). On this circle o.h = s sn cos(phi) + mu c falls
    // with phi; it crosses oc at most once. The circle is integrated in t = |phi - anchor| from an
    // anchor where o.h - oc is known: the crossing (0 there), else the arc's end phimax where o.h
    // is nearest oc. There o.h - oc = d_anchor + s sn (cos(anchor +- t) - cos(anchor)), the
    // difference written as -+2 s sn sin(anchor +- t/2) sin(t/2), exact to rounding as t -> 0;
    // t = L y^2 makes the square-root end smooth in y.
    const double ss = s * sn;
    if (!(m.oc > 0 && ss > 0) || ss + mu * c <= m.oc)  // no kink, or total reflection (F = 1) throughout
      return w * integrate(inner, 0, phimax, br, 30, tol, 1e-13);
    const double cosKink = (m.oc - mu * c) / ss;
    const bool crosses = std::fabs(cosKink) < 1 && std::acos(cosKink) < phimax;
    const double anchor = crosses ? std::acos(cosKink) : phimax;
    const double dAnchor = crosses ? 0.0 : ss * std::cos(phimax) + mu * c - m.oc;
    auto side = [&](double lo, double hi, double sign) {  // sign +1: phi = anchor + t, -1: anchor - t
      double L = hi - lo;
      auto graded = [&](double y) {
        double t = L * y * y;
        double delta = dAnchor - sign * 2 * ss * std::sin(anchor + sign * t / 2) * std::sin(t / 2);
        return innerAt(anchor + sign * t, delta) * (2 * L * y);
      };
      std::vector<double> ycut;
      for (double b : br)
        if (b > lo && b < hi) ycut.push_back(std::sqrt(std::fabs(b - anchor) / L));
      return integrate(graded, 0, 1, ycut, 30, tol, 1e-13);
    };
    if (!crosses) return w * side(0, phimax, -1);
    return w * (side(0, anchor, -1) + side(anchor, phimax, 1));
  };
  // Where the phi-integral has kinks in theta: a branch root enters or leaves the arc at one of
  // its ends (phi = 0, phi = phimax). Sampled densely, geometrically towards both ends of the
  // theta range (grazing views put them within mu of 0 and of th2), refined by root finding.
  std::vector<double> kinkTheta;
  {
    std::vector<double> xs;
    for (int k = 1; k < 512; ++k) xs.push_back(th2 * k / 512.0);
    for (double d = 1e-14; d < th2 / 512; d *= 1.5) {
      xs.push_back(d);
      xs.push_back(th2 - d);
    }
    std::sort(xs.begin(), xs.end());
    branchRoots(
        m, [&](double th) { return geometry(mu, s, th, 0.0); }, xs, kinkTheta);
    branchRoots(
        m, [&](double th) { return geometry(mu, s, th, phiEnd(th)); }, xs, kinkTheta);
  }
  // [0, th1]: the whole half circle is visible; [th1, th2]: phimax falls from pi to 0 with
  // square-root ends. The partial range is cut geometrically (th1 2^k: the NDF's tail is a power
  // law there), at the lobe scale and at the kinks; th = a + L y^2 on the first panel and
  // th = b - L (1-y)^2 on the last one make the square-root ends smooth.
  std::vector<double> fullBreaks = lobeBreaks(m.alpha, th1);
  fullBreaks.insert(fullBreaks.end(), kinkTheta.begin(), kinkTheta.end());
  Pair v = integrate(outer, 0, th1, fullBreaks);
  std::vector<double> pb = lobeBreaks(m.alpha, th2);
  pb.insert(pb.end(), kinkTheta.begin(), kinkTheta.end());
  for (double t = th1 > 0 ? 2 * th1 : std::max(m.alpha, 1e-6); t < th2; t *= 2) pb.push_back(t);
  pb.push_back(th1);
  pb.push_back(th2);
  std::sort(pb.begin(), pb.end());
  pb.erase(std::remove_if(pb.begin(), pb.end(), [&](double t) { return t < th1 || t > th2; }), pb.end());
  for (size_t k = 0; k + 1 < pb.size(); ++k) {
    double a = pb[k], b = pb[k + 1], L = b - a;
    if (L <= 0) continue;
    bool first = k == 0, last = k + 2 == pb.size();
    auto panel = [&](double y) {
      if (first && last) return outer(a + L * y * y * (3 - 2 * y)) * 6 * L * y * (1 - y);
      if (first) return outer(a + L * y * y) * 2 * L * y;
      if (last) return outer(b - L * (1 - y) * (1 - y)) * 2 * L * (1 - y);
      return outer(a + L * y) * L;
    };
    v = v + integrate(panel, 0, 1, {});
  }
  Moments out;
  out.a = v.e - v.b;
  out.b = v.b;
  return out;
}

}  // namespace

// Where the weight has a kink: total internal reflection from o.h < sqrt(1 - eta^2), eta < 1.
double weightKink(const Weight& w) {
  bool tir = w.kind == Weight::Fresnel && (w.f.model == FRESNEL_DIELECTRIC || w.f.model == FRESNEL_SCHLICK_TIR);
  return tir && w.f.x < 1 ? std::sqrt(1 - w.f.x * w.f.x) : -1;
}

double gaf(int ndf, int g, double r, const double i[3], const double o[3], const double h[3]) {
  Model m = model(ndf, g, r);
  m.direct = true;  // one point: the quadrature itself (the cache pays off over an integral)
  return gafOf(m, dvec3(i[0], i[1], i[2]), dvec3(o[0], o[1], o[2]), dvec3(h[0], h[1], h[2]));
}

double normalisation(int ndf, double r, double invKp) {
  brdf64::BrdfParams p{};
  p.r = r;
  p.alpha = r * r;
  p.inv_kp = invKp;
  auto f = [&](double th) {
    double s = std::sin(th), c = std::cos(th);
    return 2 * kPi * brdf64::ndf_D(ndf, p, c, s * s) * c * s;
  };
  std::vector<double> br = lobeBreaks(p.alpha, kPi / 2);
  if (ndf == NDF_CHARLIE)  // the sheen lobe hugs the horizon: geometric towards pi/2
    for (double d = 0.5; d > 1e-9; d /= 4) br.push_back(kPi / 2 - d);
  return integrate(f, 0, kPi / 2, br);
}

double kp(int ndf, double r) {
  brdf64::BrdfParams p{};
  p.r = r;
  p.alpha = r * r;
  if (p.alpha <= 0) return 0;  // pi alpha^2 -> 0 (the delta's normalisation)
  // k_p = 2 pi int_0^{pi/2} p(theta) cos sin dtheta
  auto f = [&](double th) {
    double s = std::sin(th), c = std::cos(th);
    return 2 * kPi * brdf64::ndf_p(ndf, p, c, s * s) * c * s;
  };
  std::vector<double> br = lobeBreaks(p.alpha, kPi / 2);
  if (ndf == NDF_CHARLIE)
    for (double d = 0.5; d > 1e-9; d /= 4) br.push_back(kPi / 2 - d);
  return integrate(f, 0, kPi / 2, br);
}

Moments albedo(int ndf, int gaf, double r, double mu, const Weight& w) {
  if (r <= 0 && mu <= 0) {
    // the corner: the limit along the mu = 0 edge, from inside (alpha ~ 1e-9, mu << alpha)
    const double rc = 3e-5;
    return albedoInside(ndf, gaf, rc, 1e-9 * rc * rc, w);
  }
  if (r <= 0) return mirrorAlbedo(gaf, mu, w);
  if (mu <= 0) return albedoInside(ndf, gaf, r, 1e-9 * std::min(1.0, r * r), w);
  return albedoInside(ndf, gaf, r, mu, w);
}

double albedoAvg(int ndf, int gaf, double r, const Weight& w) {
  auto value = [&](const Moments& m) { return w.kind == Weight::Split ? m.e() : m.b; };
  double oc = weightKink(w);
  if (r <= 0) {
    auto f = [&](double mu) { return 2 * mu * value(mirrorAlbedo(gaf, mu, w)); };
    return integrate(f, 0, 1, oc > 0 ? std::vector<double>{oc} : std::vector<double>{});
  }
  auto f = [&](double mu) { return 2 * mu * value(albedoInside(ndf, gaf, r, mu, w)); };
  std::vector<double> br = lobeBreaks(r * r, 1);
  // E_F(mu) bends where the lobe's o.h reaches the critical cosine: within a few lobe widths
  // (alpha) of mu = oc, sharply for a narrow lobe
  if (oc > 0)
    for (double k : {0.0, 0.3, 1.0, 3.0, 10.0}) {
      br.push_back(oc - k * r * r);
      br.push_back(oc + k * r * r);
    }
  return integrate(f, 0, 1, br);
}

double smithLambdaExact(int ndf, double r, double mu) {
  Model m = model(ndf, GAF_SMITH_EXACT, r);
  return detail::cLambdaQuad(ndf, m.dp, mu) / mu;
}

double weakFurnace(int ndf, double r, double mu) { return weakFurnace(ndf, GAF_SMITH, r, mu); }

double weakFurnace(int ndf, int gaf, double r, double mu) {
  Model m = model(ndf, gaf, r);
  double s = std::sqrt((1 - mu) * (1 + mu));
  bool exact = gaf == GAF_SMITH_EXACT || gaf == GAF_SMITH_CORRELATED_EXACT;
  double g1 = 1 / (1 + (exact ? smithLambdaExact(ndf, r, mu) : smithLambda(m, mu)));
  // int over h with o.h > 0: cos(phi) > -mu c/(s sn)
  auto outer = [&](double th) {
    double sn = std::sin(th), c = std::cos(th);
    double c0 = s > 0 && sn > 0 ? -mu * c / (s * sn) : -2.0;
    double phimax = std::acos(std::clamp(c0, -1.0, 1.0));
    auto inner = [&](double phi) { return std::max(0.0, s * sn * std::cos(phi) + mu * c); };
    return 2 * sn * brdf64::ndf_D(ndf, m.dp, c, sn * sn) * integrate(inner, 0, phimax, {});
  };
  std::vector<double> br = lobeBreaks(m.alpha, kPi / 2);
  br.push_back(std::atan2(mu, s));  // theta_h = pi/2 - theta_o: o.h > 0 on the whole circle below it
  return g1 * integrate(outer, 0, kPi / 2, br);
}

}  // namespace brdfbake::reference
