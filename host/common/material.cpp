#include "common/material.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/models.h"

namespace brdfbake {

const std::vector<std::string>& fresnelNames() {
  static const std::vector<std::string> n = {"one", "schlick", "dielectric", "schlick-tir", "conductor", "f82-tint"};
  return n;
}

int fresnelId(const std::string& name, const std::string& field) {
  for (size_t i = 0; i < fresnelNames().size(); ++i)
    if (fresnelNames()[i] == name) return static_cast<int>(i);
  throw Error(kExitUsage, field + ": unknown Fresnel model '" + name + "'" + didYouMean(name, fresnelNames()) +
                              "; valid: " + joinNames(fresnelNames()));
}

const std::vector<std::string>& diffuseNames() {
  static const std::vector<std::string> n = {
      "lambert", "shirley", "ashikhmin-shirley", "oren-nayar", "burley", "shirley-as-printed", "oren-nayar-as-printed"};
  return n;
}

int diffuseId(const std::string& name, const std::string& field) {
  for (size_t i = 0; i < diffuseNames().size(); ++i)
    if (diffuseNames()[i] == name) return static_cast<int>(i);
  throw Error(kExitUsage, field + ": unknown diffuse model '" + name + "'" + didYouMean(name, diffuseNames()) +
                              "; valid: " + joinNames(diffuseNames()));
}

DiffuseAxis diffuseAxis(int model) {
  switch (model) {
    case DIFFUSE_SHIRLEY:
    case DIFFUSE_ASHIKHMIN_SHIRLEY:
    case DIFFUSE_SHIRLEY_AS_PRINTED:
      return {"f0", 0, 1};
    case DIFFUSE_OREN_NAYAR:
    case DIFFUSE_OREN_NAYAR_AS_PRINTED:
      return {"sigma", 0, 1.5707963267948966};
    default:
      return {"r", 0, 1};
  }
}

std::vector<double> parseValues(const std::string& flag, const std::string& text) {
  std::vector<double> out;
  size_t start = 0;
  while (true) {
    size_t comma = text.find(',', start);
    std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    errno = 0;
    char* end = nullptr;
    double v = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || errno != 0 || !std::isfinite(v))
      throw Error(kExitUsage, flag + " must be one number or three comma-separated (R,G,B), got '" + text + "'");
    out.push_back(v);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (out.size() != 1 && out.size() != 3)
    throw Error(kExitUsage, flag + " must be one number or three comma-separated (R,G,B), got " +
                                std::to_string(out.size()) + " values");
  return out;
}

namespace {
double at(const std::vector<double>& v, int c) { return v.size() == 3 ? v[c] : v[0]; }

std::string join(const std::vector<double>& v) {
  std::string s;
  for (double x : v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.9g", x);
    s += (s.empty() ? "" : ",") + std::string(b);
  }
  return s;
}

void checkRange(const std::string& flag, const std::vector<double>& v, double lo, double hi, bool openLo,
                const std::string& range) {
  for (double x : v)
    if (x > hi || x < lo || (openLo && x == lo))
      throw Error(kExitUsage, flag + " must be in " + range + ", got " + join(v));
}
}  // namespace

int FresnelChoice::channels() const {
  for (const auto* v : {&f0, &eta, &k, &f82})
    if (v->size() == 3) return 3;
  return 1;
}

std::pair<double, double> FresnelChoice::modelParams(int c) const {
  switch (model) {
    case FRESNEL_SCHLICK:
      return {at(f0, c), 0};
    case FRESNEL_DIELECTRIC:
    case FRESNEL_SCHLICK_TIR:
      return {at(eta, c), 0};
    case FRESNEL_CONDUCTOR:
      return {at(eta, c), at(k, c)};
    case FRESNEL_F82_TINT:
      return {at(f0, c), at(f82, c)};
    default:
      return {0, 0};
  }
}

std::pair<double, double> FresnelChoice::kernelParams(int c) const {
  auto [x, y] = modelParams(c);
  if (model == FRESNEL_F82_TINT) y = brdf64::fresnel_f82_b(x, y);
  return {x, y};
}

std::vector<std::pair<std::string, std::string>> FresnelChoice::parameters() const {
  std::vector<std::pair<std::string, std::string>> p;
  if (!f0.empty()) p.push_back({"f0", join(f0)});
  if (!eta.empty()) p.push_back({"eta", join(eta)});
  if (!k.empty()) p.push_back({"k", join(k)});
  if (!f82.empty()) p.push_back({"f82", join(f82)});
  return p;
}

std::string FresnelChoice::describe() const {
  std::string s = fresnelNames()[model];
  for (const auto& [name, value] : parameters()) s += " " + name + "=" + value;
  return s;
}

double fresnelAverage(int model, double x, double y, double* err, std::string* how) {
  auto closed = [&](double v) {
    if (err) *err = 0;
    if (how) *how = "closed form";
    return v;
  };
  auto schlickAvg = [](double f0) { return (20 * f0 + 1) / 21; };  // 2 int (F0 + (1-F0)(1-mu)^5) mu dmu
  switch (model) {
    case FRESNEL_ONE:
      return closed(1);
    case FRESNEL_SCHLICK:
      return closed(schlickAvg(x));
    // 2 int mu (1 - mu)^6 mu dmu = 2 B(3, 7) = 1/126
    case FRESNEL_F82_TINT:
      return closed(schlickAvg(x) - y / 126);
    case FRESNEL_SCHLICK_TIR: {
      double f0 = (x - 1) * (x - 1) / ((x + 1) * (x + 1));
      if (x >= 1) return closed(schlickAvg(f0));
      // F = 1 below mu_c = sqrt(1 - eta^2); above, mu dmu = eta^2 ct dct maps [mu_c, 1] to ct in [0, 1]
      return closed((1 - x * x) + x * x * schlickAvg(f0));
    }
    default:
      break;
  }
  // dielectric, conductor: F from kernels/brdf/fresnel.h in double, split at the critical angle
  // mu = oc + (1 - oc) t^2: F has a square-root end at the critical angle oc (eta < 1), and for eta
  // near 1 changes on the scale mu ~ sqrt(eta^2 - 1) next to 0; the substitution smooths both
  double oc = model == FRESNEL_DIELECTRIC && x < 1 ? std::sqrt((1 - x) * (1 + x)) : 0;
  auto f = [&](double t) {
    double mu = oc + (1 - oc) * t * t;
    return 2 * mu * brdf64::fresnel_F(model, x, y, mu) * 2 * (1 - oc) * t;
  };
  using GK = boost::math::quadrature::gauss_kronrod<double, 31>;
  double e = 0;
  double v = oc * oc + GK::integrate(f, 0.0, 1.0, 15, 1e-13, &e);  // F = 1 on [0, oc]
  if (err) *err = e;
  if (how) *how = "GK31 adaptive";
  return v;
}

double fresnelAverage(const FresnelChoice& f, int c, double* err, std::string* how) {
  auto [x, y] = f.kernelParams(c);
  return fresnelAverage(f.model, x, y, err, how);
}

void validateFresnel(FresnelChoice& f) {
  const std::string name = "--fresnel " + fresnelNames()[f.model];
  // which flags each model takes
  bool takesF0 = f.model == FRESNEL_SCHLICK || f.model == FRESNEL_F82_TINT;
  bool takesEta = f.model == FRESNEL_DIELECTRIC || f.model == FRESNEL_SCHLICK_TIR || f.model == FRESNEL_CONDUCTOR;
  bool takesK = f.model == FRESNEL_CONDUCTOR;
  bool takesF82 = f.model == FRESNEL_F82_TINT;
  auto takes = [&]() {
    std::vector<std::string> t;
    if (takesF0) t.push_back("--f0");
    if (takesEta) t.push_back("--eta");
    if (takesK) t.push_back("--k");
    if (takesF82) t.push_back("--f82");
    return t.empty() ? std::string("no parameters") : joinNames(t) + " only";
  };
  auto reject = [&](const char* flag, const std::vector<double>& v, bool ok) {
    if (!v.empty() && !ok) throw Error(kExitUsage, std::string(flag) + ": " + name + " takes " + takes());
  };
  reject("--f0", f.f0, takesF0);
  reject("--eta", f.eta, takesEta);
  reject("--k", f.k, takesK);
  reject("--f82", f.f82, takesF82);
  checkRange("--f0", f.f0, 0, 1, false, "[0, 1]");
  checkRange("--eta", f.eta, 0, 100, true, "(0, 100]");
  checkRange("--k", f.k, 0, 100, false, "[0, 100]");
  checkRange("--f82", f.f82, 0, 1, false, "[0, 1] (the tint of Schlick's reflectance at mu = 1/7)");
  if (f.model == FRESNEL_CONDUCTOR && (f.eta.empty() || f.k.empty()))
    throw Error(kExitUsage, name + " needs --eta and --k (e.g. gold: --eta 0.18,0.42,1.37 --k 3.42,2.35,1.77)");
  if (takesF0 && f.f0.empty()) f.f0 = {0.04};
  if ((f.model == FRESNEL_DIELECTRIC || f.model == FRESNEL_SCHLICK_TIR) && f.eta.empty()) f.eta = {1.5};
  if (takesF82 && f.f82.empty()) f.f82 = {1.0};
}

}  // namespace brdfbake
