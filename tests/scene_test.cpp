// Scenes (host/scene): the example manifests plan their expected tables; a second bake writes
// nothing; editing one material rebakes only its tables; --force, --prune; bad manifests give
// file:line:column messages and exit 65 (66 when missing) and write nothing; shards are
// deterministic and cover the plan once; glTF files (written here) plan glTF's tables.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "cli_run.h"
#include "common/errors.h"
#include "scene/scene.h"
#include "scene/scene_plan.h"
#include "tables/registry.h"

namespace fs = std::filesystem;
namespace {
using namespace brdfbake;

using testing_cli::bytes;
using testing_cli::CmdResult;
using testing_cli::run;
fs::path freshDir(const std::string& name) { return testing_cli::freshDir("scene", name); }
void write(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  f << text;
}
std::string read(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}
std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> v;
  std::stringstream ss(s);
  for (std::string l; std::getline(ss, l);)
    if (!l.empty()) v.push_back(l);
  return v;
}
std::set<std::string> names(const std::vector<std::string>& paths) {
  std::set<std::string> n;
  for (const auto& p : paths) n.insert(fs::path(p).filename().string());
  return n;
}
std::map<std::string, fs::file_time_type> mtimes(const fs::path& dir) {
  std::map<std::string, fs::file_time_type> m;
  for (const auto& e : fs::directory_iterator(dir)) m[e.path().filename().string()] = e.last_write_time();
  return m;
}
const std::string kExamples = std::string(BRDFBAKE_SOURCE_DIR) + "/examples/scenes/";

