// `brdfbake info` and `brdfbake shader` on every format the baker writes: a user who baked KTX2 (or
// PNG, the header, DDS beside its twin) alone gets the same generated code and metadata as from the
// EXR of the same bake, differing only where the format does (PNG's value mapping and storage
// rounding, the padding channel of KTX2 and DDS, the file's own brdf.format/precision/error.storage).
// Damaged files exit 65, missing ones 66, writing nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include <zlib.h>

#include "cli_run.h"

namespace fs = std::filesystem;
namespace {

using brdfbake::testing_cli::bytes;
using brdfbake::testing_cli::CmdResult;
using brdfbake::testing_cli::run;

const char* kStems[] = {"splitsum_ggx_smith-correlated", "albedo_ggx_smith-correlated",
                        "albedo-avg_ggx_smith-correlated", "kp_ggx"};

fs::path bakeAll(const std::string& name, const std::string& formats = "exr,ktx2,dds,png16,header",
                 const std::string& extra = "") {
  fs::path d = brdfbake::testing_cli::freshDir("readcli", name);
  CmdResult r = run("bake --table splitsum,albedo,albedo-avg,kp --size 12 --format " + formats + " " + extra + " -o '" +
                    d.string() + "'");
  EXPECT_EQ(r.code, 0) << r.out;
  return d;
}

std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> v;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

std::string shaderOf(const fs::path& d, const std::string& ext, const std::string& lang) {
  std::string files;
  for (const char* stem : kStems) files += " '" + (d / (std::string(stem) + ext)).string() + "'";
  CmdResult r = run("shader --lang " + lang + files);
  EXPECT_EQ(r.code, 0) << ext << "\n" << r.out;
  return r.out;
}

// Lines of `other` that differ from the EXR's, each of them where the format really differs; returns
// how many lines build in PNG's value mapping.
int compareWithExr(const std::string& exr, const std::string& other, const std::string& ext) {
  std::vector<std::string> a = lines(exr), b;
  for (const std::string& l : lines(other))
    if (l.rfind("// (", 0) != 0) {
      b.push_back(l);
    } else {
      EXPECT_EQ(ext, ".dds") << l;  // the DDS's note: which file its metadata came from
    }
  EXPECT_EQ(a.size(), b.size()) << ext;
  const std::regex mapping(
      " \\* (vec4|float4)\\([0-9.e+-]+, [0-9.e+-]+, [0-9.e+-]+, 1\\.0\\) \\+ (vec4|float4)\\([^)]*\\)");
  int mapped = 0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    if (a[i] == b[i]) continue;
    std::string x = a[i], y = b[i];
    if (x.rfind("// ---- ", 0) == 0) {  // the file's own name
      x = std::regex_replace(x, std::regex("\\.exr:"), ext + ":");
    } else if (y.find("; A=1 (padding)") != std::string::npos && (ext == ".ktx2" || ext == ".dds")) {
      y = std::regex_replace(y, std::regex("; A=1 \\(padding\\)"), "");
    } else if (ext == ".png" && x.rfind("// error budget", 0) == 0) {
      continue;  // the PNG's own storage rounding (unorm16) is in its brdf.error
    } else if (ext == ".png" && std::regex_search(y, mapping)) {
      y = std::regex_replace(y, mapping, "");
      ++mapped;
    }
    EXPECT_EQ(x, y) << ext << " line " << i + 1;
  }
  return mapped;
}

TEST(FormatsRead, ShaderFromEveryFormatEqualsTheExrs) {
  const fs::path d = bakeAll("shader");
  for (const char* lang : {"glsl", "hlsl"}) {
    const std::string exr = shaderOf(d, ".exr", lang);
    ASSERT_NE(exr.find("lookupAB"), std::string::npos) << "the multiscatter glue needs the three tables";
    for (const char* ext : {".ktx2", ".dds", ".png", ".h", ".mjs"}) {
      const std::string other = shaderOf(d, ext, lang);
      const int mapped = compareWithExr(exr, other, ext);
      // k_p reaches 2.77: png16 stores it scaled, and both lookup paths undo the mapping
      EXPECT_EQ(mapped, std::string(ext) == ".png" ? 2 : 0) << lang << ext;
    }
  }
}

