// Shared by the MERL albedo rules (merl_albedo.cpp, merl_albedo_avg.cpp): Gauss-Legendre nodes on
// [0, 1], a small worker pool with progress lines, and the ladder both climb.
#pragma once
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "materials/merl_albedo.h"

namespace brdfbake::merl_detail {

struct Gauss {
  std::vector<double> x, w;
};
// n nodes (n <= 31), computed once.
const Gauss& gaussCached(int n);

// Runs job(k) for k in [0, n) on `threads` workers, reporting (done, n, seconds) to `progress`
// (when given) at most every 0.2 s and at the end: the caller's observer decides where it shows
// (a terminal's progress line, or nothing in a log).
template <class Job>
void parallelFor(int n, int threads, const ProgressFn& progress, const Job& job) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::max(1, std::min(threads, n));
  std::atomic<int> next{0}, done{0};
  std::mutex printLock;
  auto t0 = std::chrono::steady_clock::now();
  double lastPrint = 0;
  auto work = [&] {
    for (int k; (k = next++) < n;) {
      job(k);
      int d = ++done;
      double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (progress) {
        std::lock_guard<std::mutex> lock(printLock);
        if (t - lastPrint >= 0.2 || d == n) {
          progress(d, n, t);
          lastPrint = t;
        }
      }
    }
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
}

// Climbs `ladder`: rule(n, &unsupported) is the n-node rule's value per channel; R_n's estimate is
// max(|R_n - R_prev|, |R_n - R_prev2|), and the climb stops at the first rule from the third on
// whose estimate is within target(value) in every channel (else at the last).
template <size_t N, class Rule, class Target>
AlbedoEstimate climbLadder(const std::array<int, N>& ladder, const Target& target, const Rule& rule) {
  AlbedoEstimate r;
  std::array<double, 3> prev2 = rule(ladder[0], nullptr), prev = rule(ladder[1], nullptr);
  for (size_t k = 2; k < N; ++k) {
    r.e = rule(ladder[k], &r.unsupported);
    r.nodes = ladder[k];
    bool met = true;
    const double t = target(r.e);
    for (int c = 0; c < 3; ++c) {
      r.err[c] = std::max(std::fabs(r.e[c] - prev[c]), std::fabs(r.e[c] - prev2[c]));
      met = met && r.err[c] <= t;
    }
    if (met) break;
    prev2 = prev;
    prev = r.e;
  }
  return r;
}

}  // namespace brdfbake::merl_detail