TEST(Scene, ExampleScenesPlanTheirTables) {
  fs::path d = freshDir("examples");
  CmdResult r = run("plan '" + kExamples + "pbr-desktop.toml' -o '" + d.string() + "' --list");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(names(lines(r.out)),
            (std::set<std::string>{"splitsum_ggx_smith-correlated.exr", "albedo_ggx_smith-correlated.exr",
                                   "albedo-avg_ggx_smith-correlated.exr", "splitsum_ggx_smith-correlated_f82-tint.exr",
                                   "splitsum_ggx_smith-correlated_burley.exr",
                                   "albedo_ggx_smith-correlated_dielectric-eta1.33.exr"}));
  for (const auto& l : lines(r.out)) EXPECT_TRUE(fs::path(l).is_absolute()) << l;
  r = run("plan '" + kExamples + "glass.toml' -o '" + d.string() + "' --list");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(names(lines(r.out)),
            (std::set<std::string>{"splitsum_ggx_smith-correlated.exr", "dielectric_ggx_smith-correlated.exr",
                                   "dielectric-avg_ggx_smith-correlated.exr"}));
  r = run("plan '" + kExamples + "forward-mobile.toml' -o '" + d.string() + "' --list");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(names(lines(r.out)),
            (std::set<std::string>{"albedo_ggx_smith-correlated.exr", "albedo-avg_ggx_smith-correlated.exr"}));
  // the human plan says why, and what was left out
  r = run("plan '" + kExamples + "forward-mobile.toml' -o '" + d.string() + "'");
  EXPECT_NE(r.out.find("splitsum: image-based lighting is off"), std::string::npos) << r.out;
  r = run("plan '" + kExamples + "pbr-desktop.toml' -o '" + d.string() + "'");
  EXPECT_NE(r.out.find("material 'gold' adds no table"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("for water: image-based lighting (dielectric has no Schlick split"), std::string::npos) << r.out;
}

TEST(Scene, SecondBakeWritesNothingAndAnEditRebakesOnlyItsTables) {
  fs::path d = freshDir("incremental");
  fs::path scene = d / "scene.toml";
  write(scene, read(kExamples + "pbr-desktop.toml"));
  fs::path out = d / "tables";
  CmdResult r = run("bake '" + scene.string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  auto first = mtimes(out);
  ASSERT_EQ(first.size(), 6u);
  r = run("bake '" + scene.string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("all 6 table(s) up to date"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nothing written"), std::string::npos) << r.out;
  EXPECT_EQ(mtimes(out), first);
  // water's IOR changes: only its Fresnel-weighted albedo is baked, under a name of its own (the
  // eta 1.33 table stays until pruned)
  std::string text = read(scene);
  text.replace(text.find("eta = 1.33"), 10, "eta = 1.5 ");
  write(scene, text);
  r = run("bake '" + scene.string() + "' -o '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("baked 1 table(s), 5 up to date"), std::string::npos) << r.out;
  auto second = mtimes(out);
  for (const auto& [name, t] : first) EXPECT_EQ(second[name], t) << name;
  EXPECT_TRUE(second.count("albedo_ggx_smith-correlated_dielectric-eta1.5.exr"));
  // --force rebakes everything
  r = run("bake '" + scene.string() + "' -o '" + out.string() + "' --force");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("baked 6 table(s)"), std::string::npos) << r.out;
  // water becomes Schlick: its table is no longer needed, listed, then pruned
  text = read(scene);
  text.replace(text.find("fresnel = \"dielectric\""), 22, "fresnel = \"schlick\"   ");
  text.replace(text.find("eta = 1.5"), 9, "f0 = 0.02");
  write(scene, text);
  r = run("plan '" + scene.string() + "' -o '" + out.string() + "'");
  EXPECT_NE(r.out.find("no longer needed by this scene"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("albedo_ggx_smith-correlated_dielectric-eta1.5.exr"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("albedo_ggx_smith-correlated_dielectric-eta1.33.exr"), std::string::npos) << r.out;
  r = run("bake '" + scene.string() + "' -o '" + out.string() + "' --prune");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("removed, no longer needed"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out / "albedo_ggx_smith-correlated_dielectric-eta1.5.exr"));
  EXPECT_FALSE(fs::exists(out / "albedo_ggx_smith-correlated_dielectric-eta1.33.exr"));
  EXPECT_EQ(mtimes(out).size(), 5u);
}

// A table whose header still says "up to date" but whose bytes were damaged (one texel's bit
// flipped, the file cut short) is found by the next bake, said, and baked again to the same bytes.
TEST(Scene, DamagedTablesAreBakedAgain) {
  fs::path d = freshDir("damaged");
  fs::path out = d / "tables";
  const std::string scene = kExamples + "pbr-desktop.toml";
  CmdResult r = run("bake '" + scene + "' -o '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  const fs::path flipped = out / "splitsum_ggx_smith-correlated.exr", cut = out / "albedo_ggx_smith-correlated.exr";
  const std::string good = read(flipped), goodCut = read(cut);
  std::string bad = good;
  bad[bad.size() - 7] = static_cast<char>(bad[bad.size() - 7] ^ 0x10);  // a texel of the last row (FLOAT, uncompressed)
  write(flipped, bad);
  write(cut, goodCut.substr(0, goodCut.size() - 100));
  r = run("bake '" + scene + "' -o '" + out.string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(
      r.out.find(flipped.string() + " is damaged (its texels are not those it was written with): baking it again"),
      std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find(cut.string() + " is damaged (cannot read " + cut.string()), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("baked 2 table(s), 4 up to date"), std::string::npos) << r.out;
  EXPECT_EQ(read(flipped), good);
  EXPECT_EQ(read(cut), goodCut);
  r = run("bake '" + scene + "' -o '" + out.string() + "'");
  EXPECT_NE(r.out.find("all 6 table(s) up to date"), std::string::npos) << r.out;
}

// Each table kind is described once, by a family that bakes it (tables/kind_info.h), with the name
// the command line, scenes and files spell (the families give the names; --table's list is theirs in
// id order), and --size's defaults are the documented ones (docs/commands.md): 128 for splitsum,
// fresnel-avg and the Ashikhmin-Shirley textures, 64 for ltc (the engines' size), 32 for the others.
TEST(Registry, EveryKindIsDescribedOnceByAFamilyThatBakesIt) {
  ASSERT_EQ(allKinds().size(), static_cast<size_t>(kTableKindCount));
  ASSERT_EQ(tableNames().size(), static_cast<size_t>(kTableKindCount));
  EXPECT_EQ(
      joinNames(tableNames()),
      "splitsum, albedo, albedo-avg, kp, fresnel-avg, brdf3d, ashikhmin-shirley, dielectric, dielectric-avg, ltc");
  for (size_t id = 0; id < allKinds().size(); ++id) {
    EXPECT_EQ(static_cast<size_t>(allKinds()[id].kind), id);
    EXPECT_EQ(tableKind(allKinds()[id].name), allKinds()[id].kind);
    EXPECT_EQ(tableName(allKinds()[id].kind), allKinds()[id].name);
  }
  for (const KindInfo& k : allKinds()) {
    int describers = 0;
    for (const TableFamily* f : families())
      for (const KindInfo& d : f->describe()) describers += d.kind == k.kind;
    EXPECT_EQ(describers, 1) << tableName(k.kind);
    const std::vector<TableKind> baked = familyOf(k.kind).kinds();
    EXPECT_NE(std::find(baked.begin(), baked.end(), k.kind), baked.end()) << tableName(k.kind);
    const std::string n = tableName(k.kind);
    EXPECT_EQ(defaultSize(k.kind), n == "splitsum" || n == "fresnel-avg" || n == "ashikhmin-shirley" ? 128
                                   : n == "ltc"                                                      ? 64
                                                                                                     : 32)
        << n;
    EXPECT_EQ(findKind(n), &kindInfo(k.kind));
    if (k.shader == ShaderLookup::Value) {
      EXPECT_FALSE(k.shaderValue.empty()) << n;
    }
  }
  EXPECT_EQ(findKind("nothing"), nullptr);
}

// A scene's [output.size] takes exactly the kinds whose families say scenes plan them
// (KindInfo::inScenes), and the form [X, Y, Z] where the kind is a 3D texture (KindInfo::volume);
// the manifest reader keeps the entries, the planner checks them.
TEST(Scene, OutputSizeKeysAreTheKindsScenesPlan) {
  for (const KindInfo& k : allKinds()) {
    const std::string name = tableName(k.kind);
    const std::string text =
        "[output.size]\n\"" + name + "\" = " + (k.volume ? "[4, 4, 4]" : "16") + "\n[[material]]\nname = \"a\"\n";
    bool parsed = true;
    std::string why;
    try {
      planScene(parseManifest(text, "k.toml"), "unused");
    } catch (const Error& e) {
      parsed = false;
      why = e.what();
    }
    EXPECT_EQ(parsed, k.inScenes) << name << ": " << why;
    if (!k.inScenes) {
      EXPECT_NE(why.find("unknown key '" + name + "' in [output.size]"), std::string::npos) << why;
    }
  }
}

TEST(Scene, BadManifestsNameFileLineColumnAndWriteNothing) {
  fs::path d = freshDir("bad");
  struct Case {
    std::string text, message;
  } cases[] = {
      {"[output]\ndri = \"x\"\n", "bad.toml:2:1: unknown key 'dri' in [output] (did you mean 'dir'?)"},
      {"[[material]]\nname = \"a\"\nndf = \"ggz\"\n", "bad.toml:3:7: unknown NDF 'ggz' (did you mean 'ggx'?)"},
      {"[[material]]\nname = \"a\"\n[[material]]\nname = \"a\"\n", "duplicate material name 'a' (first at"},
      {"[[material]]\nname = \"a\"\nf0 = 2\n", "bad.toml:3:6: material 'a': f0 must be in [0, 1], got 2"},
      {"[[material]]\nname = \"a\"\nroughness = \"high\"\n", "bad.toml:3:13: material.roughness must be a number"},
      {"[[material]\nname = \"a\"\n", "bad.toml:1:12: TOML syntax:"},
      {"[output]\ngrid = \"node\"\n[[material]]\nname = \"a\"\ngaf = \"none\"\n",
       "material 'a': image-based lighting (split-sum DFG) needs a table that cannot be built"},
      {"[output.size]\nsplitsum = 0\n[[material]]\nname = \"a\"\n",
       "output.size.splitsum must be an integer in 1..8192"},
      {"[lighting]\nibl = 1\n[[material]]\nname = \"a\"\n", "bad.toml:2:7: lighting.ibl must be true or false"},
      {"[[material]]\nndf = \"ggx\"\n", "material 1 has no name"},
      {"[scene]\nname = \"x\"\n", "the scene has no materials"},
      {"[[material]]\nname = \"a\"\nbrdf3d = true\nroughness = [0.1, 0.5]\n", "brdf3d = true needs one roughness"},
      {"[[material]]\nname = \"a\"\ndiffuse = \"lambert\"\nsigma = 0.3\n",
       "material.sigma: only diffuse = \"oren-nayar\""},
      {"[[material]]\nname = \"a\"\ngaf = \"schlick-ggx\"\ntransmission = true\n",
       "transmission = true needs ndf ggx or beckmann"},
  };
  fs::path out = d / "out";
  for (const Case& c : cases) {
    write(d / "bad.toml", c.text);
    for (const char* verb : {"plan", "bake"}) {
      CmdResult r = run(std::string(verb) + " '" + (d / "bad.toml").string() + "' -o '" + out.string() + "'");
      EXPECT_EQ(r.code, 65) << c.text << "\n" << r.out;
      EXPECT_NE(r.out.find(c.message), std::string::npos) << c.text << "\n" << r.out;
      EXPECT_FALSE(fs::exists(out)) << c.text;
    }
  }
  CmdResult r = run("bake '" + (d / "missing.toml").string() + "'");
  EXPECT_EQ(r.code, 66) << r.out;
  r = run("plan '" + kExamples + "pbr-desktop.toml' --shard 4/3");
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("--shard must be I/N with 1 <= I <= N"), std::string::npos) << r.out;
  r = run("bake '" + kExamples + "pbr-desktop.toml' --table albedo");
  EXPECT_EQ(r.code, 64) << r.out;
  EXPECT_NE(r.out.find("--table: not a bake SCENE option"), std::string::npos) << r.out;
}

// Shards: the same split every time, every table in exactly one part, loads near-equal (no part
// above the mean by more than the costliest table).
TEST(Scene, ShardsAreDeterministicAndCoverThePlanOnce) {
  Scene s = readScene(kExamples + "pbr-desktop.toml");
  ScenePlan whole = planScene(s, "out");
  for (int n : {1, 2, 3, 4, 7}) {
    std::multiset<std::string> seen;
    double total = 0, costliest = 0;
    for (const auto& t : whole.tables) {
      total += t.cost;
      costliest = std::max(costliest, t.cost);
    }
    for (int i = 1; i <= n; ++i) {
      ScenePlan a = shardOf(whole, i, n), b = shardOf(whole, i, n);
      ASSERT_EQ(a.tables.size(), b.tables.size());
      double load = 0;
      for (size_t k = 0; k < a.tables.size(); ++k) {
        EXPECT_EQ(a.tables[k].path, b.tables[k].path);
        seen.insert(a.tables[k].path);
        load += a.tables[k].cost;
      }
      EXPECT_EQ(a.plan.jobs.size(), a.tables.size());
      EXPECT_LE(load, total / n + costliest + 1e-12) << i << "/" << n;
    }
    std::multiset<std::string> all;
    for (const auto& t : whole.tables) all.insert(t.path);
    EXPECT_EQ(seen, all) << n;
  }
  EXPECT_THROW(shardOf(whole, 0, 2), Error);
}

// glTF: materials become GGX + height-correlated Smith + Schlick (glTF 2.0 appendix B); IOR and
// specular change F0 only (the same split-sum table); a .glb and a .gltf plan the same.
TEST(Scene, GltfFilesPlanGltfTables) {
  fs::path d = freshDir("gltf");
  std::string json = R"({"asset":{"version":"2.0"},"extensionsUsed":["KHR_materials_ior","KHR_materials_sheen"],
    "materials":[{"name":"paint","pbrMetallicRoughness":{"roughnessFactor":0.4}},
                 {"name":"glass","extensions":{"KHR_materials_ior":{"ior":1.45}}},
                 {"name":"velvet","extensions":{"KHR_materials_sheen":{"sheenRoughnessFactor":0.5}}},
                 {"name":"water","extensions":{"KHR_materials_transmission":{"transmissionFactor":1.0}}}]})";
  write(d / "model.gltf", json);
  // GLB: header, then one JSON chunk padded with spaces to 4 bytes
  std::string body = json;
  while (body.size() % 4) body += ' ';
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  write(d / "model.glb", "glTF" + u32(2) + u32(static_cast<uint32_t>(12 + 8 + body.size())) +
                             u32(static_cast<uint32_t>(body.size())) + "JSON" + body);
  for (const char* file : {"model.gltf", "model.glb"}) {
    CmdResult r = run("plan '" + (d / file).string() + "' -o '" + (d / "out").string() + "' --list");
    ASSERT_EQ(r.code, 0) << file << "\n" << r.out;
    EXPECT_EQ(names(lines(r.out)),
              (std::set<std::string>{"splitsum_ggx_smith-correlated.exr", "albedo_charlie_charlie-smith.exr",
                                     "splitsum_charlie_neubelt.exr", "dielectric_ggx_smith-correlated.exr",
                                     "dielectric-avg_ggx_smith-correlated.exr"}))
        << file;
    r = run("plan '" + (d / file).string() + "' -o '" + (d / "out").string() + "'");
    EXPECT_NE(r.out.find("for paint: image-based lighting"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("KHR_materials_ior: ior 1.45"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("for velvet: KHR_materials_sheen (sheen albedo scaling"), std::string::npos) << r.out;
  }
  write(d / "broken.gltf", "{\"asset\":{\"version\":\"2.0\"},\"materials\":[{\"name\":\"m\"");
  CmdResult r = run("plan '" + (d / "broken.gltf").string() + "'");
  EXPECT_EQ(r.code, 65) << r.out;
  EXPECT_NE(r.out.find("broken.gltf: byte "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(": not valid JSON: "), std::string::npos) << r.out;
  // no materials: glTF's default material
  write(d / "empty.gltf", R"({"asset":{"version":"2.0"}})");
  r = run("plan '" + (d / "empty.gltf").string() + "' --list");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(names(lines(r.out)), (std::set<std::string>{"splitsum_ggx_smith-correlated.exr"}));
}

// glTF: materials only. Buffers and images are never opened: here each names a FIFO (opening it
// would block; `timeout 20` turns a hang into a failure) and a path outside the file's folder.
// Every material field is type- and range-checked, naming its JSON path.
TEST(Scene, GltfReadsMaterialsOnlyAndChecksEveryField) {
  fs::path d = freshDir("gltf-hostile");
  ASSERT_EQ(::mkfifo((d / "buffer.bin").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((d / "image.png").c_str(), 0600), 0);
  write(d / "model.gltf", R"({"asset":{"version":"2.0"},
    "buffers":[{"uri":"buffer.bin","byteLength":12},{"uri":"../../../../../../etc/passwd","byteLength":3}],
    "images":[{"uri":"image.png"}],
    "materials":[{"name":"m","pbrMetallicRoughness":{"roughnessFactor":0.5}}]})");
  CmdResult r = run("plan model.gltf --list", d.string(), "timeout 20");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out.find("passwd"), std::string::npos) << r.out;
  struct Case {
    std::string material, says;
  } cases[] = {
      {R"({"pbrMetallicRoughness":{"roughnessFactor":"high"}})",
       "materials[0].pbrMetallicRoughness.roughnessFactor: expected a number in [0, 1], got \"high\""},
      {R"({"pbrMetallicRoughness":{"roughnessFactor":1.5}})", "roughnessFactor: expected a number in [0, 1], got 1.5"},
      {R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1]}})", "materials[0].pbrMetallicRoughness.baseColorFactor"},
      {R"({"name":7})", "materials[0].name: expected a string, got 7"},
      {R"({"extensions":{"KHR_materials_ior":{"ior":0.5}}})", "KHR_materials_ior.ior: expected 0 or a number >= 1"},
      {R"({"extensions":{"KHR_materials_sheen":{"sheenRoughnessFactor":-1}}})",
       "sheenRoughnessFactor: expected a number in [0, 1]"},
      {R"({"extensions":{"KHR_materials_transmission":[]}})", "KHR_materials_transmission: expected an object"},
      {R"(3)", "materials[0]: expected an object, got 3"},
  };
  for (const Case& c : cases) {
    write(d / "bad.gltf", R"({"asset":{"version":"2.0"},"materials":[)" + c.material + "]}");
    r = run("plan bad.gltf", d.string(), "timeout 20");
    EXPECT_EQ(r.code, 65) << c.material << "\n" << r.out;
    EXPECT_NE(r.out.find("bad.gltf: materials[0]"), std::string::npos) << c.material << "\n" << r.out;
    EXPECT_NE(r.out.find(c.says), std::string::npos) << c.material << "\n" << r.out;
  }
  // a number beyond a double's range is a JSON error with a message, not an abort
  write(d / "huge.gltf",
        R"({"asset":{"version":"2.0"},"materials":[{"pbrMetallicRoughness":{"roughnessFactor":1e999}}]})");
  r = run("plan huge.gltf", d.string(), "timeout 20");
  EXPECT_EQ(r.code, 65) << r.out;
  EXPECT_NE(r.out.find("huge.gltf: $: not valid JSON"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("number overflow"), std::string::npos) << r.out;
  write(d / "v1.gltf", R"({"asset":{"version":"1.0"}})");
  r = run("plan v1.gltf", d.string());
  EXPECT_EQ(r.code, 65) << r.out;
  EXPECT_NE(r.out.find("asset.version: expected \"2.x\""), std::string::npos) << r.out;
}

// Replays a fuzzer's corpus: every input parses or is rejected with a message (brdfbake::Error,
// exit 65, naming the file), never anything else; crashers found while fuzzing stay in it.
// Returns how many inputs parsed.
template <class Parse>
size_t replayCorpus(const std::string& folder, Parse parse) {
  fs::path corpus = fs::path(BRDFBAKE_SOURCE_DIR) / "tests" / "fuzz" / folder;
  size_t files = 0, parsed = 0;
  for (const auto& e : fs::directory_iterator(corpus)) {
    ++files;
    try {
      parse(read(e.path()), e.path().filename().string());
      ++parsed;
    } catch (const Error& err) {
      EXPECT_EQ(err.code(), kExitDataErr) << e.path() << ": " << err.what();
      EXPECT_NE(std::string(err.what()).find(e.path().filename().string() + ":"), std::string::npos)
          << e.path() << ": the message names no position: " << err.what();
    } catch (const std::exception& x) {
      ADD_FAILURE() << e.path() << ": not a brdfbake::Error: " << x.what();
    }
  }
  EXPECT_GE(files, 3u) << folder;
  return parsed;
}

// The glTF fuzzer's seeds (tools/fuzz.sh gltf): valid files, each plans.
TEST(Scene, GltfFuzzCorpusParsesOrIsRejected) {
  EXPECT_GE(replayCorpus("gltf_corpus", [](const std::string& t, const std::string& n) { parseGltf(t, n); }), 3u);
}

// The manifest fuzzer's corpus (tools/fuzz.sh manifest, libFuzzer).
TEST(Scene, FuzzCorpusParsesOrIsRejected) {
  // the example scenes at least parse
  EXPECT_GE(replayCorpus("corpus", [](const std::string& t, const std::string& n) { parseManifest(t, n); }), 2u);
}

TEST(Scene, ClosestNameSuggestsTypos) {
  EXPECT_EQ(closestName("smith-corelated", gafNames()), "smith-correlated");
  EXPECT_EQ(closestName("precison", {"dir", "precision", "grid", "size"}), "precision");
  EXPECT_EQ(closestName("zzzzzzzz", {"dir", "grid"}), "");
}

}  // namespace
