// `brdfbake plan SCENE` and `brdfbake bake SCENE`: print the plan, bake what changed.
#pragma once
#include <memory>
#include <string>

#include "brdfbake/observer.h"

namespace brdfbake {

struct SceneOptions {
  std::string file;    // .toml manifest or .gltf/.glb
  std::string outDir;  // -o: overrides the scene's output.dir
  int shard = 1, shards = 1;
  bool force = false;  // rebake every table
  bool prune = false;  // remove tables of this scene that it no longer needs
  bool list = false;   // plan: only the output paths, absolute, one per line
  std::string stamp;   // bake: written (atomically) after a successful bake, listing the outputs
  std::string device, cacheDir;
  bool noWait = false;  // bake: exit 75 instead of waiting when another bake writes into the directory
  std::shared_ptr<BakeObserver> observer;  // bake: stages and progress (brdfbake/observer.h), or none
};

// Prints the plan: each table, why, its size and estimated cost, whether it is new, changed or up to
// date; what was left out and why; tables of this scene that are no longer needed. Exit 0.
int runScenePlan(const SceneOptions& o);
// Bakes the tables that are new or changed (all with --force), says which are up to date, lists
// (and with --prune removes) the stale ones. Writes nothing and says so when nothing changed.
int runSceneBake(const SceneOptions& o);

}  // namespace brdfbake
