#include "reference/diffuse_reference.h"

#include "reference/adaptive.h"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>

namespace brdfbake::reference {
namespace {

using glm::dvec3;
constexpr double kPi = 3.14159265358979323846;
constexpr double kRelTol = 1e-12;  // relative to the L1 norm, per piece
constexpr unsigned kDepth = 12;
// Model ids: kernels/brdf/diffuse.h (repeated here so that this file needs nothing of it).
enum { kLambert, kShirley, kAshikhminShirley, kOrenNayar, kBurley, kShirleyPrinted, kOrenNayarPrinted };

const dvec3 kN(0, 0, 1);

// The angle between v and the normal, accurate at both ends.
double theta(const dvec3& v) { return std::atan2(glm::length(glm::cross(kN, v)), glm::dot(kN, v)); }
// cos of the azimuth difference of i and o: their projections onto the surface, i - n (n.i) (the
// seed's erratum: L - N (N.L)); 0 where one of them is the normal.
double cosAzimuth(const dvec3& i, const dvec3& o) {
  dvec3 ip = i - kN * glm::dot(kN, i), op = o - kN * glm::dot(kN, o);
  double li = glm::length(ip), lo = glm::length(op);
  return li > 0 && lo > 0 ? glm::dot(ip, op) / (li * lo) : 0.0;
}
// Oren and Nayar 1994, qualitative model.
double onA(double sigma) { return 1 - 0.5 * sigma * sigma / (sigma * sigma + 0.33); }
double onB(double sigma) { return 0.45 * sigma * sigma / (sigma * sigma + 0.09); }

double brdf(int model, double p, const dvec3& i, const dvec3& o) {
  double ni = glm::dot(kN, i), no = glm::dot(kN, o);
  switch (model) {
    case kShirley:  // Shirley et al. 1997
      return 21.0 / (20.0 * kPi) * (1 - p) * (1 - std::pow(1 - ni, 5)) * (1 - std::pow(1 - no, 5));
    case kShirleyPrinted:  // seed 000 as printed: (1 - F0) divides
      return 21.0 / (20.0 * kPi) / (1 - p) * (1 - std::pow(1 - ni, 5)) * (1 - std::pow(1 - no, 5));
    case kAshikhminShirley:  // Ashikhmin and Shirley 2000
      return 28.0 / (23.0 * kPi) * (1 - p) * (1 - std::pow(1 - ni / 2, 5)) * (1 - std::pow(1 - no / 2, 5));
    case kOrenNayar:
    case kOrenNayarPrinted: {  // Oren and Nayar 1994 (alpha = max, beta = min); printed: swapped
      double ti = theta(i), to = theta(o);
      double al = std::max(ti, to), be = std::min(ti, to);
      if (model == kOrenNayarPrinted) std::swap(al, be);
      return (onA(p) + onB(p) * std::max(0.0, cosAzimuth(i, o)) * std::sin(al) * std::tan(be)) / kPi;
    }
    case kBurley: {  // Burley 2012
      dvec3 h = glm::normalize(i + o);
      double cd = glm::dot(i, h), fd90 = 0.5 + 2 * p * cd * cd;
      return (1 + (fd90 - 1) * std::pow(1 - ni, 5)) * (1 + (fd90 - 1) * std::pow(1 - no, 5)) / kPi;
    }
    default:  // Lambert
      return 1 / kPi;
  }
}

template <class F>
double gk(F f, double a, double b) {
  if (!(b > a)) return 0.0;
  return detail::adapt(f, a, b, 1e-14, kDepth, kRelTol);
}

}  // namespace

double diffuseBrdf(int model, double param, const double i[3], const double o[3]) {
  return brdf(model, param, dvec3(i[0], i[1], i[2]), dvec3(o[0], o[1], o[2]));
}

double diffuseAlbedo(int model, double param, double mu) {
  if (model == kOrenNayarPrinted && mu <= 0 && onB(param) > 0) return std::numeric_limits<double>::infinity();
  double so = std::sqrt((1 - mu) * (1 + mu));
  dvec3 o(so, 0, mu);
  double to = std::atan2(so, mu);
  // inner: phi over the whole circle, breakpoints where max(0, cos phi) kinks
  auto inner = [&](double th) {
    double st = std::sin(th), ct = std::cos(th);
    auto f = [&](double ph) { return brdf(model, param, dvec3(st * std::cos(ph), st * std::sin(ph), ct), o); };
    double v = gk(f, 0, kPi / 2) + gk(f, kPi / 2, 3 * kPi / 2) + gk(f, 3 * kPi / 2, 2 * kPi);
    return v * st * ct;
  };
  // outer: theta_i, breakpoint at theta_o (Oren-Nayar's max/min)
  return gk(inner, 0, to) + gk(inner, to, kPi / 2);
}

double diffuseAlbedoClosedForm(int model, double p, double mu) {
  double t = std::atan2(std::sqrt((1 - mu) * (1 + mu)), mu), s = std::sin(t);
  switch (model) {
    case kLambert:
      return 1.0;
    case kShirley:  // 2 pi int_0^1 (1-(1-x)^5) x dx = 20 pi/21
      return (1 - p) * (1 - std::pow(1 - mu, 5));
    case kShirleyPrinted:
      return (1 - std::pow(1 - mu, 5)) / (1 - p);
    case kAshikhminShirley:  // 2 pi int_0^1 (1-(1-x/2)^5) x dx = 23 pi/28
      return (1 - p) * (1 - std::pow(1 - mu / 2, 5));
    case kOrenNayar: {
      // A + (2B/pi) [sin t (t/2 - sin 2t/4) + tan t (1 - sin^3 t)/3], the last term written as
      // s mu (1 + s + s^2)/(1 + s) (1 - s = mu^2/(1 + s)): 0 at mu = 0.
      double tail = s * mu * (1 + s + s * s) / (1 + s) / 3;
      return onA(p) + 2 * onB(p) / kPi * (s * (t / 2 - std::sin(2 * t) / 4) + tail);
    }
    case kOrenNayarPrinted: {
      // A + (2B/pi) [tan t sin^3 t/3 + sin t (pi/4 - t/2 + sin 2t/4)]
      double b = onB(p);
      if (b > 0 && mu <= 0) return std::numeric_limits<double>::infinity();
      double tn = b > 0 ? s / mu : 0.0;
      return onA(p) + 2 * b / kPi * (tn * s * s * s / 3 + s * (kPi / 4 - t / 2 + std::sin(2 * t) / 4));
    }
    case kBurley:
      if (mu == 0) {
        // m = 1/2 + r: m + 2 (m^2 - m)/42 + r^2 11/504 (int x(1-x)^5 = 1/42, int x^3 (1-x)^5 = 1/504)
        double m = 0.5 + p;
        return m + 2 * (m * m - m) / 42 + p * p * 11.0 / 504;
      }
      return std::numeric_limits<double>::quiet_NaN();
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

std::string diffuseName(int model) {
  static const char* const names[] = {
      "lambert", "shirley", "ashikhmin-shirley", "oren-nayar", "burley", "shirley-as-printed", "oren-nayar-as-printed"};
  return model >= 0 && model < 7 ? names[model] : "diffuse#" + std::to_string(model);
}

}  // namespace brdfbake::reference
