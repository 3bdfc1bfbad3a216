// The microfacet family: the split sum (A, B, and its Fresnel or diffuse third channel), the
// directional albedo E(mu, r) (F = 1, a Fresnel model, or a diffuse model's albedo), its average
// E_avg(r) and the NDF normalisation k_p(r). One OpenCL program per NDF/GAF pair.
#pragma once
#include <vector>

#include "cl/runner.h"
#include "formats/table_image.h"
#include "tables/job.h"

namespace brdfbake {

// Computes one planned table (kernels + header attributes) without writing it. texelBounds, when
// given, receives each texel's claimed bound (relative to max(1, |value|), every stored channel,
// what the file's brdf.error is the largest of), in the table's texel order.
TableImage computeTable(KernelRunner& runner, const TableJob& job, double* seconds,
                        std::vector<double>* texelBounds = nullptr);

// The convergence ladders of splitsum, albedo, albedo-avg and kp (tables/microfacet/microfacet_ladder.cpp).
struct Ladder;
struct LadderBudgets;
struct BakeRequest;
class BakeContext;
Ladder microfacetLadder(BakeContext& ctx, const BakeRequest& req, TableKind kind, const LadderBudgets& budgets);

// Its stress points (tables/microfacet/microfacet_stress.cpp).
struct StressPoint;
void microfacetStress(KernelRunner& kr, std::vector<StressPoint>& out);

// The table's file name: <table>_<ndf>_<gaf>[_<fresnel>|_<diffuse>].exr, kp_<ndf>.exr, albedo_<diffuse>.exr.
std::string microfacetFileName(const TableJob& job);

}  // namespace brdfbake
