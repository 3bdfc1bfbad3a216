// brdfbake render: the white furnace through OpenGL ES 3.1 on Mesa's llvmpipe (CI installs Mesa's
// EGL): the rows that should conserve vanish into the background, the single-scattering row loses
// energy with roughness and matches the reference, the files carry what made them; a broken
// compensation fails the measurement; no EGL and bad options are refused before anything is written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>

#include "cli_run.h"
#include "formats/exr/table_file.h"

namespace fs = std::filesystem;
using namespace brdfbake::testing_cli;

namespace {
const char* const kSmall = "render --cell 24 --columns 6";

// The row's line of render's table: [1] conserves, [2] what it tests, [3] the largest deviation,
// [4] the bound at that pixel, [5] the largest bound, [6] pixels over.
std::smatch rowLine(const std::string& out, const std::string& row) {
  std::smatch m;
  std::regex re(
      "\\n" + row +
      " +(yes|no) +(the tables|algebra only) +([-0-9.e+]+) \\([^)]*\\) +([-0-9.e+]+) +([-0-9.e+]+) +([0-9]+)\\n");
  EXPECT_TRUE(std::regex_search(out, m, re)) << row << "\n" << out;
  return m;
}
}  // namespace

TEST(Render, FurnaceRowsVanishAndTheSingleRowLosesEnergy) {
  const fs::path d = freshDir("render", "furnace");
  CmdResult r = run(std::string(kSmall) + " -o out", d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("on llvmpipe"), std::string::npos) << r.out;
  for (const char* row : {"kulla-conty", "single-table", "dielectric-lambert", "single"}) {
    std::smatch m = rowLine(r.out, row);
    if (m.empty()) continue;
    EXPECT_EQ(m[6].str(), "0") << row << ": pixels over their bound\n" << r.out;
  }
  // Kulla-Conty from the albedo and albedo-avg tables: within 2e-3 of 1 everywhere
  std::smatch kc = rowLine(r.out, "kulla-conty");
  ASSERT_FALSE(kc.empty()) << "no kulla-conty row\n" << r.out;
  EXPECT_LT(std::stod(kc[3].str()), 2e-3) << r.out;
  // single scattering against the reference's E(mu, r): within 1e-2 at every sampled pixel
  std::smatch single = rowLine(r.out, "single");
  ASSERT_FALSE(single.empty()) << "no single row\n" << r.out;
  EXPECT_LT(std::stod(single[3].str()), 1e-2) << r.out;

  const brdfbake::TableImage img = brdfbake::readTableExr((d / "out/furnace.exr").string());
  ASSERT_EQ(img.width, 6 * 24);
  ASSERT_EQ(img.height, 7 * 24);
  auto at = [&](int c, int col, int row) {  // a sphere's centre pixel
    return img.planes[c][static_cast<size_t>(row * 24 + 12) * img.width + col * 24 + 12];
  };
  EXPECT_EQ(img.planes[0][0], 1.0f) << "the background is the furnace's white";
  // single scattering: a mirror keeps its energy, rougher spheres lose more of it (at normal view
  // about 0.69 of it at r = 1, where Kulla-Conty's lobe brings it back)
  EXPECT_NEAR(at(0, 0, 0), 1.0f, 1e-4);
  EXPECT_LT(at(0, 5, 0), at(0, 3, 0));
  EXPECT_LT(at(0, 3, 0), at(0, 1, 0));
  EXPECT_LT(at(0, 5, 0), 0.5f);
  for (int col = 0; col < 6; ++col) EXPECT_NEAR(at(0, col, 1), 1.0f, 2e-3) << "kulla-conty, column " << col;
  EXPECT_LT(at(2, 3, 4), at(0, 3, 4)) << "gold reflects less blue than red";
  EXPECT_LT(at(0, 5, 5), 0.5f) << "the sheen's albedo alone";
  // rough glass (E_R + E_T at eta 1.5): all of it at r = 0, less for rough spheres, least at the rim
  EXPECT_NEAR(at(0, 0, 6), 1.0f, 1e-5);
  EXPECT_LT(at(0, 5, 6), 0.999f);
  auto rim = [&](int col, int row) {  // a pixel near a sphere's edge: mu = 0.23
    return img.planes[0][static_cast<size_t>(row * 24 + 12) * img.width + col * 24 + 12 + 10];
  };
  EXPECT_LT(rim(5, 6), at(0, 5, 6));
  EXPECT_GT(rim(5, 6), 0.2f);  // 0.36: at r = 1 single scattering loses most of a grazing view's energy
  std::smatch glass = rowLine(r.out, "glass");
  ASSERT_FALSE(glass.empty()) << "no glass row\n" << r.out;
  EXPECT_EQ(glass[6].str(), "0") << "glass off the reference's E_R + E_T, or above 1\n" << r.out;
  EXPECT_EQ(img.strings.at("render.rows"), "single,kulla-conty,single-table,dielectric-lambert,gold,sheen,glass");
  EXPECT_NE(img.strings.at("render.tables").find("tables/dielectric_ggx_smith-correlated.exr"), std::string::npos);
  EXPECT_NE(img.strings.at("render.tables").find("tables/albedo-avg_ggx_smith-correlated.exr"), std::string::npos);
  // the lobe picture: single scattering on top, the Kulla-Conty lobe added below, everywhere at
  // least as bright; at r = 1 the lobe adds more than 0.1 somewhere, at r = 0.4 less than 0.05
  const brdfbake::TableImage lobe = brdfbake::readTableExr((d / "out/lobe.exr").string());
  ASSERT_EQ(lobe.width, 3 * 24);
  ASSERT_EQ(lobe.height, 2 * 24);
  double added[3] = {0, 0, 0};
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < lobe.width; ++x) {
      const float top = lobe.planes[0][static_cast<size_t>(y) * lobe.width + x];
      const float bottom = lobe.planes[0][static_cast<size_t>(y + 24) * lobe.width + x];
      EXPECT_GE(bottom, top) << x << "," << y;
      EXPECT_GE(top, 0.0f);
      added[x / 24] = std::max(added[x / 24], static_cast<double>(bottom - top));
    }
  EXPECT_GT(added[2], 0.1) << "r = 1";
  EXPECT_LT(added[0], 0.05) << "r = 0.4";
  EXPECT_LT(added[0], added[1]);
  EXPECT_NE(r.out.find("lobe picture (directional light): the Kulla-Conty lobe adds at most"), std::string::npos)
      << r.out;
  EXPECT_TRUE(fs::exists(d / "out/lobe.png"));
  // the PNG: 8-bit RGB (IHDR at byte 16: width, height, bit depth, colour type) with an sRGB chunk
  const std::string png = bytes(d / "out/furnace.png");
  ASSERT_GT(png.size(), 33u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_EQ(static_cast<int>(png[24]), 8);
  EXPECT_EQ(static_cast<int>(png[25]), 2);
  EXPECT_NE(png.find("sRGB"), std::string::npos);
  // the PNG is the grid with a band of row names on the left and roughness on top (the EXR is the bare
  // grid): wider by the longest name, "dielectric-lambert" or a row's note, and taller by a text line
  auto be32 = [&](size_t at) {
    return (static_cast<unsigned char>(png[at]) << 24) | (static_cast<unsigned char>(png[at + 1]) << 16) |
           (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
  };
  EXPECT_GE(be32(16), 6u * 24 + 18 * 6) << "no band for the row names";
  EXPECT_GT(be32(20), 7u * 24) << "no band for the roughness";
}

// The default render's bounds come from the texels each pixel's lookups read: tight enough that the
// Kulla-Conty row's are at most 0.01 (a 10% weaker lobe is off by up to 0.0675) and the single row's
// at most 0.02, while every pixel holds them; the table says which rows test the tables.
TEST(Render, DefaultBoundsAreLocalAndTight) {
  const fs::path d = freshDir("render", "default");
  CmdResult r = run("render -o out", d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  for (const char* row : {"single", "kulla-conty", "glass", "single-table", "dielectric-lambert"}) {
    std::smatch m = rowLine(r.out, row);
    ASSERT_FALSE(m.empty()) << row << "\n" << r.out;
    EXPECT_EQ(m[6].str(), "0") << row << "\n" << r.out;
    EXPECT_EQ(m[2].str(), std::string(row) == "single-table" || std::string(row) == "dielectric-lambert"
                              ? "algebra only"
                              : "the tables")
        << row << "\n"
        << r.out;
  }
  EXPECT_LE(std::stod(rowLine(r.out, "kulla-conty")[5].str()), 0.01) << r.out;
  EXPECT_LE(std::stod(rowLine(r.out, "single")[5].str()), 0.02) << r.out;
  // the glass row against the reference: the 16 r rows' clamp at r = 1 is up to 0.04 off, and seen
  EXPECT_GT(std::stod(rowLine(r.out, "glass")[3].str()), 0.01) << r.out;
  EXPECT_NE(r.out.find("\ngold                no        nothing (looks)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"algebra only\": the row is 1 by construction whatever the tables hold"), std::string::npos)
      << r.out;
}

// A compensation lobe at 90% of its strength does not conserve: the measurement says so, exit 1.
TEST(Render, ABrokenCompensationFailsTheMeasurement) {
  const fs::path d = freshDir("render", "broken");
  CmdResult r = run("render --rows kulla-conty -o out", d.string(), "BRDFBAKE_TEST_RENDER_LOBE_SCALE=0.9");
  EXPECT_EQ(r.code, 1) << r.out;
  std::smatch m = rowLine(r.out, "kulla-conty");
  ASSERT_FALSE(m.empty()) << "no kulla-conty row\n" << r.out;
  // the row docs/reports.md quotes: its largest deviation and the pixels over their bound
  std::printf("the Kulla-Conty lobe at 0.9 of its strength:%s", m[0].str().c_str());
  EXPECT_NE(m[6].str(), "0") << r.out;
  EXPECT_NE(r.out.find("FAIL: a row's pixels are off by more than the tables predict"), std::string::npos) << r.out;
}

// Another pair: the rows and the lobe are that pair's, measured the same way (single against the
// reference's E of beckmann + smith).
TEST(Render, AnyMicrofacetPair) {
  const fs::path d = freshDir("render", "pair");
  CmdResult r =
      run(std::string(kSmall) + " --ndf beckmann --gaf smith --rows single,kulla-conty,glass -o out", d.string());
  ASSERT_EQ(r.code, 0) << r.out;
  EXPECT_NE(r.out.find("beckmann + smith"), std::string::npos) << r.out;
  for (const char* row : {"single", "kulla-conty", "glass"}) {
    std::smatch m = rowLine(r.out, row);
    ASSERT_FALSE(m.empty()) << "no " << row << " row\n" << r.out;
    EXPECT_EQ(m[6].str(), "0") << row << "\n" << r.out;
  }
  const brdfbake::TableImage img = brdfbake::readTableExr((d / "out/furnace.exr").string());
  EXPECT_EQ(img.height, 3 * 24);
  EXPECT_NE(img.strings.at("render.tables").find("tables/albedo_beckmann_smith.exr"), std::string::npos);
}

TEST(Render, NoEglOrBadOptionsWriteNothing) {
  const fs::path d = freshDir("render", "refused");
  CmdResult r = run("render -o out", d.string(), "BRDFBAKE_EGL_LIBRARY=/nonexistent/libEGL.so.1");
  EXPECT_EQ(r.code, 69) << r.out;
  EXPECT_NE(r.out.find("render: no EGL library (/nonexistent/libEGL.so.1): install Mesa's EGL and GLES (Debian: "
                       "apt-get install libegl1 libegl-mesa0 libgles2 libgl1-mesa-dri)"),
            std::string::npos)
      << r.out;
  struct Case {
    std::string args, says;
  } cases[] = {
      {"--cell 8", "--cell: pixels per sphere, 16..256, got 8"},
      {"--columns 40", "--columns: roughness steps, 2..33, got 40"},
      {"--rows single,glod", "--rows: unknown row 'glod' (did you mean 'gold'?); valid: single, kulla-conty"},
      {"--cell x", "--cell: expected an integer, 16..256 (pixels per sphere), got 'x'"},
      {"--table albedo", "--table: not a render option"},
      {"--ndf charlie", "--ndf: render shades ggx, beckmann, blinn-phong or gaussian"},
      {"--ndf ggx,beckmann", "--ndf: render shades one pair; give one name, got 'ggx,beckmann'"},
      {"--ndf ggx --gaf charlie-smith", "charlie-smith"},
      {"--ndf blinn-phong --gaf smith --rows glass", "--rows: the glass row takes --ndf ggx or beckmann"},
  };
  for (const Case& c : cases) {
    r = run("render " + c.args + " -o out", d.string());
    EXPECT_EQ(r.code, 64) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.says), std::string::npos) << c.args << "\n" << r.out;
  }
  EXPECT_FALSE(fs::exists(d / "out"));
}
