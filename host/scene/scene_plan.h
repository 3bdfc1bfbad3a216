// Scene -> the smallest set of tables that serves it: which table each material's lighting path
// needs, shared where the tables are the same, each with why, what it costs and a content hash of
// everything it depends on (incremental bakes); what was left out and why; shards of near-equal
// cost for bakes spread over machines.
#pragma once
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "plan/plan.h"
#include "scene/scene.h"

namespace brdfbake {

struct PlannedTable {
  size_t index = 0;  // plan.jobs[index]
  std::string path;
  std::string table;                 // table kind name
  std::string models;                // "ggx + smith-correlated, schlick"
  std::string size;                  // "128x128", "32x32x32"
  std::vector<std::string> reasons;  // "metal: image-based lighting (split-sum DFG)"
  double texels = 0;
  double cost = 0;   // estimated seconds on PoCL with 2 cores (a guide, for shards)
  std::string hash;  // content hash: kind, models, parameters, size, grid, precision, baker, kernels
};

struct ScenePlan {
  std::string scene;                 // the scene's name (recorded in each file as brdf.scene)
  Plan plan;                         // the tables, in plan order
  std::vector<PlannedTable> tables;  // one per output, in plan order
  std::vector<std::string> leftOut;  // table kinds not planned, and why
  std::vector<std::string> notes;    // materials that add nothing, mappings from glTF
  // planScene's indexes while it plans (empty after): a table by its content hash, by its path, and
  // each table's reasons, so that planning stays linear in the materials (100,000 glTF materials
  // had taken 40 s through a search of every table's reasons)
  std::unordered_map<std::string, size_t> byHash, byPath;
  std::vector<std::unordered_set<std::string>> reasonSets;
};

// outDir: "" = the scene's own (output.dir, relative to the scene file's directory).
// Throws Error(kExitDataErr) "file:line:column: material 'x': ..." when a material's lighting needs
// a table that cannot be built for it.
ScenePlan planScene(const Scene& scene, const std::string& outDir);

// Part `part` (1-based) of `parts`: tables dealt to the part with the least estimated cost so far,
// the most costly first (ties by path): deterministic, every table in exactly one part.
ScenePlan shardOf(const ScenePlan& plan, int part, int parts);

}  // namespace brdfbake
