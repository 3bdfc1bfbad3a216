// A glTF 2.0 file as a scene: its materials, and the tables glTF's reference shading needs for
// them. glTF's metallic-roughness model is GGX with the height-correlated Smith visibility and
// Schlick's Fresnel (glTF 2.0 specification, appendix B), lit by image-based lighting and punctual
// lights (KHR_lights_punctual) in the reference viewer.
//
// Materials only: the JSON (a .gltf, or a .glb's first chunk; nothing past it is read) is parsed
// with nlohmann/json (Debian nlohmann-json3-dev) and only `asset` and `materials` are looked at.
// Buffers and images are never opened, so no URI in the file reaches outside it. Every material
// field brdfbake reads or that glTF bounds is checked for its type and range (glTF 2.0 schema and
// the KHR_materials_* extensions), exit 65 naming its JSON path.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "common/input_file.h"
#include "scene/scene.h"

namespace brdfbake {

namespace {

using Json = nlohmann::json;

[[noreturn]] void bad(const std::string& path, const std::string& where, const std::string& what) {
  throw Error(kExitDataErr, path + ": " + where + ": " + what);
}

std::string shown(const Json& v) {
  std::string t = v.dump();
  return t.size() > 40 ? t.substr(0, 37) + "..." : t;
}

// The number at `key` of `obj` (absent: fallback), within [lo, hi].
double number(const std::string& path, const Json& obj, const std::string& where, const char* key, double fallback,
              double lo, double hi) {
  auto it = obj.find(key);
  if (it == obj.end()) return fallback;
  const std::string at = where + "." + key;
  if (!it->is_number()) bad(path, at, "expected a number in [" + fmtG(lo) + ", " + fmtG(hi) + "], got " + shown(*it));
  const double v = it->get<double>();
  if (!(v >= lo && v <= hi)) bad(path, at, "expected a number in [" + fmtG(lo) + ", " + fmtG(hi) + "], got " + fmtG(v));
  return v;
}

// An array of `n` numbers in [lo, hi] at `key`, if present.
void numbers(const std::string& path, const Json& obj, const std::string& where, const char* key, size_t n, double lo,
             double hi) {
  auto it = obj.find(key);
  if (it == obj.end()) return;
  const std::string at = where + "." + key;
  const std::string want = "an array of " + std::to_string(n) + " numbers in [" + fmtG(lo) + ", " + fmtG(hi) + "]";
  if (!it->is_array() || it->size() != n) bad(path, at, "expected " + want + ", got " + shown(*it));
  for (size_t i = 0; i < n; ++i) {
    const Json& x = (*it)[i];
    if (!x.is_number() || !(x.get<double>() >= lo && x.get<double>() <= hi))
      bad(path, at + "[" + std::to_string(i) + "]", "expected " + want + ", got " + shown(x));
  }
}

const Json& object(const std::string& path, const Json& obj, const std::string& where, const char* key) {
  static const Json empty = Json::object();
  auto it = obj.find(key);
  if (it == obj.end()) return empty;
  if (!it->is_object()) bad(path, where + "." + key, "expected an object, got " + shown(*it));
  return *it;
}

// The JSON text of a .gltf, or of a .glb's JSON chunk (the binary chunk after it is not read).
std::string gltfJson(const std::string& path, bool glb) {
  if (!glb) return readInputFile(path, "scene", kCapGltfJson);
  const uint64_t size = checkInputFile(path, "scene", kCapGlb);
  std::string head = readInputPrefix(path, "scene", 20);
  auto u32 = [&](size_t at) {
    return uint32_t(uint8_t(head[at])) | uint32_t(uint8_t(head[at + 1])) << 8 | uint32_t(uint8_t(head[at + 2])) << 16 |
           uint32_t(uint8_t(head[at + 3])) << 24;
  };
  if (head.size() < 20 || head.compare(0, 4, "glTF") != 0)
    bad(path, "header", "not a binary glTF (.glb): it does not start with \"glTF\"");
  if (u32(4) != 2) bad(path, "header", "glTF binary version " + std::to_string(u32(4)) + "; brdfbake reads version 2");
  const uint64_t len = u32(12);
  if (head.compare(16, 4, "JSON") != 0) bad(path, "chunk 0", "the first chunk is not JSON");
  if (len > kCapGltfJson || 20 + len > size)
    bad(path, "chunk 0",
        "JSON chunk of " + std::to_string(len) + " bytes does not fit the file or the " +
            std::to_string(kCapGltfJson >> 20) + " MiB cap");
  return readInputPrefix(path, "scene", 20 + len).substr(20);
}

// A glTF's materials nest 4 levels deep (materials[i].pbrMetallicRoughness.baseColorFactor); its
// extensions and extras a few more. Anything past kMaxJsonNesting is refused here, before the parser
// (recursive, as is building its error message and freeing the tree) sees the text: a 200 KB file
// nested 100,000 deep had crashed `plan`. Brackets inside strings do not count.
constexpr int kMaxJsonNesting = 64;
void checkJsonNesting(const std::string& text, const std::string& path) {
  int depth = 0;
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonNesting)
        bad(path, "byte " + std::to_string(i),
            "arrays and objects nest deeper than " + std::to_string(kMaxJsonNesting) +
                " levels; a glTF's materials need at most 8");
    } else if (c == ']' || c == '}') {
      depth = std::max(0, depth - 1);
    }
  }
}

}  // namespace

