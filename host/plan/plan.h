// Request -> plan: the list of tables to bake, each a job of the family that bakes it
// (tables/family.h), with its size, grid and file name. Validation of combinations happens here
// (each family checks its own), so nothing is computed or written for a request that cannot be
// honoured.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "brdfbake/request.h"
#include "tables/job.h"

namespace brdfbake {

struct Plan {
  std::string outDir;
  std::string device;
  bool noWait = false;                     // another writer holds outDir: exit 75 instead of waiting
  std::shared_ptr<BakeObserver> observer;  // the request's (brdfbake/observer.h), or none
  std::vector<Job> jobs;                   // in the registry's family order
  // Extra string attributes of the file at a path (scenes: brdf.hash, brdf.scene).
  std::map<std::string, std::map<std::string, std::string>> extraStrings;
  std::string shardHint;  // what to do when the plan has too many files (scenes: --shard)
};

// Throws Error(kExitUsage) for combinations that have no finite table (gaf none on a node grid,
// whose mu = 0 column is infinite).
Plan makePlan(const BakeRequest& req);

}  // namespace brdfbake
