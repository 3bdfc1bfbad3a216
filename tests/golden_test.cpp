// Same input, same bytes: a sweep of bakes (every table kind, several models, every format and
// precision, the layout presets, a scene) whose files must hash to the values recorded in
// tests/data/golden/<case>.txt. It guards restructurings of the host code: a change that moves code
// without meaning to change a table keeps every hash.
//
// The bytes are those of the files as written, with one normalisation: the generator's git
// revision (brdf.generator, "brdfbake X (git REV)") is replaced by a fixed token, since it changes
// with every commit; PNG chunks are hashed without their CRCs, which cover that text.
//
// Hashes are recorded per OpenCL device name (PoCL names the CPU's instruction set in it, and a
// different code generator may round a kernel's float arithmetic differently). On a device with
// no recorded hashes the file names and sizes recorded for any device are checked instead, and
// the test says so. Record: `BRDFBAKE_GOLDEN=write ctest -R Golden` (after an intended change).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "common/hash.h"
#include "cli_run.h"
#include "version.h"

namespace fs = std::filesystem;
using brdfbake::testing_cli::bytes;
using brdfbake::testing_cli::freshDir;
using brdfbake::testing_cli::run;

namespace {

std::string normalised(std::string b) {
  const std::string rev = BRDFBAKE_GIT_REV;
  const std::string token(rev.size(), '#');
  for (size_t at = b.find(rev); !rev.empty() && at != std::string::npos; at = b.find(rev, at + rev.size()))
    b.replace(at, rev.size(), token);
  return b;
}

// PNG: signature, then chunks (length, type, data, CRC); the CRCs are left out.
std::string withoutPngCrcs(const std::string& b) {
  std::string out = b.substr(0, 8);
  size_t at = 8;
  while (at + 12 <= b.size()) {
    uint32_t len = (uint32_t(uint8_t(b[at])) << 24) | (uint32_t(uint8_t(b[at + 1])) << 16) |
                   (uint32_t(uint8_t(b[at + 2])) << 8) | uint32_t(uint8_t(b[at + 3]));
    if (at + 12 + len > b.size()) break;
    out += b.substr(at, 8 + len);
    at += 12 + len;
  }
  out += b.substr(std::min(at, b.size()));
  return out;
}

std::string hex(uint64_t h) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

// The default device's first line and its version line in `brdfbake devices` (the code generator
// and the driver that compile the kernels).
std::string deviceName() {
  brdfbake::testing_cli::CmdResult r = run("devices");
  std::istringstream in(r.out);
  std::string name, line;
  while (std::getline(in, line)) {
    size_t at = line.find_first_not_of(' ');
    if (at == std::string::npos) continue;
    if (name.empty() && line.rfind("[0]", 0) == 0)
      name = line;
    else if (!name.empty() && line.compare(at, 8, "version:") == 0)
      return name + " | " + line.substr(at + 9);
  }
  return name.empty() ? "unknown device" : name;
}

struct Entry {
  std::string device, file, hash;
  size_t size;
};

fs::path goldenFile(const std::string& name) {
  return fs::path(BRDFBAKE_SOURCE_DIR) / "tests/data/golden" / (name + ".txt");
}

std::vector<Entry> readGolden(const std::string& name) {
  std::vector<Entry> out;
  std::ifstream f(goldenFile(name));
  for (std::string line; std::getline(f, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    Entry e;
    std::getline(ls, e.device, '\t');
    std::getline(ls, e.file, '\t');
    std::getline(ls, e.hash, '\t');
    std::string size;
    std::getline(ls, size);
    e.size = std::stoull(size);
    out.push_back(e);
  }
  return out;
}

// Runs `args` (each command of the case in turn, in a fresh directory; `-o out` is the caller's)
// and checks every file under the directory against the case's record.
// `inputs` are copied into the directory first (kept out of the record).
void checkCase(const std::string& name, const std::vector<std::string>& commands,
               const std::vector<fs::path>& inputs = {}) {
  fs::path d = freshDir("golden", name);
  std::set<std::string> skip;
  for (const fs::path& p : inputs) {
    fs::copy_file(p, d / p.filename());
    skip.insert(p.filename().string());
  }
  for (const std::string& c : commands) {
    brdfbake::testing_cli::CmdResult r = run(c, d.string());
    ASSERT_EQ(r.code, 0) << c << "\n" << r.out;
  }
  std::map<std::string, std::pair<std::string, size_t>> got;
  for (const auto& e : fs::recursive_directory_iterator(d)) {
    if (!e.is_regular_file()) continue;
    std::string rel = fs::relative(e.path(), d).string();
    if (skip.count(rel)) continue;
    std::string b = normalised(bytes(e.path()));
    if (e.path().extension() == ".png") b = withoutPngCrcs(b);
    got[rel] = {hex(brdfbake::fnv1a(b)), static_cast<size_t>(e.file_size())};
  }
  ASSERT_FALSE(got.empty()) << name << ": the commands wrote nothing";
  const std::string device = deviceName();
  std::vector<Entry> golden = readGolden(name);
  if (const char* mode = std::getenv("BRDFBAKE_GOLDEN"); mode && std::string(mode) == "write") {
    std::ofstream f(goldenFile(name), std::ios::trunc);
    f << "# device\tfile\tFNV-1a 64 of the normalised bytes\tsize (tests/golden_test.cpp)\n";
    for (const Entry& e : golden)
      if (e.device != device) f << e.device << '\t' << e.file << '\t' << e.hash << '\t' << e.size << '\n';
    for (const auto& [file, hs] : got) f << device << '\t' << file << '\t' << hs.first << '\t' << hs.second << '\n';
    return;
  }
  ASSERT_FALSE(golden.empty()) << name << ": no record in " << goldenFile(name) << " (BRDFBAKE_GOLDEN=write)";
  std::map<std::string, std::pair<std::string, size_t>> want;
  std::set<std::string> devices;
  for (const Entry& e : golden) devices.insert(e.device);
  bool exact = devices.count(device) > 0;
  const std::string recorded = exact ? device : *devices.begin();
  for (const Entry& e : golden)
    if (e.device == recorded) want[e.file] = {e.hash, e.size};
  if (!exact)
    std::cout << "[ golden ] no hashes recorded for device '" << device << "': file names and sizes checked against '"
              << recorded << "'\n";
  for (const auto& [file, hs] : want) {
    auto it = got.find(file);
    if (it == got.end()) {
      ADD_FAILURE() << name << ": " << file << " was not written";
      continue;
    }
    EXPECT_EQ(it->second.second, hs.second) << name << ": " << file << " size";
    if (exact) {
      EXPECT_EQ(it->second.first, hs.first) << name << ": " << file << " bytes changed";
    }
  }
  for (const auto& [file, hs] : got)
    EXPECT_TRUE(want.count(file)) << name << ": " << file << " was written but is not in the record";
}

}  // namespace

// The microfacet family: every table of the default set, two more pairs in half precision.
TEST(Golden, MicrofacetTables) {
  checkCase("microfacet",
            {"bake --table splitsum,albedo,albedo-avg,kp --size 16 -o out/a",
             "bake --ndf beckmann,blinn-phong --gaf smith,schlick-ggx --table splitsum,albedo,albedo-avg,kp "
             "--size 8 --half -o out/b",
             "bake --ndf charlie --gaf neubelt,charlie-smith --table splitsum,albedo --size 8 -o out/c",
             "bake --table splitsum,albedo --size 8 --mu-axis sqrt -o out/d",
             "bake --table albedo --size 5 --grid node -o out/e"});
}

TEST(Golden, FresnelAndDiffuseChannels) {
  checkCase("fresnel",
            {"bake --table albedo,albedo-avg --fresnel conductor --eta 0.2,0.9,1.1 --k 3,2.5,2 --size 8 -o out/a",
             "bake --table splitsum --fresnel f82-tint --f82 0.8 --size 8 -o out/b",
             "bake --table albedo,albedo-avg --fresnel dielectric --eta 1.5 --size 8 -o out/c",
             "bake --table albedo --diffuse oren-nayar --size 8 -o out/d",
             "bake --table splitsum --diffuse burley --size 8 -o out/e",
             "bake --table fresnel-avg --fresnel dielectric --size 16 -o out/f",
             "bake --table fresnel-avg --fresnel schlick-tir --size 16 -o out/g"});
}

TEST(Golden, FormatsAndPrecisions) {
  checkCase("formats",
            {"bake --table splitsum,albedo --size 8 --format ktx2,dds,png16,header --precision unorm16 -o out/a",
             "bake --table splitsum,albedo-avg --size 8 --format exr,ktx2,dds,header --precision float16 -o out/b",
             "bake --table splitsum --size 8 --format ktx2,dds --precision unorm8 -o out/c",
             "bake --table albedo --size 8 --format ktx2,dds,header -o out/d"});
}

TEST(Golden, LayoutsAndPresets) {
  checkCase("layouts",
            {"bake --layout filament --size 8 -o out/filament", "bake --layout bevy --size 8 -o out/bevy",
             "bake --layout unity-hdrp --size 8 -o out/hdrp", "bake --layout unity-hdrp-sqrt --size 8 -o out/hdrp-sqrt",
             "bake --layout unreal --size 8 -o out/unreal", "bake --layout gltf-sample-viewer --size 8 -o out/gsv",
             "bake --table splitsum --axes r,mu --flip-y --channels B,A --size 8 -o out/custom",
             "bake --preset gltf --size 8 -o out/gltf"});
}

TEST(Golden, AshikhminAnd3dTables) {
  checkCase("volumes",
            {"bake --table ashikhmin-shirley --size 8 -o out/as",
             "bake --table brdf3d --size 6 --format exr,ktx2,dds,header -o out/angles",
             "bake --table brdf3d --param rusinkiewicz --theta-h sqrt --size 4,5,6 --diffuse lambert --rho 0.5 "
             "--fresnel schlick --f0 0.9 --half -o out/rus",
             "bake --table brdf3d --format merl --roughness 0.3 -o out/merl",
             "bake --brdf merl:out/merl/brdf3d_ggx_smith-correlated.binary --table albedo --size 2 -o out/measured"});
}

TEST(Golden, DielectricTables) {
  checkCase("dielectric", {"bake --table dielectric --size 3 -o out/a",
                           "bake --table dielectric-avg --ndf beckmann --gaf smith --size 2 -o out/b"});
}

// The LTC family: a specular, a sheen and a diffuse lobe, EXR and the header formats (three.js's .mjs).
TEST(Golden, LtcTables) {
  checkCase("ltc", {"bake --table ltc --size 6 --diffuse burley -o out/a",
                    "bake --table ltc --ndf charlie --gaf charlie-smith --size 4 --format exr,header -o out/b"});
}

TEST(Golden, SceneBake) {
  checkCase("scene", {"bake forward-mobile.toml -o out", "bake pbr-desktop.toml -o out2"},
            {fs::path(BRDFBAKE_SOURCE_DIR) / "examples/scenes/forward-mobile.toml",
             fs::path(BRDFBAKE_SOURCE_DIR) / "examples/scenes/pbr-desktop.toml"});
}
