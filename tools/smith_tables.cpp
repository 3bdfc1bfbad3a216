// smith_tables: generates kernels/brdf/smith_tables.h, the exact Smith Lambda of the Blinn-Phong
// and gaussian NDFs as a correction to Beckmann's (docs/MODELS.md "Exact Smith Lambda").
//
//   build: cmake --build build --target brdfbake-smith-tables
//   run:   build/brdfbake-smith-tables > kernels/brdf/smith_tables.h   (prints its error to stderr)
//
// Smith 1967 / Heitz 2014 (eq. 17-18 and sec. 5.1): with P22 the slope distribution
// (P22(m) = D(h) cos^4 theta_h for an isotropic NDF, m = tan theta_h) and a = cot theta_o,
//   cos(theta_o) Lambda = sin(theta_o) F(a),  F(a) = int_{q > a} (q - a) P22(q, p) dq dp
// (the projected area of the back-facing microfacets). In polar slope coordinates the azimuth
// integrates in closed form: F(a) = int_a^inf P22(m) m 2 (sqrt(m^2 - a^2) - a acos(a/m)) dm.
// In Beckmann-scaled units x = m/alpha, b = a/alpha, Ft(b) = F/alpha = int_b^inf h(x) x 2 g(x, b) dx
// with h(x) = alpha^2 P22(alpha x):
//   Beckmann:    h = exp(-x^2)/pi                       Ft = exp(-b^2)/(2 sqrt pi) - b erfc(b)/2
//   Blinn-Phong: h = (1 + y x^2)^-(1/y + 1) / pi,  y = alpha^2 = 2/(e + 2)
//   gaussian:    h = y exp(-atan(sqrt(y) x)^2 / y) / (k_p (1 + y x^2)^2)
// Tabulated: V(z, y) = (Ft_exact(b) - Ft_beckmann(b))/y on z = b/(1+b) = c/(c + alpha s) in [0, 1]
// and y = alpha^2 in [0, 1], uniform; V(z, 0) by Richardson extrapolation. The kernel evaluates
//   c Lambda = c Lambda_beckmann + alpha^3 s V(z, y)
// with 4-point Lagrange interpolation in both axes (kernels/brdf/ndf.h, ndf_cLambda_exact).
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "reference/adaptive.h"

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr int NZ = 129, NY = 33;

template <class F>
double integrate(F f, std::vector<double> br, double tol) {
  double s = 0;
  for (size_t i = 0; i + 1 < br.size(); ++i) s += brdfbake::reference::detail::adapt(f, br[i], br[i + 1], tol, 40, 0.0);  // absolute tolerance only
  return s;
}

// g(x, b) = sqrt(x^2 - b^2) - b acos(b/x) = b (r - atan r), r = sqrt(u (2b + u))/b, u = x - b.
double gfun(double u, double b) {
  if (b <= 0) return u;
  double r = std::sqrt(u * (2 * b + u)) / b;
  if (r > 0.05) return b * (r - std::atan(r));
  double r2 = r * r, s = 0, p = r * r2;
  for (int k = 1; k <= 7; ++k, p *= r2) s += (k % 2 ? 1.0 : -1.0) * p / (2 * k + 1);
  return b * s;
}

struct Ndf {
  int model;  // 1 beckmann, 2 blinn-phong, 3 gaussian
  double y, kp;
  double h(double x) const {
    if (model == 1) return std::exp(-x * x) / kPi;
    if (model == 2) return std::exp(-(1 / y + 1) * std::log1p(y * x * x)) / kPi;
    double t = std::atan(std::sqrt(y) * x);
    double d = 1 + y * x * x;
    return y * std::exp(-t * t / y) / (kp * d * d);
  }
};

Ndf makeNdf(int model, double y) {
  Ndf n{model, y, 0};
  static double lastY = -1, lastKp = 0;  // k_p depends on y only: once per table row
  if (model == 3 && y == lastY) {
    n.kp = lastKp;
  } else if (model == 3) {  // k_p = 2 pi int_0^{pi/2} exp(-theta^2/alpha^2) cos sin dtheta
    double al = std::sqrt(y);
    auto f = [&](double th) { return 2 * kPi * std::exp(-th * th / y) * std::cos(th) * std::sin(th); };
    std::vector<double> br{0};
    for (double m : {0.5, 1.0, 2.0, 4.0, 8.0})
      if (m * al < kPi / 2) br.push_back(m * al);
    br.push_back(kPi / 2);
    n.kp = integrate(f, br, 1e-16 * y);
    lastY = y;
    lastKp = n.kp;
  }
  return n;
}

// Ft(b) = int_b^inf h(x) x 2 g(x, b) dx, over u = x - b = w t/(1 - t), t in [0, 1).
double ft(const Ndf& n, double b) {
  double w = 1 / (1 + 2 * b);
  auto f = [&](double t) {
    if (t >= 1) return 0.0;
    double u = w * t / (1 - t), du = w / ((1 - t) * (1 - t));
    return n.h(b + u) * (b + u) * 2 * gfun(u, b) * du;
  };
  return integrate(f, {0, 0.25, 0.5, 0.75, 0.9, 0.97, 0.99, 0.997, 0.999, 1}, 1e-16);
}

double ftBeckmann(double b) { return std::exp(-b * b) / (2 * std::sqrt(kPi)) - b * std::erfc(b) / 2; }

