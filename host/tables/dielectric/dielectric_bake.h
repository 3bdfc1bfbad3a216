// The rough dielectric's tables (--table dielectric, dielectric-avg; docs/MODELS.md "Rough
// dielectric"): E_R and E_T over (mu, r, eta) as an EXR atlas of eta slices, and their averages over
// mu over (r, eta). The eta axis is sampled uniformly in s = (eta - 1)/(eta + 1).
#pragma once
#include <vector>

#include "tables/dielectric_avg.h"
#include "formats/output_set.h"
#include "formats/exr/table_file.h"
#include "cl/runner.h"
#include "tables/job.h"

namespace brdfbake {

// The eta axis's coordinate and back: s = (eta - 1)/(eta + 1) = sign(eta - 1) sqrt(F0), in (-1, 1).
double dielectricCoord(double eta);
double dielectricEta(double s);
// eta of samples z0 .. z0 + n - 1 of the job's eta axis (texel centres or nodes in s).
std::vector<double> dielectricEtas(const DielectricJob& job, int z0, int n);

// The estimate each texel's quadrature aims at, per lobe (kernels/integrate/dielectric.h). With the
// rescaled estimates, 5e-8 makes the 32^3 table take 141 s, against 110 s for the bare |K15 - G7|
// at 2e-6 (brdfbake-bench --dielectric, docs/rough-glass.md), and with the storage rounding a
// float table claims about 2e-7.
constexpr float kDielectricTarget = 5e-8f;

// The rough dielectric's kernels (kernels/dielectric.cl) for the pair, to prepare: the 3D table's
// slabs (bake_dielectric) and the averages' points (bake_dielectric_points).
KernelNeed dielectricKernel(int ndf, int gaf);
KernelNeed dielectricPointsKernel(int ndf, int gaf);
// Planes E_R, E_T and the bound (relative to max(1, |value|)) over mu (nx) x r (ny) at each of the
// given etas, [(z * ny + y) * nx + x]; each texel's quadrature aims at `target` per lobe.
std::vector<std::vector<float>> dielectricSlab(KernelRunner& runner, int ndf, int gaf, int nx, int ny,
                                               const std::vector<double>& etas, bool nodeGrid, float target);
// E_R, E_T and their bounds (absolute, each lobe's) at points (mus[k], rs[k], etas[k]): the nodes
// of the averages' rule (tables/dielectric_avg.h), one plane each, in the program's precision
// (double where the device has fp64: unrounded, so that only the averages' stored entries round).
std::vector<std::vector<double>> dielectricPoints(KernelRunner& runner, int ndf, int gaf,
                                                  const std::vector<double>& mus, const std::vector<double>& rs,
                                                  const std::vector<double>& etas, float target);

// The averages' rule's E(mu) on the device (dielectricPoints) with its nodes to
// `target` per lobe: what the bake uses (kDielectricAvgNodeTarget), and tests and the bench tighter.
DielectricEval dielectricDeviceEval(KernelRunner& runner, int ndf, int gaf, float target);

// A computed dielectric table: the header (its brdf.error from the texels' bounds) and, for the
// 3D table, its planes E_R, E_T, E_R + E_T in slab order [(z * ny + y) * nx + x]; for the average,
// the image itself.
struct DielectricTable {
  TableImage image;                      // header (3D) or the whole 2D table (avg)
  std::vector<std::vector<float>> cube;  // 3D only
  double maxBound = 0;                   // the largest texel bound (quadrature), before allowances
  long long nodes = 0;                   // avg: E(mu) evaluations the averages' rule took
};

// Computes the table on the device (the 3D one slab by slab of `job.cols` slices) and checks that
// every value is finite (Error(kExitSoftware) otherwise: nothing is written). *seconds: kernel time.
DielectricTable computeDielectric(KernelRunner& runner, const DielectricJob& job, double* seconds);

// The OutputFile that writes a computed table (the 3D one through the atlas writer of tables/volume.h).
OutputFile dielectricOutput(const DielectricJob& job, const DielectricTable& table);

}  // namespace brdfbake
