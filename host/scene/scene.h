// A scene: the materials a renderer uses and how it lights them, read from a TOML manifest
// (manifest.cpp) or a glTF 2.0 file (gltf_scene.cpp). scene_plan.h turns it into the smallest set
// of tables that serves it.
#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/material.h"
#include "common/models.h"

namespace brdfbake {

// Where a value came from, for messages: "scene.toml:12:5".
struct SourcePos {
  std::string file;
  int line = 0, column = 0;
  std::string str() const;
};

// One [output.size] entry as the manifest writes it. The manifest reader takes any key; the planner
// checks it against the kinds' descriptions (tables/kind_info.h: which kinds scenes plan, which take
// [X, Y, Z]) and the value against the kind's range, with these positions in its messages.
struct SceneSize {
  std::string kind;  // the key
  SourcePos keyPos, valuePos;
  bool array = false;                          // [X, Y, Z] (or an array of another length)
  std::vector<SourcePos> itemPos;              // each array item's position
  std::vector<std::optional<int64_t>> values;  // the value, or each item; empty optional: not an integer
};

struct SceneMaterial {
  std::string name;
  SourcePos pos;
  int ndf = 0, gaf = 10;                    // ggx + smith-correlated
  FresnelChoice fresnel;                    // validated; model one = F = 1 (a manifest without fresnel: schlick 0.04)
  int diffuse = -1;                         // DIFFUSE_* or -1
  std::optional<double> sigma;              // oren-nayar's sigma
  std::vector<double> rho;                  // diffuse albedo (brdf3d)
  double roughnessLo = 0, roughnessHi = 1;  // the roughness (range) the material uses
  std::string coupling = "sum";             // "sum" or "albedo-scaling" (the diffuse lobe scaled by 1 - E_F)
  bool brdf3d = false;                      // a 3D table of this material (one roughness)
  bool transmission = false;                // glTF KHR_materials_transmission (not served yet: reported)
  bool sheen = false;                       // glTF KHR_materials_sheen (not served yet: reported)
  std::vector<std::string> notes;           // what the reader mapped and how (glTF extensions)
};

struct SceneLighting {
  bool ibl = true;            // image-based lighting: the split-sum (DFG) tables
  bool analytic = true;       // analytic lights: k_p where an NDF has no closed-form normalisation
  bool multiscatter = false;  // Kulla-Conty compensation: E(mu, r) and E_avg(r) with F = 1
};

struct SceneOutput {
  std::string dir = "out";  // relative to the scene file's directory
  bool half = false;
  bool nodeGrid = false;
  std::vector<SceneSize> sizes;  // [output.size], as written; missing: the kind's default
};

struct Scene {
  std::string name;     // the file's stem, or [scene] name
  std::string path;     // the file read
  std::string baseDir;  // directory the output dir is relative to
  SceneLighting lighting;
  SceneOutput output;
  std::vector<SceneMaterial> materials;
};

// Reads a scene: a .toml manifest or a .gltf/.glb file (by extension). Throws Error(kExitNoInput)
// when the file is missing or unreadable, Error(kExitDataErr) with "file:line:column: what was
// expected" for anything malformed.
Scene readScene(const std::string& path);
Scene readManifest(const std::string& path);
Scene readGltfScene(const std::string& path);
// Parses a glTF file's JSON (for the fuzzer and tests); `name` stands for the file in messages.
Scene parseGltf(const std::string& json, const std::string& name);
// Parses manifest text (for the fuzzer and tests); `name` stands for the file in messages.
Scene parseManifest(const std::string& text, const std::string& name);

}  // namespace brdfbake
