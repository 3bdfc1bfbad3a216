// Request -> plan: the list of tables to bake, each with its size, grid, file name and the header
// attributes that do not depend on the baked values. Validation of combinations happens here, so
// nothing is computed or written for a request that cannot be honoured.
#pragma once
#include <string>
#include <vector>

#include "cli/args.h"
#include "common/models.h"

namespace brdfbake {

struct TableJob {
  TableKind kind;
  int ndf;
  int gaf;           // GAF_NONE for kp, which depends on the NDF only
  int width, height; // x = mu (2D tables) or r (1D), y = r (2D) or 1
  bool nodeGrid;
  bool half;
  std::string path;  // output file
  FresnelChoice fresnel;  // albedo, albedo-avg: the model in B (one: F = 1); splitsum: schlick or f82-tint
  int diffuse = -1;       // albedo: a diffuse model's albedo (ndf, gaf unused); splitsum: burley in B
};

struct Plan {
  std::string outDir;
  std::string device;
  std::vector<TableJob> jobs;
  std::string merl;  // a measured material's MERL file, the jobs' material (bake/merl_bake.h); "" = none
};

// Throws Error(kExitUsage) for combinations that have no finite table (gaf none on a node grid,
// whose mu = 0 column is infinite).
Plan makePlan(const BakeRequest& req);

std::string fileName(const TableJob& job);

}  // namespace brdfbake
