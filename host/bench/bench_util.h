// Helpers the benchmark's modes share (bench_main.cpp, materials_bench.cpp): relative error,
// the sampled texels, two-thread loops for the reference, best-of timing.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <thread>
#include <utility>
#include <vector>

namespace brdfbake::bench {

inline double rel(double got, double want) { return std::fabs(got - want) / std::max(1.0, std::fabs(want)); }

// The texels whose errors are measured: every stride-th per axis, plus the table's edges.
inline std::vector<std::pair<int, int>> sampledTexels(int n, int stride) {
  std::vector<std::pair<int, int>> texels;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if ((i % stride == 0 && j % stride == 0) || i == 0 || j == 0 || i == n - 1 || j == n - 1)
        texels.push_back({i, j});
  return texels;
}

// f(k) for every k in [0, count), on 2 threads (the reference is the slow part).
template <class F>
void onTwoThreads(size_t count, F f) {
  std::thread th([&] {
    for (size_t k = 1; k < count; k += 2) f(k);
  });
  for (size_t k = 0; k < count; k += 2) f(k);
  th.join();
}

inline double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Best of `repeat` of f().
template <class F>
double best(int repeat, F f) {
  double b = 1e30;
  for (int r = 0; r < repeat; ++r) {
    auto t0 = std::chrono::steady_clock::now();
    f();
    b = std::min(b, seconds(t0));
  }
  return b;
}

}  // namespace brdfbake::bench
