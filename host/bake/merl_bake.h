// Baking the 2D-table kinds (albedo, albedo-avg, splitsum) of a measured material, --brdf
// merl:FILE.binary: planned and run on the host (no OpenCL), written through the same
// all-or-nothing output set as every other table.
#pragma once
#include <string>
#include <vector>

#include "bake/bake.h"
#include "cli/args.h"
#include "plan/plan.h"

namespace brdfbake {

// "dir/gold-metallic-paint.binary" -> "gold-metallic-paint" (brdf.material = "merl:" + that).
std::string merlMaterialName(const std::string& path);

// The jobs of a request with req.merl set (files <table>_merl-<name>.exr): albedo and splitsum width = --size (default 32 and 128)
// over mu, height 1; albedo-avg 1 x 1. Throws Error(kExitUsage) for any other table.
Plan makeMerlPlan(const BakeRequest& req);

// True when the plan is a measured material's (plan.merl set by makeMerlPlan).
bool isMerlPlan(const Plan& plan);

// Checks -o, reads the MERL file (Error 66 missing/unreadable, 65 wrong size/header/values: nothing
// is written), computes every table, then commits them together (bake/output_set.h).
std::vector<TableReport> runMerlPlan(const Plan& plan);

}  // namespace brdfbake
