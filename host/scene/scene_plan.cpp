#include "scene/scene_plan.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <map>
#include <numeric>

#include "cl/embedded_kernels.h"
#include "common/brdf_host.h"
#include "common/errors.h"
#include "common/format.h"
#include "version.h"

namespace brdfbake {

namespace {

// FNV-1a, 64 bits: a content hash for change detection (not for security).
uint64_t fnv1a(const std::string& s, uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string hex16(uint64_t h) {
  char b[17];
  std::snprintf(b, sizeof b, "%016" PRIx64, h);
  return b;
}

// The baker itself: its version and every kernel source it compiles (the models and estimators).
uint64_t bakerHash() {
  static const uint64_t h = [] {
    uint64_t x = fnv1a(std::string("brdfbake ") + BRDFBAKE_VERSION);
    for (const auto& f : kEmbeddedKernelSources) x = fnv1a(std::string(f.path) + '\n' + f.text, x);
    return x;
  }();
  return h;
}

std::string vec(const std::vector<double>& v) {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : ",") + fmtG9(x);
  return s;
}

// Everything a table's values and header depend on, as text.
std::string jobKey(const TableJob& j) {
  return "table=" + tableName(j.kind) + ";ndf=" + std::to_string(j.ndf) + ";gaf=" + std::to_string(j.gaf) +
         ";size=" + std::to_string(j.width) + "x" + std::to_string(j.height) + ";grid=" + (j.nodeGrid ? "node" : "texel") +
         ";half=" + (j.half ? "1" : "0") + ";fresnel=" + j.fresnel.describe() + ";diffuse=" + std::to_string(j.diffuse) +
         ";texture=" + std::to_string(j.texture);
}
std::string dielectricKey(const DielectricJob& d) {
  return std::string("table=") + (d.avg ? "dielectric-avg" : "dielectric") + ";ndf=" + std::to_string(d.ndf) +
         ";gaf=" + std::to_string(d.gaf) + ";size=" + std::to_string(d.nx) + "x" + std::to_string(d.ny) + "x" +
         std::to_string(d.nz) + ";eta=" + fmtG9(d.etaLo) + "," + fmtG9(d.etaHi) + ";grid=" + (d.nodeGrid ? "node" : "texel") +
         ";half=" + (d.half ? "1" : "0");
}
std::string volumeKey(const VolumeJob& v) {
  const Brdf3dSpec& s = v.spec;
  return "table=brdf3d;ndf=" + std::to_string(s.ndf) + ";gaf=" + std::to_string(s.gaf) + ";r=" + fmtG9(s.roughness) +
         ";fresnel=" + s.fresnel.describe() + ";diffuse=" + std::to_string(s.diffuse) + ";dparam=" + fmtG9(s.diffuseParam) +
         ";rho=" + vec(s.rho) + ";param=" + std::to_string(s.kernelParam()) + ";grid=" + std::to_string(s.kernelGrid()) +
         ";cos=" + (s.timesCos ? "1" : "0") + ";size=" + std::to_string(s.nx) + "x" + std::to_string(s.ny) + "x" +
         std::to_string(s.nz) + ";atlas=" + std::to_string(v.cols) + "x" + std::to_string(v.rows) + ";half=" +
         (v.half ? "1" : "0") + ";merl=" + (v.merl ? "1" : "0");
}

// Estimated seconds (PoCL, 2 cores; measured on ggx and beckmann tables of 64^2: a guide for the
// plan's cost column and for balancing shards, not a promise).
double estimate(const TableJob& j) {
  double perTexel = j.ndf == NDF_GGX ? 4e-6 : 1.5e-5;
  double texels = static_cast<double>(j.width) * j.height;
  switch (j.kind) {
    case TableKind::AlbedoAvg: return texels * 31 * perTexel * 0.5;
    case TableKind::Kp: return texels * 1e-6;
    case TableKind::SplitSum:
    case TableKind::Albedo: return texels * perTexel * (j.fresnel.channels() == 3 ? 3 : 1);
    default: return texels * 1e-6;
  }
}

std::string modelsOf(const TableJob& j) {
  std::string m = j.ndf >= 0 ? ndfNames()[j.ndf] + (j.kind == TableKind::Kp ? "" : " + " + gafNames()[j.gaf]) : "";
  if (j.diffuse >= 0) m += (m.empty() ? "" : ", ") + diffuseNames()[j.diffuse];
  if (j.kind == TableKind::SplitSum)
    m += j.fresnel.model == FRESNEL_F82_TINT ? ", F82-tint split (F0 A + B - b C: no F0 or tint in the table)"
                                             : ", Schlick split (F0 A + B: no F0 in the table)";
  else if (!j.fresnel.isOne() && j.kind != TableKind::Kp)
    m += ", " + j.fresnel.describe();
  return m;
}

// Adds the tables of `req` (one material's lighting path) to `sp`, sharing files with the same key.
void addTables(ScenePlan& sp, const BakeRequest& req, const SceneMaterial& m, const std::string& why) {
  Plan p;
  try {
    p = makePlan(req);
  } catch (const Error& e) {
    throw Error(kExitDataErr, m.pos.str() + ": material '" + m.name + "': " + why + " needs a table that cannot be built: " +
                                  e.what());
  }
  std::string reason = m.name + ": " + why;
  auto place = [&](const std::string& key, std::string path, bool volume, auto addJob) {
    // the same key: the same file; the same name for a different table: a suffix from the key
    for (auto& t : sp.tables) {
      if (t.hash == hex16(fnv1a(key, bakerHash()))) {
        if (std::find(t.reasons.begin(), t.reasons.end(), reason) == t.reasons.end()) t.reasons.push_back(reason);
        return;
      }
    }
    for (const auto& t : sp.tables)
      if (t.path == path) {
        size_t dot = path.find_last_of('.');
        path = path.substr(0, dot) + "_" + hex16(fnv1a(key)).substr(0, 8) + path.substr(dot);
        break;
      }
    PlannedTable t;
    t.volume = volume;
    t.path = path;
    t.hash = hex16(fnv1a(key, bakerHash()));
    t.reasons.push_back(reason);
    addJob(t, path);
    sp.tables.push_back(t);
  };
  for (TableJob j : p.jobs)
    place(jobKey(j), j.path, false, [&](PlannedTable& t, const std::string& path) {
      j.path = path;
      t.index = sp.plan.jobs.size();
      t.table = tableName(j.kind);
      t.models = modelsOf(j);
      t.size = std::to_string(j.width) + "x" + std::to_string(j.height);
      t.texels = static_cast<double>(j.width) * j.height;
      t.cost = estimate(j);
      sp.plan.jobs.push_back(j);
    });
  for (DielectricJob d : p.dielectric)
    place(dielectricKey(d), d.path, false, [&](PlannedTable& t, const std::string& path) {
      d.path = path;
      t.dielectric = true;
      t.index = sp.plan.dielectric.size();
      t.table = d.avg ? "dielectric-avg" : "dielectric";
      t.models = ndfNames()[d.ndf] + " + " + gafNames()[d.gaf] + ", eta " + fmtG(d.etaLo) + ".." + fmtG(d.etaHi);
      t.size = std::to_string(d.nx) + "x" + std::to_string(d.ny) + (d.avg ? "" : "x" + std::to_string(d.nz));
      t.texels = static_cast<double>(d.nx) * d.ny * d.nz;
      t.cost = t.texels * (d.avg ? 0.05 : 5e-3);  // measured: 4.8 ms per texel of E; the averages ~50 ms per entry
      sp.plan.dielectric.push_back(d);
    });
  for (VolumeJob v : p.volumes)
    place(volumeKey(v), v.path, true, [&](PlannedTable& t, const std::string& path) {
      v.path = path;
      t.index = sp.plan.volumes.size();
      t.table = "brdf3d";
      t.models = ndfNames()[v.spec.ndf] + " + " + gafNames()[v.spec.gaf] + ", r " + fmtG(v.spec.roughness);
      t.size = std::to_string(v.spec.nx) + "x" + std::to_string(v.spec.ny) + "x" + std::to_string(v.spec.nz);
      t.texels = static_cast<double>(v.spec.nx) * v.spec.ny * v.spec.nz;
      t.cost = t.texels * 1.5e-7;
      sp.plan.volumes.push_back(v);
    });
}

}  // namespace

ScenePlan planScene(const Scene& scene, const std::string& outDir) {
  ScenePlan sp;
  sp.scene = scene.name;
  std::string dir = outDir;
  if (dir.empty())
    dir = scene.output.dir.front() == '/' || scene.baseDir == "." ? scene.output.dir : scene.baseDir + "/" + scene.output.dir;
  sp.plan.outDir = dir;
  const SceneLighting& L = scene.lighting;
  auto request = [&](const SceneMaterial& m, TableKind kind) {
    BakeRequest r;
    r.ndfs = {m.ndf};
    r.gafs = {m.gaf};
    r.tables = {kind};
    r.outDir = dir;
    r.half = scene.output.half;
    r.nodeGrid = scene.output.nodeGrid;
    auto it = scene.output.size.find(kind);
    if (it != scene.output.size.end()) r.size = it->second;
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
        BakeRequest r = request(m, TableKind::SplitSum);
        r.fresnel.model = fm == FRESNEL_F82_TINT ? FRESNEL_F82_TINT : FRESNEL_SCHLICK;
        if (fm == FRESNEL_F82_TINT) r.fresnel = m.fresnel;  // its split has a third channel, F0-free
        r.fresnel.f0.clear();
        r.fresnel.f82.clear();
        validateFresnel(r.fresnel);
        r.fresnelGiven = true;
        if (m.diffuse == DIFFUSE_BURLEY) r.diffuse = DIFFUSE_BURLEY;
        addTables(sp, r, m, std::string("image-based lighting (split-sum DFG") +
                                (m.diffuse == DIFFUSE_BURLEY ? ", burley's diffuse albedo in B" : "") + ")");
      } else {
        BakeRequest r = request(m, TableKind::Albedo);
        r.fresnel = m.fresnel;
        r.fresnelGiven = true;
        addTables(sp, r, m, "image-based lighting (" + fresnelNames()[fm] + " has no Schlick split: its DFG is the "
                            "Fresnel-weighted albedo)");
      }
    }
    if (L.multiscatter)
      for (TableKind k : {TableKind::Albedo, TableKind::AlbedoAvg})
        addTables(sp, request(m, k), m, "multiple-scattering compensation (Kulla-Conty E and E_avg, F = 1)");
    if (L.analytic && m.ndf == NDF_GAUSSIAN) {
      anyGaussianAnalytic = true;
      addTables(sp, request(m, TableKind::Kp), m, "analytic lights (the gaussian's D = p/k_p, k_p has no closed form)");
    }
    if (m.coupling == "albedo-scaling")
      for (TableKind k : {TableKind::Albedo, TableKind::AlbedoAvg}) {
        BakeRequest r = request(m, k);
        r.fresnel = m.fresnel;
        r.fresnelGiven = !m.fresnel.isOne();
        addTables(sp, r, m, "albedo-scaling coupling (the diffuse lobe scaled by 1 - E_F, with E_F,avg)");
      }
    if (m.brdf3d) {
      anyVolume = true;
      BakeRequest r = request(m, TableKind::Brdf3d);
      r.fresnel = m.fresnel;
      r.fresnelGiven = true;
      r.diffuse = m.diffuse;
      r.sigma = m.sigma;
      r.size.reset();
      r.volume.roughness = m.roughnessLo;
      r.volume.rho = m.rho;
      if (scene.output.brdf3dSize) r.volume.size = scene.output.brdf3dSize;
      addTables(sp, r, m, "a 3D table of the whole material (brdf3d = true)");
    }
    size_t reasonsAfter = 0;
    for (const auto& t : sp.tables) reasonsAfter += t.reasons.size();
    if (sp.tables.size() == before && reasonsAfter > reasonsBefore)
      sp.notes.push_back("material '" + m.name + "' adds no table: it shares every table it needs with earlier materials "
                         "(the tables do not depend on the parameters that differ)");
    else if (reasonsAfter == reasonsBefore)
      sp.notes.push_back("material '" + m.name + "' needs no table under this lighting");
    if (m.transmission) {
      // rough glass: E_R and E_T over (mu, r, eta), and their averages (Kulla-Conty for dielectrics)
      anyGlass = true;
      for (TableKind k : {TableKind::Dielectric, TableKind::DielectricAvg})
        addTables(sp, request(m, k), m, "transmission (rough glass: reflected and transmitted albedo" +
                                            std::string(k == TableKind::DielectricAvg ? ", their averages)" : ")"));
    }
    if (m.sheen) {
      // KHR_materials_sheen: the Charlie lobe's albedo (its albedo-scaling of the layers below, with
      // the Charlie visibility) and, under image-based lighting, its DFG-style term (Neubelt's
      // visibility, as Filament's cloth and glTF's reference viewer use)
      SceneMaterial sheen = m;
      sheen.ndf = NDF_CHARLIE;
      sheen.gaf = GAF_CHARLIE_SMITH;
      BakeRequest a = request(sheen, TableKind::Albedo);
      addTables(sp, a, m, "KHR_materials_sheen (sheen albedo scaling: E of charlie + charlie-smith)");
      if (L.ibl) {
        sheen.gaf = GAF_NEUBELT;
        addTables(sp, request(sheen, TableKind::SplitSum), m, "KHR_materials_sheen under image-based lighting (charlie + neubelt)");
      }
    }
    for (const auto& n : m.notes) sp.notes.push_back("material '" + m.name + "': " + n);
  }
  if (!L.ibl) sp.leftOut.push_back("splitsum: image-based lighting is off (lighting.ibl = false)");
  if (!L.multiscatter)
    sp.leftOut.push_back("albedo and albedo-avg with F = 1: multiple-scattering compensation is off (lighting.multiscatter)");
  if (!anyGaussianAnalytic)
    sp.leftOut.push_back(L.analytic ? "kp: every NDF lit by analytic lights has a closed-form normalisation (only the "
                                      "gaussian needs a k_p table)"
                                    : "kp: analytic lights are off (lighting.analytic = false)");
  if (!anyVolume) sp.leftOut.push_back("brdf3d: no material asks for a 3D table (brdf3d = true)");
  if (!anyGlass) sp.leftOut.push_back("dielectric, dielectric-avg: no material transmits (transmission = true)");
  return sp;
}

ScenePlan shardOf(const ScenePlan& whole, int part, int parts) {
  if (parts < 1 || part < 1 || part > parts)
    throw Error(kExitUsage, "--shard must be I/N with 1 <= I <= N, got " + std::to_string(part) + "/" + std::to_string(parts));
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
    if (t.volume) {
      t.index = sp.plan.volumes.size();
      sp.plan.volumes.push_back(whole.plan.volumes[whole.tables[k].index]);
    } else if (t.dielectric) {
      t.index = sp.plan.dielectric.size();
      sp.plan.dielectric.push_back(whole.plan.dielectric[whole.tables[k].index]);
    } else {
      t.index = sp.plan.jobs.size();
      sp.plan.jobs.push_back(whole.plan.jobs[whole.tables[k].index]);
    }
    sp.tables.push_back(t);
  }
  return sp;
}

}  // namespace brdfbake
