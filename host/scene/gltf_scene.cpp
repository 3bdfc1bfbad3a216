// A glTF 2.0 file as a scene (tinygltf, Debian libtinygltf-dev): its materials, and the tables
// glTF's reference shading needs for them. glTF's metallic-roughness model is GGX with the
// height-correlated Smith visibility and Schlick's Fresnel (glTF 2.0 specification, appendix B), lit
// by image-based lighting and punctual lights (KHR_lights_punctual) in the reference viewer.
#include <tiny_gltf.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>

#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/input_file.h"
#include "common/format.h"
#include "scene/scene.h"

namespace brdfbake {

namespace {
// The number at `key` of an extension object, or `fallback`.
double extNumber(const tinygltf::Value& ext, const char* key, double fallback) {
  if (!ext.IsObject() || !ext.Has(key)) return fallback;
  const tinygltf::Value& v = ext.Get(key);
  return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}
}  // namespace

Scene readGltfScene(const std::string& path) {
  const bool glb = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
  checkInputFile(path, "scene", glb ? kCapGlb : kCapGltfJson);
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  // materials only: images are neither needed nor loaded
  loader.SetImageLoader([](tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
                           void*) { return true; },
                        nullptr);
  std::string err, warn;
  bool binary = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
  bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, path)
                   : loader.LoadASCIIFromFile(&model, &err, &warn, path);
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
    throw Error(kExitDataErr, path + ": not a glTF 2.0 file tinygltf can parse: " + (err.empty() ? "unknown error" : err));
  }
  Scene s;
  s.path = path;
  size_t slash = path.find_last_of('/');
  s.baseDir = slash == std::string::npos ? "." : path.substr(0, slash == 0 ? 1 : slash);
  std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  s.name = base.substr(0, base.find_last_of('.'));
  // glTF's reference viewer: image-based lighting and punctual lights, no multiple-scattering term
  s.lighting = SceneLighting{};
  s.output.dir = "out";
  for (size_t i = 0; i < model.materials.size(); ++i) {
    const tinygltf::Material& gm = model.materials[i];
    SceneMaterial m;
    m.name = gm.name.empty() ? "material_" + std::to_string(i) : gm.name;
    m.pos = SourcePos{path, 0, 0};
    m.ndf = NDF_GGX;
    m.gaf = GAF_SMITH_CORRELATED;
    double r = gm.pbrMetallicRoughness.roughnessFactor;
    m.roughnessLo = 0;  // a roughness texture can reach any value up to the factor
    m.roughnessHi = std::clamp(r, 0.0, 1.0);
    m.diffuse = DIFFUSE_LAMBERT;
    m.fresnel.model = FRESNEL_SCHLICK;
    double ior = 1.5;
    auto ext = [&](const char* name) -> const tinygltf::Value* {
      auto it = gm.extensions.find(name);
      return it == gm.extensions.end() ? nullptr : &it->second;
    };
    if (const tinygltf::Value* e = ext("KHR_materials_ior")) {
      ior = extNumber(*e, "ior", 1.5);
      m.notes.push_back("KHR_materials_ior: ior " + fmtG(ior) + " -> Schlick F0 ((ior-1)/(ior+1))^2");
    }
    double f0 = ior > 0 ? std::pow((ior - 1) / (ior + 1), 2) : 0.04;
    if (const tinygltf::Value* e = ext("KHR_materials_specular")) {
      double k = extNumber(*e, "specularFactor", 1.0);
      f0 = std::min(1.0, f0 * k);
      m.notes.push_back("KHR_materials_specular: F0 scaled by " + fmtG(k) + " (Schlick, the same split-sum table)");
    }
    m.fresnel.f0 = {std::clamp(f0, 0.0, 1.0)};
    validateFresnel(m.fresnel);
    if (ext("KHR_materials_clearcoat"))
      m.notes.push_back("KHR_materials_clearcoat: a second GGX lobe, served by the same split-sum table");
    if (ext("KHR_materials_transmission")) m.transmission = true;
    if (ext("KHR_materials_sheen")) m.sheen = true;
    for (const auto& [name, v] : gm.extensions) {
      (void)v;
      if (name != "KHR_materials_ior" && name != "KHR_materials_specular" && name != "KHR_materials_clearcoat" &&
          name != "KHR_materials_transmission" && name != "KHR_materials_sheen")
        m.notes.push_back(name + ": no table of its own (shaded analytically or not a BRDF extension)");
    }
    s.materials.push_back(m);
  }
  if (s.materials.empty()) {
    // meshes without a material use glTF's default: metallic-roughness, roughness 1, F0 0.04
    SceneMaterial m;
    m.name = "default";
    m.pos = SourcePos{path, 0, 0};
    m.ndf = NDF_GGX;
    m.gaf = GAF_SMITH_CORRELATED;
    m.diffuse = DIFFUSE_LAMBERT;
    m.fresnel.model = FRESNEL_SCHLICK;
    validateFresnel(m.fresnel);
    m.notes.push_back("the file has no materials: glTF's default material (metallic-roughness)");
    s.materials.push_back(m);
  }
  return s;
}

// A scene file by its extension: .gltf/.glb, else a TOML manifest.
Scene readScene(const std::string& path) {
  auto ends = [&](const std::string& e) {
    return path.size() >= e.size() && std::equal(e.rbegin(), e.rend(), path.rbegin(),
                                                 [](char a, char b) { return std::tolower(a) == std::tolower(b); });
  };
  if (ends(".gltf") || ends(".glb")) return readGltfScene(path);
  return readManifest(path);
}

}  // namespace brdfbake
