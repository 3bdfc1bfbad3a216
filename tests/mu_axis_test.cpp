// --mu-axis linear|sqrt: the split sum's and albedo's x texels spaced in mu or in u = sqrt(mu), as
// Unity HDRP's newer pre-integrated FGD samples it. The option's errors (exit 64, nothing written),
// brdf.mu.index in every format and in `brdfbake info`, the generated GLSL/HLSL applying sqrt(mu)
// from every format's metadata, the texels at mu = u^2 end to end, the layout preset's grid and
// axis, and the interpolation-error estimate against a dense evaluation of the kernel for 64^2
// tables on both axes (the figures the README gives).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "tables/microfacet/microfacet.h"
#include "tables/interp_estimate.h"
#include "cli_run.h"
#include "doc_figures.h"
#include "common/brdf_host.h"
#include "brdfbake/table_kind.h"
#include "formats/exr/table_file.h"
#include "formats/readers/table_reader.h"
#include "reference/reference.h"
#include "test_device.h"

namespace fs = std::filesystem;
namespace {
using namespace brdfbake;
using namespace brdfbake::testing_cli;

bool sqrtIndex(const TableImage& t) {
  auto it = t.strings.find("brdf.mu.index");
  return it != t.strings.end() && it->second.rfind("sqrt", 0) == 0;
}

TEST(MuAxis, BadValuesAndTablesWithoutTheAxisExit64WritingNothing) {
  const fs::path d = freshDir("mu", "bad", false);
  const std::string o = " -o '" + (d / "o").string() + "'";
  const std::pair<std::string, std::string> cases[] = {
      {"--mu-axis diagonal", "--mu-axis must be linear (x = mu, the default) or sqrt"},
      {"--mu-axis", "--mu-axis: missing value"},
      {"--mu-axis sqrt --mu-axis linear", "--mu-axis given twice"},
      {"--mu-axis sqrt --table kp", "--mu-axis sqrt: --table kp has no (mu, r) x axis"},
      {"--mu-axis sqrt --table splitsum,albedo-avg", "--table albedo-avg has no (mu, r) x axis"},
      {"--mu-axis sqrt --table fresnel-avg --fresnel dielectric", "--table fresnel-avg has no (mu, r) x axis"},
      {"--mu-axis sqrt --table brdf3d", "--table brdf3d has no (mu, r) x axis"},
      {"--mu-axis sqrt --table dielectric", "--table dielectric has no (mu, r) x axis"},
      {"--mu-axis sqrt --table splitsum --diffuse burley", "--diffuse burley: the diffuse albedo is baked on a linear"},
      {"--mu-axis sqrt --diffuse oren-nayar", "linear mu axis only (accepted: --mu-axis linear)"},
      {"--mu-axis sqrt --brdf merl:none.binary", "a measured material (--brdf merl:) is tabulated on a linear"},
      {"--preset gltf --mu-axis sqrt", "--preset gltf bakes what glTF samples, on a linear mu axis"},
      {"--layout unity-hdrp-sqrt --grid texel-center", "--layout unity-hdrp-sqrt samples a node grid"},
      {"--layout unity-hdrp-sqrt --mu-axis linear", "--layout unity-hdrp-sqrt samples x = sqrt(NdotV)"},
      {"--layout unity-hdrp --mu-axis sqrt", "--layout unity-hdrp samples x = NdotV"},
      {"--layout filament --grid node", "--layout filament samples a texel-center grid"},
      {"energy --mu-axis sqrt", "--mu-axis: not an energy option"},
      {"verify --mu-axis sqrt", "--mu-axis: not a verify option"},
      {"convergence --mu-axis sqrt", "--mu-axis: not a convergence option"},
      {"stress --mu-axis sqrt", "--mu-axis: not a stress option"},
  };
  for (const auto& [args, msg] : cases) {
    CmdResult r = run(args + o);
    EXPECT_EQ(r.code, 64) << args << "\n" << r.out;
    EXPECT_NE(r.out.find(msg), std::string::npos) << args << "\n" << r.out;
    EXPECT_FALSE(fs::exists(d)) << args;
  }
  // linear is the default: accepted wherever (the tables with no mu axis are unaffected)
  CmdResult help = run("--help");
  EXPECT_NE(help.out.find("--mu-axis A"), std::string::npos);
  EXPECT_NE(help.out.find("unity-hdrp-sqrt"), std::string::npos);
}

// The option's default tables are the two over (mu, r); every format states the axis, info prints
// it, and the generated code of every format takes sqrt(mu) as the EXR's does.
TEST(MuAxis, EveryFormatStatesItAndShaderCodeAppliesIt) {
  const fs::path d = freshDir("mu", "formats");
  ASSERT_EQ(run("--mu-axis sqrt --size 8 -o '" + (d / "def").string() + "'").code, 0);
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(d / "def")) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"albedo_ggx_smith-correlated.exr", "splitsum_ggx_smith-correlated.exr"}));

  CmdResult r = run("--mu-axis sqrt --table splitsum,albedo --size 8 --format exr,ktx2,dds,png16,header -o '" +
                    (d / "all").string() + "'");
  ASSERT_EQ(r.code, 0) << r.out;
  for (const std::string table : {"splitsum", "albedo"}) {
    const std::string stem = (d / "all" / (table + "_ggx_smith-correlated")).string();
    const std::string exrGlsl = run("shader --lang glsl '" + stem + ".exr'").out;
    const std::string exrHlsl = run("shader --lang hlsl '" + stem + ".exr'").out;
    for (const std::string ext : {".exr", ".ktx2", ".dds", ".png", ".h", ".mjs"}) {
      const std::string f = stem + ext;
      EXPECT_TRUE(sqrtIndex(tableMetadata(f))) << f;
      // info prints it (a DDS, which has no metadata, names the twin that holds it)
      CmdResult info = run("info '" + f + "'");
      EXPECT_EQ(info.code, 0) << f;
      if (ext == std::string(".dds")) {
        EXPECT_NE(info.out.find(stem + ".ktx2 beside it holds this table's"), std::string::npos) << info.out;
      } else {
        EXPECT_NE(info.out.find("brdf.mu.index"), std::string::npos) << f << "\n" << info.out;
        EXPECT_NE(info.out.find("sqrt (x = sqrt(mu): texel i holds mu = x_i^2)"), std::string::npos) << f;
      }
      for (bool hlsl : {false, true}) {
        CmdResult code = run(std::string("shader --lang ") + (hlsl ? "hlsl" : "glsl") + " '" + f + "'");
        ASSERT_EQ(code.code, 0) << f << code.out;
        // the coordinate map, line for line the EXR's
        auto tLine = [](const std::string& s) {
          size_t at = s.find("t = clamp(");
          return at == std::string::npos ? std::string() : s.substr(at, s.find('\n', at) - at);
        };
        EXPECT_NE(tLine(code.out).find("sqrt(max(x, 0.0))"), std::string::npos) << f << "\n" << code.out;
        EXPECT_EQ(tLine(code.out), tLine(hlsl ? exrHlsl : exrGlsl)) << f;
        EXPECT_NE(code.out.find("mu index sqrt"), std::string::npos) << f;
      }
    }
  }
  // a linear table states it too, and its code has no sqrt
  ASSERT_EQ(run("--table albedo --size 4 -o '" + (d / "lin").string() + "'").code, 0);
  const std::string lin = (d / "lin" / "albedo_ggx_smith-correlated.exr").string();
  EXPECT_EQ(readTableExrHeader(lin).strings["brdf.mu.index"], "linear (x = mu)");
  EXPECT_EQ(run("shader --lang glsl '" + lin + "'").out.find("sqrt"), std::string::npos);
}

