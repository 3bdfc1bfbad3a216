// brdfbake-bench --volume: the 3D tables. (1) The MERL-shaped table (ggx + smith-correlated,
// r = 0.5, Schlick F0 = 0.04; rusinkiewicz, sqrt theta_h index, 90 x 90 x 180 at the bins' lower
// edges) on the OpenCL device against a plain single-threaded C++ evaluation of the same BRDF
// (host/common/brdf3d_grid.cpp hostBrdf: GLM directions, double), in the same run: time, texels per
// second, and their largest difference. (2) A large table (--volume-size N, default 256) baked and
// written as the bake does it, slab by slab: the process's peak resident memory against the size
// the whole table would take.
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "tables/volume.h"
#include "tables/brdf3d/brdf3d.h"
#include "bench/bench_util.h"
#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "tables/job.h"

namespace brdfbake {

using bench::best;
using bench::seconds;

namespace {
double peakRssMB() {
  struct rusage ru {};
  ::getrusage(RUSAGE_SELF, &ru);
  return ru.ru_maxrss / 1024.0;  // kilobytes on Linux
}
}  // namespace

int volumeBench(KernelRunner& runner, int repeat, int bigSize);
int volumeBench(KernelRunner& runner, int repeat, int bigSize) {
  Brdf3dSpec s;
  s.ndf = NDF_GGX;
  s.gaf = GAF_SMITH_CORRELATED;
  s.roughness = 0.5;
  s.fresnel.model = FRESNEL_SCHLICK;
  s.fresnel.f0 = {0.04};
  validateFresnel(s.fresnel);
  s.param = Brdf3dParam::Rusinkiewicz;
  s.thetaHSqrt = true;
  s.grid = Brdf3dGrid::CellStart;
  s.nx = 90;
  s.ny = 90;
  s.nz = 180;
  const double texels = 90.0 * 90 * 180;
  brdf3dSlab(runner, s, 0, 1);  // builds the program: not part of the timing
  std::vector<std::vector<float>> dev;
  double td = best(repeat, [&] { dev = brdf3dSlab(runner, s, 0, s.nz); });
  std::vector<double> host(static_cast<size_t>(texels));
  auto t0 = std::chrono::steady_clock::now();
  for (int z = 0; z < s.nz; ++z)
    for (int y = 0; y < s.ny; ++y)
      for (int x = 0; x < s.nx; ++x)
        host[(static_cast<size_t>(z) * s.ny + y) * s.nx + x] = hostBrdf(s, texelDirections(s, x, y, z), 0);
  double th = seconds(t0);
  double worst = 0;
  for (size_t t = 0; t < host.size(); ++t)
    worst = std::max(worst, std::fabs(dev[0][t] - host[t]) / std::max(1.0, std::fabs(host[t])));
  std::printf(
      "3D table, MERL layout (rusinkiewicz, sqrt theta_h, 90x90x180 = %.0f texels), ggx + smith-correlated, "
      "r = 0.5, Schlick F0 = 0.04\n",
      texels);
  std::printf("%-40s %10s %14s\n", "method", "seconds", "texels/s");
  std::printf("%-40s %10.4f %14.3e\n", "brdfbake kernel (OpenCL, best of repeat)", td, texels / td);
  std::printf("%-40s %10.4f %14.3e\n", "plain C++ (GLM + double, 1 thread)", th, texels / th);
  std::printf("speed ratio kernel/C++: %.1f; largest difference relative to max(1, |f|): %.2e\n", th / td, worst);

  // The large table, as the bake writes it (output set, slab by slab), into a temporary directory.
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / ("brdfbake_volume_bench_" + std::to_string(::getpid()));
  VolumeJob big;
  big.spec = s;
  big.spec.fresnel = FresnelChoice{};
  big.spec.param = Brdf3dParam::Angles;
  big.spec.thetaHSqrt = false;
  big.spec.grid = Brdf3dGrid::TexelCenter;
  big.spec.nx = big.spec.ny = big.spec.nz = bigSize;
  std::tie(big.cols, big.rows) = atlasGrid(bigSize);
  big.path = (dir / volumeFileName(big)).string();
  double before = peakRssMB();
  double kernelSeconds = 0;
  uint64_t slab = 0;
  t0 = std::chrono::steady_clock::now();
  TableImage header = volumeHeader(big);
  OutputFile f = volumeOutput(runner, big, header, &kernelSeconds, &slab);
  commitOutputs(dir.string(), {f});
  double total = seconds(t0);
  double after = peakRssMB();
  uintmax_t bytes = fs::file_size(big.path);
  fs::remove_all(dir);
  double whole = 3.0 * bigSize * bigSize * static_cast<double>(bigSize) * 4 / 1e6;
  std::printf("\n%d^3 angles table (ggx + smith-correlated, FLOAT RGB), baked and written slab by slab:\n", bigSize);
  std::printf("  %.1f s in all (%.1f s kernel, the rest EXR compression and writing), file %.1f MB\n", total,
              kernelSeconds, bytes / 1e6);
  std::printf(
      "  largest slab %.1f MB; peak resident memory %.1f MB (%.1f MB before the bake); the whole table "
      "would be %.1f MB\n",
      slab / 1e6, after, before, whole);
  return 0;
}

}  // namespace brdfbake