TEST(FormatsRead, DdsTakesItsMetadataFromTheFileBesideIt) {
  const fs::path d = bakeAll("dds_half", "exr,ktx2,dds", "--precision float16");
  const std::string stem = (d / "splitsum_ggx_smith-correlated").string();
  // float16 KTX2 beside it: the DDS's code is the KTX2's, error budget included
  CmdResult k = run("shader --lang glsl '" + stem + ".ktx2'"), s = run("shader --lang glsl '" + stem + ".dds'");
  ASSERT_EQ(k.code, 0) << k.out;
  ASSERT_EQ(s.code, 0) << s.out;
  EXPECT_NE(s.out.find("holds no metadata: the table's is read from " + stem + ".ktx2"), std::string::npos) << s.out;
  EXPECT_EQ(compareWithExr(k.out, std::regex_replace(s.out, std::regex("\\.dds:"), ".ktx2:"), ".dds"), 0);
  // only the EXR beside it (float32 there, float16 in the DDS): its metadata, the DDS's precision
  fs::path alone = brdfbake::testing_cli::freshDir("readcli", "dds_exr");
  fs::copy_file(stem + ".dds", alone / "splitsum_ggx_smith-correlated.dds");
  fs::copy_file(stem + ".exr", alone / "splitsum_ggx_smith-correlated.exr");
  CmdResult r = run("shader --lang hlsl '" + (alone / "splitsum_ggx_smith-correlated.dds").string() + "'");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("read from " + (alone / "splitsum_ggx_smith-correlated.exr").string()), std::string::npos)
      << r.out;
  // nothing beside it that holds the table: exit 65 naming what to do, -o not written
  fs::remove(alone / "splitsum_ggx_smith-correlated.exr");
  fs::copy_file(d / "albedo_ggx_smith-correlated.ktx2", alone / "splitsum_ggx_smith-correlated.ktx2");  // other texels
  r = run("shader --lang glsl '" + (alone / "splitsum_ggx_smith-correlated.dds").string() + "' -o '" +
          (alone / "out.glsl").string() + "'");
  EXPECT_EQ(r.code, 65) << r.out;
  EXPECT_NE(r.out.find("holds no metadata"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bake --format dds,ktx2"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(alone / "out.glsl"));
  // info describes the DDS alone and says where its metadata is not
  r = run("info '" + (alone / "splitsum_ggx_smith-correlated.dds").string() + "'");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("DXGI_FORMAT_R16G16B16A16_FLOAT, TEXTURE2D (float16)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("metadata: none"), std::string::npos) << r.out;
}

// "  name (type): value" lines of `info`, v2f "(a, b)" as "a,b".
std::map<std::string, std::string> attributes(const std::string& info) {
  std::map<std::string, std::string> m;
  const std::regex line("^  ([A-Za-z][^ ]*) \\(([a-z0-9]+)\\): (.*)$");
  std::smatch g;
  for (const std::string& l : lines(info))
    if (std::regex_match(l, g, line)) {
      std::string v = g[3];
      if (g[2] == "v2f") v = std::regex_replace(v, std::regex("^\\((.*), (.*)\\)$"), "$1,$2");
      m[g[1]] = v;
    }
  return m;
}

TEST(FormatsRead, InfoPrintsTheExrsMetadataForEveryFormat) {
  const fs::path d = bakeAll("info");
  for (const char* stem : kStems) {
    CmdResult e = run("info '" + (d / (std::string(stem) + ".exr")).string() + "'");
    ASSERT_EQ(e.code, 0) << e.out;
    const auto exr = attributes(e.out);
    ASSERT_GT(exr.count("brdf.table"), 0u) << e.out;
    for (const char* ext : {".ktx2", ".png", ".h", ".mjs"}) {
      CmdResult o = run("info '" + (d / (std::string(stem) + ext)).string() + "'");
      ASSERT_EQ(o.code, 0) << o.out;
      auto other = attributes(o.out);
      for (const auto& [k, v] : exr) {
        if (k == "brdf.error" && std::string(ext) == ".png") continue;  // its own unorm16 rounding
        std::string w = other[k];
        if (k == "brdf.channels") w = std::regex_replace(w, std::regex("; A=1 \\(padding\\)$"), "");
        EXPECT_EQ(w, v) << stem << ext << " " << k;
      }
      for (const char* own : {"brdf.format", "brdf.precision", "brdf.error.storage"})
        EXPECT_GT(other.count(own), 0u) << stem << ext << " " << own;
      if (std::string(ext) == ".png") {
        EXPECT_GT(other.count("brdf.mapping.scale"), 0u);
      }
      // float32 files hold the EXR's values: the same ranges
      if (std::string(ext) != ".png") {
        for (const std::string& l : lines(e.out)) {
          if (l.rfind("  channel ", 0) == 0) {
            EXPECT_NE(o.out.find(l + "\n"), std::string::npos) << stem << ext << ": " << l;
          }
        }
      }
    }
  }
}

TEST(FormatsRead, BadFilesExit65MissingExit66WritingNothing) {
  const fs::path d = bakeAll("bad");
  const fs::path w = brdfbake::testing_cli::freshDir("readcli", "bad_work");
  auto expect = [&](const std::string& content, const std::string& name, const std::string& message) {
    const fs::path p = w / name;
    {
      std::ofstream out(p, std::ios::binary | std::ios::trunc);
      out << content;
    }
    for (const std::string& cmd : {"info '" + p.string() + "'",
                                   "shader --lang glsl '" + p.string() + "' -o '" + (w / "out.glsl").string() + "'"}) {
      CmdResult r = run(cmd);
      EXPECT_EQ(r.code, 65) << cmd << "\n" << r.out;
      EXPECT_EQ(r.out.rfind("brdfbake: cannot read " + p.string() + ": ", 0), 0u) << r.out;
      EXPECT_NE(r.out.find(message), std::string::npos) << cmd << "\n" << r.out;
      EXPECT_FALSE(fs::exists(w / "out.glsl")) << cmd;
    }
  };
  const std::string ktx2 = bytes(d / "splitsum_ggx_smith-correlated.ktx2");
  expect(ktx2.substr(0, ktx2.size() - 5), "cut.ktx2", "KTX2 is truncated: level 0 would end at byte");
  expect(ktx2.substr(0, 60), "short.ktx2", "KTX2 is truncated");
  std::string k = ktx2;
  k[12] = static_cast<char>(131);  // vkFormat 131: BC1_RGB_UNORM_BLOCK
  expect(k, "bc1.ktx2", "vkFormat 131 is not one brdfbake reads");
  k = ktx2;
  k[44] = 2;  // supercompressionScheme 2: zstd
  expect(k, "zstd.ktx2", "supercompressionScheme 2: brdfbake reads 0 (none)");
  const std::string dds = bytes(d / "splitsum_ggx_smith-correlated.dds");
  expect(dds.substr(0, dds.size() / 2), "cut.dds", "DDS is truncated: the texels (12x12)");
  std::string s = dds;
  s.replace(84, 4, "DXT1");
  expect(s, "dxt1.dds", "has no DX10 header");
  s = dds;
  s[128] = 71;  // DXGI_FORMAT_BC1_UNORM
  expect(s, "bc1.dds", "DXGI_FORMAT 71 is not one brdfbake reads");
  const std::string png = bytes(d / "splitsum_ggx_smith-correlated.png");
  expect(png.substr(0, png.size() - 20), "cut.png", "PNG is damaged or truncated");
  std::string p = png;
  const size_t idat = p.find("IDAT") + 10;  // inside the image data: its CRC fails
  p[idat] = static_cast<char>(p[idat] ^ 0x55);
  expect(p, "crc.png", "PNG is damaged or truncated");
  const std::string h = bytes(d / "splitsum_ggx_smith-correlated.h");
  expect(h.substr(0, h.size() / 2), "cut.h", "ends before its last line (#endif): truncated");
  expect(std::regex_replace(h, std::regex("0\\.[0-9]+f,"), "zz,", std::regex_constants::format_first_only), "value.h",
         "is not a float32 number");
  const std::string mjs = bytes(d / "splitsum_ggx_smith-correlated.mjs");
  expect(mjs.substr(0, mjs.size() - 10), "cut.mjs", "truncated");
  expect("not a table\n", "text.exr", "is not a table file brdfbake reads");
  expect("", "empty.ktx2", "is empty");
  // a 3D texture: `shader` generates the atlas lookups of the EXR
  const fs::path v = brdfbake::testing_cli::freshDir("readcli", "volume");
  ASSERT_EQ(run("bake --table brdf3d --size 6,5,4 --format ktx2 -o '" + v.string() + "'").code, 0);
  CmdResult r = run("shader --lang glsl '" + (v / "brdf3d_ggx_smith-correlated_angles.ktx2").string() + "'");
  EXPECT_EQ(r.code, 65) << r.out;
  EXPECT_NE(r.out.find("holds a 3D texture (6x5x4)"), std::string::npos) << r.out;
  EXPECT_EQ(run("info '" + (v / "brdf3d_ggx_smith-correlated_angles.ktx2").string() + "'").code, 0);
  // missing, a directory: 66
  for (const std::string& missing : {(w / "absent.ktx2").string(), w.string()}) {
    r = run("info '" + missing + "'");
    EXPECT_EQ(r.code, 66) << r.out;
    r = run("shader --lang hlsl '" + missing + "' -o '" + (w / "out.hlsl").string() + "'");
    EXPECT_EQ(r.code, 66) << r.out;
    EXPECT_FALSE(fs::exists(w / "out.hlsl"));
  }
}

// Readers check a header before they believe it, under a 1.5 GB address-space limit (prlimit) so
// that believing it shows as a failed allocation: a PNG whose brdf.mapping.scale chunk fails its CRC
// (libpng's default drops it, and the table read as scale 1), a PNG IHDR claiming 16384^2 in a
// 1 KB file, an EXR dataWindow made 16777224 wide, and a KTX2 made a sparse 3 GB file: each 65,
// named, from info and shader alike.
TEST(FormatsRead, DamagedHeadersAreCheckedBeforeTheyAreBelieved) {
  const fs::path d = bakeAll("believe", "exr,ktx2,png16");
  const fs::path w = brdfbake::testing_cli::freshDir("readcli", "believe_work");
  auto expect = [&](const fs::path& p, const std::string& message) {
    for (const std::string& cmd : {"info '" + p.string() + "'", "shader --lang glsl '" + p.string() + "'"}) {
      CmdResult r = run(cmd, "", "prlimit --as=1500000000");
      EXPECT_EQ(r.code, 65) << cmd << "\n" << r.out;
      EXPECT_NE(r.out.find("brdfbake: cannot read " + p.string() + ": " + message), std::string::npos) << cmd << "\n"
                                                                                                       << r.out;
    }
  };
  auto put = [&](const std::string& name, const std::string& content) {
    std::ofstream(w / name, std::ios::binary | std::ios::trunc) << content;
    return w / name;
  };
  auto be32 = [](std::string& s, size_t at, uint32_t v) {
    for (int k = 0; k < 4; ++k) s[at + k] = static_cast<char>(v >> (24 - 8 * k));
  };
  std::string png = bytes(d / "kp_ggx.png");
  const size_t key = png.find(std::string("brdf.mapping.scale") + '\0');
  ASSERT_NE(key, std::string::npos);
  std::string crc = png;
  crc[key + 20] = static_cast<char>(crc[key + 20] ^ 1);  // a digit of the scale: the chunk's CRC fails
  expect(put("crc.png", crc), "PNG is damaged or truncated: tEXt: CRC error");
  std::string big = png;
  be32(big, 16, 16384);
  be32(big, 20, 16384);
  be32(big, 29,
       static_cast<uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(big.data() + 12), 17)));  // IHDR's CRC holds
  expect(put("big.png", big), "PNG is damaged or truncated: IHDR declares 16384 x 16384");
  std::string exr = bytes(d / "kp_ggx.exr");
  const std::string window = std::string("dataWindow") + '\0' + "box2i" + '\0';
  const size_t at = exr.find(window);
  ASSERT_NE(at, std::string::npos);
  const uint32_t xmax = 16777223;
  for (int k = 0; k < 4; ++k) exr[at + window.size() + 4 + 8 + k] = static_cast<char>(xmax >> (8 * k));
  expect(put("window.exr", exr), "OpenEXR ");
  const fs::path sparse = put("sparse.ktx2", bytes(d / "splitsum_ggx_smith-correlated.ktx2"));
  fs::resize_file(sparse, 3ull << 30);  // a hole: no disk used
  expect(sparse, "KTX2 is longer than its header declares");
  fs::remove(sparse);
}

}  // namespace