// A file whose brdf.mu.index the code generator cannot follow: 65, naming the field and the values.
TEST(MuAxis, UnknownIndexInAFileExits65) {
  const fs::path d = freshDir("mu", "unknown");
  ASSERT_EQ(run("--table albedo --size 4 --format header -o '" + d.string() + "'").code, 0);
  const fs::path h = d / "albedo_ggx_smith-correlated.h";
  std::string text = bytes(h);
  const std::string from = "linear (x = mu)", to = "cubic (x = mu^3)";  // every copy: comments and the table
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  std::ofstream(h, std::ios::binary) << text;
  CmdResult r = run("shader --lang glsl '" + h.string() + "'");
  EXPECT_EQ(r.code, 65) << r.out;
  EXPECT_NE(r.out.find("brdf.mu.index 'cubic (x = mu^3)' is not one brdfbake reads: linear or sqrt"), std::string::npos)
      << r.out;
}

// End to end: texel i of a 5-node sqrt table holds the table at mu = (i/4)^2, which a 17-node linear
// table holds at texel 16 (i/4)^2 = i^2 (r: j/4 = 4j/16): the same quadrature at the same point.
TEST(MuAxis, SqrtTexelsHoldTheTableAtMuSquared) {
  const fs::path d = freshDir("mu", "texels");
  ASSERT_EQ(run("--mu-axis sqrt --grid node --size 5 -o '" + (d / "sq").string() + "'").code, 0);
  ASSERT_EQ(run("--table splitsum,albedo --grid node --size 17 -o '" + (d / "lin").string() + "'").code, 0);
  for (const std::string f : {"splitsum_ggx_smith-correlated.exr", "albedo_ggx_smith-correlated.exr"}) {
    TableImage sq = readTableExr((d / "sq" / f).string()), lin = readTableExr((d / "lin" / f).string());
    EXPECT_TRUE(sqrtIndex(sq));
    EXPECT_EQ(sq.strings["brdf.grid"], "node");
    for (size_t c = 0; c < 3; ++c)
      for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i)
          EXPECT_NEAR(sq.planes[c][j * 5 + i], lin.planes[c][(4 * j) * 17 + i * i], 2e-6)
              << f << " channel " << c << " u = " << i / 4.0 << " r = " << j / 4.0;
  }
  // the preset: HDRP's node grid and sqrt axis, 64^2 float16 EXR, (B, A + B)
  ASSERT_EQ(run("--layout unity-hdrp-sqrt -o '" + (d / "hdrp").string() + "'").code, 0);
  TableImage h = readTableExrHeader((d / "hdrp" / "splitsum_ggx_smith-correlated_unity-hdrp-sqrt.exr").string());
  EXPECT_TRUE(sqrtIndex(h));
  EXPECT_EQ(h.strings["brdf.grid"], "node");
  EXPECT_EQ(h.width, 64);
  EXPECT_EQ(h.strings["brdf.channels"], "R=B,G=A+B");
  EXPECT_EQ(std::distance(fs::directory_iterator(d / "hdrp"), fs::directory_iterator()), 1);
}