double value(int model, double z, double y) {
  if (z >= 1) return 0;
  double b = z / (1 - z);
  if (y <= 0) {  // Richardson: V(0) = 2 V(d) - V(2d) + O(d^2)
    const double d = 1e-3;
    return 2 * value(model, z, d) - value(model, z, 2 * d);
  }
  return (ft(makeNdf(model, y), b) - ftBeckmann(b)) / y;
}

// 4-point Lagrange interpolation as in the kernel
double lagrange(const std::vector<double>& tab, double z, double y) {
  auto axis = [](double v, int n, int* i0, double w[4]) {
    double u = v * (n - 1);
    double f = std::floor(u) - 1;
    f = std::fmin(std::fmax(f, 0.0), n - 4.0);
    double t = u - f;
    w[0] = -(t - 1) * (t - 2) * (t - 3) / 6;
    w[1] = t * (t - 2) * (t - 3) / 2;
    w[2] = -t * (t - 1) * (t - 3) / 2;
    w[3] = t * (t - 1) * (t - 2) / 6;
    *i0 = (int)f;
  };
  int iz, iy;
  double wz[4], wy[4];
  axis(z, NZ, &iz, wz);
  axis(y, NY, &iy, wy);
  double s = 0;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) s += wy[j] * wz[i] * (double)(float)tab[(iy + j) * NZ + iz + i];
  return s;
}
}  // namespace

int main(int argc, char** argv) {
  // optional argument: 2 or 3, only that model (for checking)
  int only = argc > 1 ? std::atoi(argv[1]) : 0;
  // sanity: the polar form reproduces Beckmann's closed form
  {
    Ndf bk{1, 0, 0};
    double worst = 0;
    for (double b : {0.0, 0.1, 0.5, 1.0, 2.0, 4.0})
      worst = std::fmax(worst, std::fabs(ft(bk, b) / ftBeckmann(b) - 1));
    std::fprintf(stderr, "polar form vs Beckmann closed form: max rel %.2e\n", worst);
  }
  const char* names[2] = {"blinn_phong", "gaussian"};
  std::printf("/* smith_tables.h: GENERATED by tools/smith_tables.cpp, do not edit.\n"
              " * V(z, y) = (Ft_exact - Ft_beckmann)/y for the exact Smith Lambda of Blinn-Phong and the\n"
              " * gaussian (docs/MODELS.md \"Exact Smith Lambda\"): z = c/(c + alpha s) on %d nodes, y = alpha^2\n"
              " * on %d nodes, both uniform in [0, 1], row-major tab[j * SMITH_NZ + i] (j: y, i: z). */\n",
              NZ, NY);
  std::printf("/* Once per pass (compat.h \"Passes\"). */\n"
              "#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_SMITH_TABLES_H_2) : !defined(BRDF_SMITH_TABLES_H)\n"
              "#ifdef BRDF_SECOND_PASS\n#define BRDF_SMITH_TABLES_H_2\n#else\n#define BRDF_SMITH_TABLES_H\n#endif\n"
              "#include \"brdf/compat.h\"\n");
  std::printf("#ifndef BRDF_LANE_PASS\n#define SMITH_NZ %d\n#define SMITH_NY %d\n", NZ, NY);
  for (int m = 0; m < 2; ++m) {
    int model = 2 + m;
    if (only && only != model) continue;
    std::vector<double> tab(NZ * NY);
    for (int j = 0; j < NY; ++j)
      for (int i = 0; i < NZ; ++i) tab[j * NZ + i] = value(model, double(i) / (NZ - 1), double(j) / (NY - 1));
    std::printf("BRDF_CONST float smith_tab_%s[SMITH_NZ * SMITH_NY] = {\n", names[m]);
    // values below float's smallest subnormal are 0 as float literals anyway: written as 0, so
    // that compilers do not warn about truncation
    for (int k = 0; k < NZ * NY; ++k)
      std::printf("%.9ef%s", std::fabs(tab[k]) < 1e-45 ? 0.0 : tab[k], (k % 24 == 23 || k + 1 == NZ * NY) ? ",\n" : ", ");
    std::printf("};\n");
    // error at cell centres (and off-centre points): G1-relative (|dLambda|/(1 + Lambda)) and
    // Lambda-relative where Lambda > 1e-3
    double worstG = 0, worstL = 0;
    for (int j = 0; j + 1 < NY; ++j)
      for (int i = 0; i + 1 < NZ; i += 1)
        for (double fy : {0.5})
          for (double fz : {0.5}) {
            double y = (j + fy) / (NY - 1), z = (i + fz) / (NZ - 1), b = z / (1 - z);
            double exact = value(model, z, y), got = lagrange(tab, z, y);
            double ftx = ftBeckmann(b) + y * exact;  // Lambda = Ft/b, 1 + Lambda = (b + Ft)/b
            double dft = y * std::fabs(got - exact);
            worstG = std::fmax(worstG, dft / (b + ftx));
            if (ftx / b > 1e-3) worstL = std::fmax(worstL, dft / ftx);
          }
    std::fprintf(stderr, "%s: interpolation error max |dLambda|/(1+Lambda) %.2e, max |dLambda|/Lambda (Lambda > 1e-3) %.2e\n",
                 names[m], worstG, worstL);
  }
  std::printf("#endif /* !BRDF_LANE_PASS */\n");
  std::printf("#endif /* BRDF_SMITH_TABLES_H */\n");
}
