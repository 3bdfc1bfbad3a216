// Shared by the MERL albedo rules (merl_albedo.cpp, merl_albedo_avg.cpp): Gauss-Legendre nodes on
// [0, 1] and a small worker pool with progress lines.
#pragma once
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace brdfbake::merl_detail {

struct Gauss {
  std::vector<double> x, w;
};
// n nodes (n <= kMerlLadder.back()), computed once.
const Gauss& gaussCached(int n);

// Runs job(k) for k in [0, n) on `threads` workers; progress lines on stderr after two seconds.
template <class Job>
void parallelFor(int n, int threads, const std::string& what, const Job& job) {
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
      if (!what.empty() && t > 2) {
        std::lock_guard<std::mutex> lock(printLock);
        if (t - lastPrint >= 1 || d == n) {
          std::fprintf(stderr, "brdfbake: %s: %d/%d (%.0f s)\n", what.c_str(), d, n, t);
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

}  // namespace brdfbake::merl_detail