Scene readGltfScene(const std::string& path) {
  const bool glb = path.size() >= 4 && path.compare(path.size() - 4, 4, ".glb") == 0;
  Scene s = parseGltf(gltfJson(path, glb), path);
  size_t slash = path.find_last_of('/');
  s.baseDir = slash == std::string::npos ? "." : path.substr(0, slash == 0 ? 1 : slash);
  std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  s.name = base.substr(0, base.find_last_of('.'));
  return s;
}

Scene parseGltf(const std::string& text, const std::string& path) {
  checkJsonNesting(text, path);
  Json doc;
  try {
    doc = Json::parse(text);
  } catch (const Json::parse_error& e) {
    bad(path, "byte " + std::to_string(e.byte), std::string("not valid JSON: ") + e.what());
  } catch (const Json::exception& e) {
    // nlohmann reports a number beyond a double's range (1e999) as out_of_range, not parse_error
    bad(path, "$", std::string("not valid JSON: ") + e.what());
  }
  if (!doc.is_object()) bad(path, "$", "a glTF file is a JSON object");
  const Json& asset = object(path, doc, "$", "asset");
  auto version = asset.find("version");
  if (version == asset.end() || !version->is_string() || version->get<std::string>().rfind("2.", 0) != 0)
    bad(path, "asset.version", "expected \"2.x\" (a glTF 2.0 file)");
  auto mats = doc.find("materials");
  if (mats != doc.end() && !mats->is_array()) bad(path, "materials", "expected an array, got " + shown(*mats));
  Scene s;
  s.path = path;
  s.baseDir = ".";
  s.name = "gltf";
  // glTF's reference viewer: image-based lighting and punctual lights, no multiple-scattering term
  s.lighting = SceneLighting{};
  s.output.dir = "out";
  const size_t count = mats == doc.end() ? 0 : mats->size();
  for (size_t i = 0; i < count; ++i) {
    const Json& gm = (*mats)[i];
    const std::string at = "materials[" + std::to_string(i) + "]";
    if (!gm.is_object()) bad(path, at, "expected an object, got " + shown(gm));
    SceneMaterial m;
    auto name = gm.find("name");
    if (name != gm.end() && !name->is_string()) bad(path, at + ".name", "expected a string, got " + shown(*name));
    m.name = name == gm.end() || name->get<std::string>().empty() ? "material_" + std::to_string(i)
                                                                  : name->get<std::string>();
    m.pos = SourcePos{path, 0, 0};
    m.ndf = NDF_GGX;
    m.gaf = GAF_SMITH_CORRELATED;
    const std::string pbrAt = at + ".pbrMetallicRoughness";
    const Json& pbr = object(path, gm, at, "pbrMetallicRoughness");
    const double r = number(path, pbr, pbrAt, "roughnessFactor", 1.0, 0, 1);
    number(path, pbr, pbrAt, "metallicFactor", 1.0, 0, 1);
    numbers(path, pbr, pbrAt, "baseColorFactor", 4, 0, 1);
    numbers(path, gm, at, "emissiveFactor", 3, 0, 1);
    number(path, gm, at, "alphaCutoff", 0.5, 0, 1e300);
    m.roughnessLo = 0;  // a roughness texture can reach any value up to the factor
    m.roughnessHi = r;
    m.diffuse = DIFFUSE_LAMBERT;
    m.fresnel.model = FRESNEL_SCHLICK;
    const std::string extAt = at + ".extensions";
    const Json& exts = object(path, gm, at, "extensions");
    double ior = 1.5;
    if (exts.contains("KHR_materials_ior")) {
      const Json& e = object(path, exts, extAt, "KHR_materials_ior");
      ior = number(path, e, extAt + ".KHR_materials_ior", "ior", 1.5, 0, 1e300);
      if (ior != 0 && ior < 1)
        bad(path, extAt + ".KHR_materials_ior.ior", "expected 0 or a number >= 1, got " + fmtG(ior));
      m.notes.push_back("KHR_materials_ior: ior " + fmtG(ior) + " -> Schlick F0 ((ior-1)/(ior+1))^2");
    }
    double f0 = ior > 0 ? std::pow((ior - 1) / (ior + 1), 2) : 0.04;
    if (exts.contains("KHR_materials_specular")) {
      const Json& e = object(path, exts, extAt, "KHR_materials_specular");
      const double k = number(path, e, extAt + ".KHR_materials_specular", "specularFactor", 1.0, 0, 1);
      numbers(path, e, extAt + ".KHR_materials_specular", "specularColorFactor", 3, 0, 1e300);
      f0 = std::min(1.0, f0 * k);
      m.notes.push_back("KHR_materials_specular: F0 scaled by " + fmtG(k) + " (Schlick, the same split-sum table)");
    }
    m.fresnel.f0 = {std::clamp(f0, 0.0, 1.0)};
    validateFresnel(m.fresnel);
    if (exts.contains("KHR_materials_clearcoat")) {
      const Json& e = object(path, exts, extAt, "KHR_materials_clearcoat");
      number(path, e, extAt + ".KHR_materials_clearcoat", "clearcoatFactor", 0, 0, 1);
      number(path, e, extAt + ".KHR_materials_clearcoat", "clearcoatRoughnessFactor", 0, 0, 1);
      m.notes.push_back("KHR_materials_clearcoat: a second GGX lobe, served by the same split-sum table");
    }
    if (exts.contains("KHR_materials_transmission")) {
      const Json& e = object(path, exts, extAt, "KHR_materials_transmission");
      number(path, e, extAt + ".KHR_materials_transmission", "transmissionFactor", 0, 0, 1);
      m.transmission = true;
    }
    if (exts.contains("KHR_materials_sheen")) {
      const Json& e = object(path, exts, extAt, "KHR_materials_sheen");
      number(path, e, extAt + ".KHR_materials_sheen", "sheenRoughnessFactor", 0, 0, 1);
      numbers(path, e, extAt + ".KHR_materials_sheen", "sheenColorFactor", 3, 0, 1);
      m.sheen = true;
    }
    for (const auto& [extName, v] : exts.items()) {
      (void)v;
      if (extName != "KHR_materials_ior" && extName != "KHR_materials_specular" &&
          extName != "KHR_materials_clearcoat" && extName != "KHR_materials_transmission" &&
          extName != "KHR_materials_sheen")
        m.notes.push_back(extName + ": no table of its own (shaded analytically or not a BRDF extension)");
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
