// The reference's exact Smith Lambda (the blinn-phong and gaussian -exact GAFs): by quadrature
// of the back-facing projected area, and tabled per (NDF, alpha) for the albedo integrals.
#include "reference/smith_exact_reference.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "reference/adaptive.h"

namespace brdfbake::reference::detail {
namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

// Exact Smith Lambda of any isotropic NDF from its projected area (Smith 1967; Heitz 2014 eq. 17-18):
//   cos(theta_o) (1 + Lambda) = int max(0, o.h) D dw_h, int D (n.h) dw_h = 1, so
//   cos(theta_o) Lambda = int max(0, -o.h) D(h) dw_h   (the back-facing microfacets' projected area).
// With o = (s, 0, c) and h at (theta, phi), o.h < 0 on |phi| > phi0 once theta > pi/2 - theta_o; the
// phi-integral is closed: 2 s sin(theta) (sin psi - psi cos psi), cos psi = cot(theta_o) cot(theta),
// psi = pi - phi0. theta = pi/2 - theta_o + d, d in (0, theta_o]: 1 - cos psi = sin d/(s sin theta)
// without cancellation. Adaptive GK31 in d, relative tolerance 1e-11 only (Lambda may be tiny).
double cLambdaQuad(int ndf, const brdf64::BrdfParams& dp, double c) {
  double s = std::sqrt((1 - c) * (1 + c));
  if (s <= 0 || dp.alpha <= 0) return 0;
  double tho = std::atan2(s, c);
  auto f = [&](double d) {
    double ct = std::sin(tho - d), st = std::cos(tho - d);  // cos, sin of theta = pi/2 - theta_o + d
    double om = std::sin(d) / (s * st);                     // 1 - cos psi
    double x = 1 - om, sp = std::sqrt(std::max(0.0, om * (2 - om)));
    double psi = std::atan2(sp, x);
    double g;         // sin psi - psi cos psi
    if (psi < 0.3) {  // series: the difference cancels (its terms 2k psi^(2k+1)/(2k+1)!)
      double p2 = psi * psi;
      g = psi * p2 *
          (1.0 / 3 - p2 * (1.0 / 30 - p2 * (1.0 / 840 - p2 * (1.0 / 45360 - p2 * (1.0 / 3991680 - p2 / 518918400)))));
    } else {
      g = sp - psi * x;
    }
    return brdf64::ndf_D(ndf, dp, ct, st * st) * st * 2 * s * st * g;
  };
  std::vector<double> br;
  // the lobe near theta = few alpha, i.e. d = theta - pi/2 + theta_o; and geometric towards d = 0
  for (double t : lobeBreaks(dp.alpha, kPi / 2)) {
    double d = t - kPi / 2 + tho;
    if (d > 0 && d < tho) br.push_back(d);
  }
  for (double d = tho / 2; d > tho * 1e-6; d /= 4) br.push_back(d);
  return adaptPieces(f, 0.0, tho, br, 1e-300, 18, 1e-11);
}

namespace {
// cos(theta) Lambda_exact on a dense grid in z = c/(c + alpha s) (Beckmann's b/(1+b)), from
// cLambdaQuad, 8-point Lagrange in between: the albedo integrals need it at millions of points.
// As cLambda/(alpha s), which is smooth in z on [0, 1] for every alpha.
struct ExactLambdaCache {
  int ndf = -1;
  double alpha = -1;
  std::vector<double> v;  // cLambda/(alpha s) at z_k = k/(N - 1)
  static constexpr int N = 1025;
};

// One table per (NDF, alpha) for the whole process, shared by every thread: at alpha ~ 1e-5 one
// takes 32 s to build on one thread, and a test that checks texels on two threads would build it twice a row.
const ExactLambdaCache& exactLambdaTable(int ndf, const brdf64::BrdfParams& dp) {
  thread_local std::shared_ptr<const ExactLambdaCache> last;
  if (last && last->ndf == ndf && last->alpha == dp.alpha) return *last;
  static std::mutex mutex;
  static std::vector<std::shared_ptr<const ExactLambdaCache>> built;
  std::lock_guard<std::mutex> lock(mutex);  // held while building: a second thread waits for it
  for (const auto& t : built)
    if (t->ndf == ndf && t->alpha == dp.alpha) return *(last = t);
  const int N = ExactLambdaCache::N;
  auto t = std::make_shared<ExactLambdaCache>();
  t->ndf = ndf;
  t->alpha = dp.alpha;
  t->v.assign(N, 0.0);
  // the entries on every hardware thread (each entry is independent): the caller's other threads
  // wait on the mutex for this table anyway
  auto fill = [&](int first, int stride) {
    for (int k = first; k + 1 < N; k += stride) {
      double z = double(k) / (N - 1);
      // c/(alpha s) = b = z/(1 - z): c = b alpha/sqrt(1 + b^2 alpha^2)
      double b = z / (1 - z), tb = b * dp.alpha, cc = tb / std::sqrt(1 + tb * tb), ss = 1 / std::sqrt(1 + tb * tb);
      t->v[k] = cLambdaQuad(ndf, dp, cc) / (dp.alpha * ss);
    }
  };
  const int threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(fill, i, threads);
  fill(0, threads);
  for (auto& th : pool) th.join();
  if (built.size() >= 256) built.erase(built.begin());  // 8 KiB each
  built.push_back(t);
  return *(last = t);
}

}  // namespace

double cLambdaTabled(int ndf, const brdf64::BrdfParams& dp, double c) {
  double s = std::sqrt((1 - c) * (1 + c));
  if (s <= 0 || dp.alpha <= 0) return 0;
  const ExactLambdaCache& cache = exactLambdaTable(ndf, dp);
  const int N = ExactLambdaCache::N;
  double z = c / (c + dp.alpha * s), u = z * (N - 1);
  int i0 = std::clamp(int(std::floor(u)) - 3, 0, N - 8);
  double sum = 0;
  for (int i = 0; i < 8; ++i) {
    double w = 1;
    for (int j = 0; j < 8; ++j)
      if (j != i) w *= (u - (i0 + j)) / double(i - j);
    sum += w * cache.v[i0 + i];
  }
  return sum * dp.alpha * s;
}

}  // namespace brdfbake::reference::detail