// The estimator differences texel to texel: a function linear in sqrt(mu) has no interpolation
// error on a sqrt axis, and a large one on a linear axis (where sqrt(mu) is steep at grazing).
TEST(MuAxis, EstimateTakesTheTablesOwnSpacing) {
  const int n = 32;
  TableImage lin, sq;
  for (TableImage* t : {&lin, &sq}) {
    t->width = n;
    t->height = 2;
    t->planes.assign(1, std::vector<float>(2 * n));
  }
  for (int y = 0; y < 2; ++y)
    for (int i = 0; i < n; ++i) {
      const double c = (i + 0.5) / n;                               // texel centre of the axis
      lin.planes[0][y * n + i] = static_cast<float>(std::sqrt(c));  // sqrt(mu) at mu = c
      sq.planes[0][y * n + i] = static_cast<float>(c);              // sqrt(mu) at mu = c^2
    }
  EXPECT_LT(estimateInterpolation(sq, false).interior, 1e-7);
  EXPECT_GT(estimateInterpolation(lin, false).interior, 0.005);
}

// 64^2 tables, linear and sqrt axis, texel centres and nodes: the lookup (u = sqrt(mu) on the sqrt
// axis, then bilinear, as the generated code does) against the kernel evaluated densely (a 512^2
// node grid in sqrt(mu): every mu cell of the linear table holds >= 4 of its points, grazing far
// more), max over A, B and A + B relative to max(1, |v|). The kernel's own error (~1e-5) is far
// below the interpolation errors measured. Regions: mu < 0.1 with r < 0.05 (the corner), 0.05 <= r
// < 0.2 and r >= 0.2; mu >= 0.1. Near the corner E dips where mu ~ alpha = r^2 (to 0.892 at mu =
// alpha, the reference agrees) between edges that hold 1: a wedge narrower than a texel there,
// which no grid resolves and the estimate from the texels does not see; the bake's probes between
// texels measure it (host/tables/interp_probe.h), so brdf.interp-error holds in every region. The sqrt
// axis spaces u = sqrt(mu) like r, so the wedge mu ~ r^2 (u ~ r) is resolved from r ~ 0.05 on; on a
// linear axis only from r ~ 0.2.
TEST(MuAxis, InterpolationEstimateHoldsOnBothAxes) {
  KernelRunner& k = testing_device::runner();
  const int dense = 512, n = 64;
  KernelTable truth = k.hemisphere(NDF_GGX, GAF_SMITH_CORRELATED, dense, dense, true, {}, true);
  // the dip is the BRDF's, not the kernel's: the independent reference at mu = alpha, r = 0.0313
  const double dip = reference::albedo(NDF_GGX, GAF_SMITH_CORRELATED, 0.0313, 0.0313 * 0.0313).e();
  EXPECT_NEAR(dip, 0.892, 0.001);
  std::printf("the corner's dip: the reference's E at mu = alpha, r = 0.0313: %.4f\n", dip);
  std::printf("64^2 ggx + smith-correlated split sums: lookup vs the kernel at %d^2 points, max over A, B, A+B\n",
              dense);
  // the table docs/layouts.md shows
  std::string table =
      "| x axis, grid | mu < 0.1, r < 0.05 | mu < 0.1, 0.05 <= r < 0.2 | mu < 0.1, r >= 0.2 | mu >= 0.1 | "
      "`brdf.interp-error` (`.interior`) |\n|---|---|---|---|---|---|\n";
  double band[2][2][4] = {};  // [node][sqrt][region]
  for (bool node : {false, true})
    for (bool sq : {false, true}) {
      TableJob job =
          TableJob::of(TableKind::SplitSum).forPair(NDF_GGX, GAF_SMITH_CORRELATED).texels(n, n).onNodeGrid(node);
      job.muSqrt = sq;
      double secs = 0;
      TableImage t = computeTable(k, job, &secs);
      ASSERT_EQ(sqrtIndex(t), sq);
      auto lookup = [&](int c, double mu, double r) {
        const double tx = sq ? std::sqrt(mu) : mu;
        const double px = std::clamp(node ? tx * (n - 1) : tx * n - 0.5, 0.0, n - 1.0);
        const double py = std::clamp(node ? r * (n - 1) : r * n - 0.5, 0.0, n - 1.0);
        const int x0 = std::min(static_cast<int>(px), n - 2), y0 = std::min(static_cast<int>(py), n - 2);
        const double fx = px - x0, fy = py - y0;
        auto at = [&](int x, int y) { return static_cast<double>(t.planes[c][static_cast<size_t>(y) * n + x]); };
        return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
               fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
      };
      double* worst = band[node][sq];
      for (int j = 0; j < dense; ++j)
        for (int i = 0; i < dense; ++i) {
          const double u = static_cast<double>(static_cast<float>(i) / (dense - 1));
          const double mu = static_cast<double>(static_cast<float>(u * u));
          const double r = static_cast<double>(static_cast<float>(j) / (dense - 1));
          const size_t x = static_cast<size_t>(j) * dense + i;
          const int reg = mu >= 0.1 ? 3 : r < 0.05 ? 0 : r < 0.2 ? 1 : 2;
          for (int c = 0; c < 3; ++c)
            worst[reg] = std::max(worst[reg], testing_device::rel(lookup(c, mu, r), truth.planes[c][x]));
        }
      const double err = t.floats["brdf.error"], est = t.floats["brdf.interp-error"];
      const double interior = t.floats["brdf.interp-error.interior"];
      char row[200];
      std::snprintf(row, sizeof row, "| %s, %s | %.3g | %.3g | %.3g | %.3g | %.3g (%.3g) |\n", sq ? "sqrt" : "linear",
                    node ? "node" : "texel-center", worst[0], worst[1], worst[2], worst[3], est, interior);
      table += row;
      const std::string which = std::string(sq ? "sqrt" : "linear") + (node ? " node" : " texel-center");
      // the whole claim holds everywhere, the corner's wedge included (the bake probes it between
      // texels: host/tables/interp_probe.h); away from grazing the estimate from the texels is the
      // whole story, and the probe's figure is what the lookups near the corner really miss
      for (int reg = 0; reg < 4; ++reg) EXPECT_LE(worst[reg], err + est) << which << ", region " << reg;
      EXPECT_LE(worst[3], err + interior) << which << ": away from grazing the interior term is the whole story";
      const double probe = t.floats["brdf.interp-error.probe"];
      EXPECT_GE(probe, 0.5 * std::max(worst[0], worst[1])) << which << ": the probes find the wedge";
    }
  // the trade: at grazing (mu < 0.1, 0.05 <= r < 0.2) the sqrt axis is over ten times closer; inside alike
  for (bool node : {false, true}) {
    EXPECT_LT(10 * band[node][1][1], band[node][0][1]) << (node ? "node" : "texel-center");
    EXPECT_LT(band[node][1][3], 1.5 * band[node][0][3]) << (node ? "node" : "texel-center");
  }
  std::printf("%s", table.c_str());
  testing_docs::expectPagesQuote(table);
}

}  // namespace
