#include "scene/scene_plan.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <map>
#include <numeric>

#include "common/hash.h"
#include "cl/embedded_kernels.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "tables/family.h"
#include "version.h"
#include "tables/registry.h"

namespace brdfbake {

namespace {

// The baker itself: its version and every kernel source it compiles (the models and estimators).
uint64_t bakerHash() {
  static const uint64_t h = [] {
    uint64_t x = fnv1a(std::string("brdfbake ") + BRDFBAKE_VERSION);
    for (const auto& f : kEmbeddedKernelSources) x = fnv1a(std::string(f.path) + '\n' + f.text, x);
    return x;
  }();
  return h;
}

// Adds the tables of `req` (one material's lighting path) to `sp`, sharing files with the same key.
void addTables(ScenePlan& sp, const BakeRequest& req, const SceneMaterial& m, const std::string& why) {
  Plan p;
  try {
    p = makePlan(req);
  } catch (const Error& e) {
    throw Error(kExitDataErr, m.pos.str() + ": material '" + m.name + "': " + why +
                                  " needs a table that cannot be built: " + e.what());
  }
  std::string reason = m.name + ": " + why;
  for (Job j : p.jobs) {
    const std::string key = j.family->key(j);
    const std::string hash = hex16(fnv1a(key, bakerHash()));
    // the same key: the same file; the same name for a different table: a suffix from the key
    if (auto same = sp.byHash.find(hash); same != sp.byHash.end()) {
      if (sp.reasonSets[same->second].insert(reason).second) sp.tables[same->second].reasons.push_back(reason);
      continue;
    }
    std::string path = j.path;
    if (sp.byPath.count(path)) {
      size_t dot = path.find_last_of('.');
      path = path.substr(0, dot) + "_" + hex16(fnv1a(key)).substr(0, 8) + path.substr(dot);
    }
    j.path = path;
    JobSummary sum = j.family->summary(j);
    PlannedTable t;
    t.path = path;
    t.hash = hash;
    t.reasons.push_back(reason);
    t.index = sp.plan.jobs.size();
    t.table = sum.table;
    t.models = sum.models;
    t.size = sum.size;
    t.texels = sum.texels;
    t.cost = sum.cost;
    sp.byHash[hash] = sp.tables.size();
    sp.byPath[path] = sp.tables.size();
    sp.reasonSets.push_back({reason});
    sp.plan.jobs.push_back(j);
    sp.tables.push_back(t);
  }
}

// [output.size] checked against the kinds' descriptions: each key a kind scenes plan, each value in
// the kind's range ([X, Y, Z] or N for a 3D texture). Messages name the manifest's line and column.
struct SceneSizes {
  std::map<TableKind, int> size;
  std::map<TableKind, std::array<int, 3>> volume;
};

SceneSizes checkSizes(const std::vector<SceneSize>& entries) {
  SceneSizes out;
  std::vector<std::string> valid;
  for (const KindInfo& k : allKinds())
    if (k.inScenes) valid.push_back(tableName(k.kind));
  for (const SceneSize& e : entries) {
    const KindInfo* k = findKind(e.kind);
    if (!k || !k->inScenes) {
      const std::string near = closestName(e.kind, valid);
      throw Error(kExitDataErr, e.keyPos.str() + ": unknown key '" + e.kind + "' in [output.size]" +
                                    (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                                    "; valid: " + joinNames(valid));
    }
    const std::string what = "output.size." + e.kind;
    auto integer = [&](const std::optional<int64_t>& v, const SourcePos& at, int lo, int hi) {
      const std::string range = what + " must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
      if (!v) throw Error(kExitDataErr, at.str() + ": " + range);
      if (*v < lo || *v > hi) throw Error(kExitDataErr, at.str() + ": " + range + ", got " + std::to_string(*v));
      return static_cast<int>(*v);
    };
    if (k->volume && e.array) {
      if (e.values.size() != 3) throw Error(kExitDataErr, e.valuePos.str() + ": " + what + " must be N or [X, Y, Z]");
      std::array<int, 3> n3{};
      for (int i = 0; i < 3; ++i) n3[i] = integer(e.values[i], e.itemPos[i], 1, kMaxVolumeSize);
      out.volume[k->kind] = n3;
    } else if (k->volume) {
      const int n1 = integer(e.values[0], e.valuePos, 1, kMaxVolumeSize);
      out.volume[k->kind] = {n1, n1, n1};
    } else {
      out.size[k->kind] = integer(e.array ? std::nullopt : e.values[0], e.valuePos, kMinSize, kMaxSize);
    }
  }
  return out;
}

}  // namespace

ScenePlan planScene(const Scene& scene, const std::string& outDir) {
  const SceneSizes sizes = checkSizes(scene.output.sizes);
  ScenePlan sp;
  sp.scene = scene.name;
  std::string dir = outDir;
  if (dir.empty())
    dir = scene.output.dir.front() == '/' || scene.baseDir == "." ? scene.output.dir
                                                                  : scene.baseDir + "/" + scene.output.dir;
  sp.plan.outDir = dir;
  const SceneLighting& L = scene.lighting;
  auto request = [&](const SceneMaterial& m, TableKind kind) {
    BakeRequest r;
    r.ndfs = {m.ndf};
    r.gafs = {m.gaf};
    r.tables = {kind};
    r.outDir = dir;
    if (scene.output.half) r.precision = Precision::Float16;
    r.nodeGrid = scene.output.nodeGrid;
    auto it = sizes.size.find(kind);
    if (it != sizes.size.end()) r.size = it->second;
    return r;
  };
  bool anyGaussianAnalytic = false, anyVolume = false, anyGlass = false;
  size_t before = 0;
  for (const SceneMaterial& m : scene.materials) {
    before = sp.tables.size();
    size_t reasonsBefore = 0;
    for (const auto& t : sp.tables) reasonsBefore += t.reasons.size();
    const int fm = m.fresnel.model;
    bool schlickLike = fm == FRESNEL_ONE || fm == FRESNEL_SCHLICK;
    if (L.ibl) {
      if (schlickLike || fm == FRESNEL_F82_TINT) {
        for (TableKind k : kindsServing(kUseIbl)) {
          BakeRequest r = request(m, k);
          FresnelChoice split;
          split.model = fm == FRESNEL_F82_TINT ? FRESNEL_F82_TINT : FRESNEL_SCHLICK;
          if (fm == FRESNEL_F82_TINT) split = m.fresnel;  // its split has a third channel, F0-free
          split.f0.clear();
          split.f82.clear();
          validateFresnel(split);
          r.fresnel = split;
          if (m.diffuse == DIFFUSE_BURLEY) r.diffuse = DIFFUSE_BURLEY;
          addTables(sp, r, m,
                    std::string("image-based lighting (split-sum DFG") +
                        (m.diffuse == DIFFUSE_BURLEY ? ", burley's diffuse albedo in B" : "") + ")");
        }
      } else {
        for (TableKind k : kindsServing(kUseIblFresnel)) {
          BakeRequest r = request(m, k);
          r.fresnel = m.fresnel;
          addTables(sp, r, m,
                    "image-based lighting (" + fresnelNames()[fm] +
                        " has no Schlick split: its DFG is the "
                        "Fresnel-weighted albedo)");
        }
      }
    }
    if (L.multiscatter)
      for (TableKind k : kindsServing(kUseMultiscatter))
        addTables(sp, request(m, k), m, "multiple-scattering compensation (Kulla-Conty E and E_avg, F = 1)");
    if (L.analytic && m.ndf == NDF_GAUSSIAN) {
      anyGaussianAnalytic = true;
      for (TableKind k : kindsServing(kUseNormalisation))
        addTables(sp, request(m, k), m, "analytic lights (the gaussian's D = p/k_p, k_p has no closed form)");
    }
    if (m.coupling == "albedo-scaling")
      for (TableKind k : kindsServing(kUseAlbedoScaling)) {
        BakeRequest r = request(m, k);
        if (!m.fresnel.isOne()) r.fresnel = m.fresnel;
        addTables(sp, r, m, "albedo-scaling coupling (the diffuse lobe scaled by 1 - E_F, with E_F,avg)");
      }
    if (m.brdf3d)
      for (TableKind k : kindsServing(kUseWholeMaterial)) {
        anyVolume = true;
        BakeRequest r = request(m, k);
        r.fresnel = m.fresnel;
        r.diffuse = m.diffuse;
        r.sigma = m.sigma;
        r.size.reset();
        r.volume.roughness = m.roughnessLo;
        r.volume.rho = m.rho;
        if (auto v = sizes.volume.find(k); v != sizes.volume.end()) r.volume.size = v->second;
        addTables(sp, r, m, "a 3D table of the whole material (brdf3d = true)");
      }
    size_t reasonsAfter = 0;
    for (const auto& t : sp.tables) reasonsAfter += t.reasons.size();
    if (sp.tables.size() == before && reasonsAfter > reasonsBefore)
      sp.notes.push_back("material '" + m.name +
                         "' adds no table: it shares every table it needs with earlier materials "
                         "(the tables do not depend on the parameters that differ)");
    else if (reasonsAfter == reasonsBefore)
      sp.notes.push_back("material '" + m.name + "' needs no table under this lighting");
    if (m.transmission) {
      // rough glass: E_R and E_T over (mu, r, eta), and their averages (Kulla-Conty for dielectrics)
      anyGlass = true;
      for (TableKind k : kindsServing(kUseTransmission))
        addTables(sp, request(m, k), m,
                  "transmission (rough glass: reflected and transmitted albedo" +
                      std::string(kindInfo(k).average ? ", their averages)" : ")"));
    }
    if (m.sheen) {
      // KHR_materials_sheen: the Charlie lobe's albedo (its albedo-scaling of the layers below, with
      // the Charlie visibility) and, under image-based lighting, its DFG-style term (Neubelt's
      // visibility, as Filament's cloth and glTF's reference viewer use)
      SceneMaterial sheen = m;
      sheen.ndf = NDF_CHARLIE;
      sheen.gaf = GAF_CHARLIE_SMITH;
      for (TableKind k : kindsServing(kUseSheen))
        addTables(sp, request(sheen, k), m, "KHR_materials_sheen (sheen albedo scaling: E of charlie + charlie-smith)");
      if (L.ibl) {
        sheen.gaf = GAF_NEUBELT;
        for (TableKind k : kindsServing(kUseSheenIbl))
          addTables(sp, request(sheen, k), m, "KHR_materials_sheen under image-based lighting (charlie + neubelt)");
      }
    }
    for (const auto& n : m.notes) sp.notes.push_back("material '" + m.name + "': " + n);
  }
  // what was left out, each line led by the kinds that serve the use
  auto serving = [](unsigned use, const std::string& last) { return kindNames(kindsServing(use), last); };
  auto namesOf = [](const std::vector<TableKind>& kinds) {
    std::vector<std::string> v;
    for (TableKind k : kinds) v.push_back(tableName(k));
    return v;
  };
  if (!L.ibl) sp.leftOut.push_back(serving(kUseIbl, "and") + ": image-based lighting is off (lighting.ibl = false)");
  if (!L.multiscatter)
    sp.leftOut.push_back(serving(kUseMultiscatter, "and") +
                         " with F = 1: multiple-scattering compensation is off (lighting.multiscatter)");
  if (!anyGaussianAnalytic)
    sp.leftOut.push_back(serving(kUseNormalisation, "and") +
                         (L.analytic ? ": every NDF lit by analytic lights has a closed-form normalisation (only the "
                                       "gaussian needs a k_p table)"
                                     : ": analytic lights are off (lighting.analytic = false)"));
  if (!anyVolume)
    sp.leftOut.push_back(serving(kUseWholeMaterial, "and") + ": no material asks for a 3D table (brdf3d = true)");
  if (!anyGlass)
    sp.leftOut.push_back(joinNames(namesOf(kindsServing(kUseTransmission))) +
                         ": no material transmits (transmission = true)");
  sp.byHash.clear();
  sp.byPath.clear();
  sp.reasonSets.clear();
  return sp;
}

ScenePlan shardOf(const ScenePlan& whole, int part, int parts) {
  if (parts < 1 || part < 1 || part > parts)
    throw Error(kExitUsage,
                "--shard must be I/N with 1 <= I <= N, got " + std::to_string(part) + "/" + std::to_string(parts));
  std::vector<size_t> order(whole.tables.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const auto &x = whole.tables[a], &y = whole.tables[b];
    return x.cost != y.cost ? x.cost > y.cost : x.path < y.path;
  });
  std::vector<double> load(parts, 0.0);
  std::vector<int> owner(whole.tables.size());
  for (size_t k : order) {
    int best = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    owner[k] = best;
    load[best] += whole.tables[k].cost;
  }
  ScenePlan sp;
  sp.scene = whole.scene;
  sp.plan.outDir = whole.plan.outDir;
  sp.plan.device = whole.plan.device;
  sp.leftOut = whole.leftOut;
  sp.notes = whole.notes;
  for (size_t k = 0; k < whole.tables.size(); ++k) {
    if (owner[k] != part - 1) continue;
    PlannedTable t = whole.tables[k];
    t.index = sp.plan.jobs.size();
    sp.plan.jobs.push_back(whole.plan.jobs[whole.tables[k].index]);
    sp.tables.push_back(t);
  }
  return sp;
}

}  // namespace brdfbake
