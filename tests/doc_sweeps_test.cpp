// The pages' figures that come from runs of minutes: each test here runs the commands a page names
// (the benchmark, a bake, a tool script, a whole test binary), prints what the page quotes, and
// calls expectPagesQuote, so that every figure tied to it ("in: Docs.DISABLED_...") is checked
// against a fresh run. They are disabled in the binary and run by ctest under the `sweep` label
// (tests/CMakeLists.txt names each, with its time on two cores), which the README's test command
// leaves out: `ctest -L sweep` runs them. A tool script of seconds (tools/node_counts.sh) is run
// the same way by a test in the suite.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <initializer_list>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_run.h"
#include "doc_figures.h"

namespace fs = std::filesystem;
using namespace brdfbake::testing_cli;
using namespace brdfbake::testing_docs;

namespace {

// `command` run in `dir`; it must exit 0. Its output, printed.
std::string runOk(const fs::path& dir, const std::string& command) {
  const CmdResult r = shell("cd '" + dir.string() + "' && " + command);
  std::printf("$ %s\n%s", command.c_str(), r.out.c_str());
  EXPECT_EQ(r.code, 0) << command;
  return r.out;
}

const std::string kBench = "'" BRDFBAKE_BINARY_DIR "/brdfbake-bench'";

// Every line of `text` with `label` in front: two runs of one benchmark print the same lines, and
// a page names the run a figure comes from by its label.
std::string labelled(const std::string& label, const std::string& text) {
  std::string out;
  for (const std::string& l : lines(text)) out += label + l + "\n";
  return out;
}

// `brdfbake-bench --bounds ARGS` for each ARGS in turn, in one scratch directory: each must find no
// texel over its claim. Their outputs, one after the other.
std::string boundsRuns(const std::string& name, std::initializer_list<const char*> runs) {
  const fs::path d = freshDir("readme", name);
  std::string printed;
  for (const char* args : runs) {
    const std::string out = runOk(d, kBench + " --bounds" + args);
    EXPECT_NE(out.find("\n0 texels over their claimed bound"), std::string::npos) << args;
    printed += out;
  }
  return printed;
}

// One row of the per-pair tables that `--all-pairs` and `--albedo-avg` print:
// "ndf gaf max-error max-claim over".
struct PairRow {
  std::string ndf, gaf;
  double error, claim;
  int over;
};

std::vector<PairRow> pairRows(const std::string& out) {
  static const std::regex row("^(\\S+) +(\\S+) +(\\d\\.\\d+e[-+]\\d+) +(\\d\\.\\d+e[-+]\\d+) +(\\d+)$");
  std::vector<PairRow> rows;
  for (const std::string& l : lines(out)) {
    std::smatch m;
    if (std::regex_match(l, m, row))
      rows.push_back({m[1], m[2], std::strtod(m[3].str().c_str(), nullptr), std::strtod(m[4].str().c_str(), nullptr),
                      std::atoi(m[5].str().c_str())});
  }
  return rows;
}

// The pages speak of three kinds of pair: the GAFs with breaks of their own (none, cook-torrance,
// kelemen, neumann), blinn-phong's and the gaussian's tabulated exact Lambda, and the rest (the
// sharpened estimates).
const char* kindOf(const PairRow& p) {
  if (p.gaf == "none" || p.gaf == "cook-torrance" || p.gaf == "kelemen" || p.gaf == "neumann") return "gaf breaks";
  if ((p.ndf == "blinn-phong" || p.ndf == "gaussian") && p.gaf.size() > 6 &&
      p.gaf.compare(p.gaf.size() - 6, 6, "-exact") == 0)
    return "tabulated Lambda";
  return "sharpened";
}

// Per kind: "KIND: claims A to B, claim / error C to D (largest ratio: NDF + GAF, CLAIM against ERROR)",
// then the claims of every pair but the tabulated Lambda's, and the largest error with its pair.
// Every row must have no value over its claim.
std::string pairSummary(const std::vector<PairRow>& rows) {
  std::string said;
  for (const char* kind : {"sharpened", "gaf breaks", "tabulated Lambda"}) {
    double lo = INFINITY, hi = 0, rlo = INFINITY, rhi = 0;
    const PairRow* top = nullptr;
    for (const PairRow& p : rows) {
      if (std::strcmp(kindOf(p), kind) != 0) continue;
      lo = std::min(lo, p.claim), hi = std::max(hi, p.claim);
      const double ratio = p.claim / p.error;
      rlo = std::min(rlo, ratio);
      if (ratio > rhi) rhi = ratio, top = &p;
    }
    if (!top) continue;
    say(said, "%s: claims %s to %s, claim / error %.1f to %.1f (largest ratio: %s + %s, %s against %s)\n", kind,
        sci(lo, 2).c_str(), sci(hi, 2).c_str(), rlo, rhi, top->ndf.c_str(), top->gaf.c_str(),
        sci(top->claim, 2).c_str(), sci(top->error, 2).c_str());
  }
  double lo = INFINITY, hi = 0;
  const PairRow* worst = nullptr;
  for (const PairRow& p : rows) {
    EXPECT_EQ(p.over, 0) << p.ndf << " + " << p.gaf;
    if (std::strcmp(kindOf(p), "tabulated Lambda") != 0) lo = std::min(lo, p.claim), hi = std::max(hi, p.claim);
    if (!worst || p.error > worst->error) worst = &p;
  }
  if (worst) {
    say(said, "every pair but the tabulated Lambda's: claims %s to %s\n", sci(lo, 2).c_str(), sci(hi, 2).c_str());
    say(said, "largest error %s: %s + %s\n", sci(worst->error, 2).c_str(), worst->ndf.c_str(), worst->gaf.c_str());
  }
  return said;
}

}  // namespace

// docs/accuracy.md's bounds tables are the benchmark's: `brdfbake-bench --bounds --stride 4` (every
// table of the default set as brdfbake bakes it and four other pairs against the reference, about 3
// minutes on two cores; then five pairs of the GAFs with breaks of their own, about 2 minutes)
// prints them as markdown rows, and the page's rows must be among them, with no texel over its
// claim. Behind the `sweep` label (BoundsSweep.TheBenchmarksTableIsThePages).
TEST(Docs, DISABLED_BoundsTableIsTheBenchmarks) {
  // the default set's pairs, then five of the pairs whose GAFs need their own breaks (the page's
  // second table)
  expectPagesQuote(boundsRuns("bounds", {" --stride 4",
                                         " --stride 4 --pair ggx+cook-torrance --pair ggx+kelemen --pair ggx+neumann"
                                         " --pair ggx+none --pair beckmann+cook-torrance"}));
}

// docs/accuracy.md's runs of the bounds benchmark on other strides: every texel of four pairs'
// tables (`--stride 1`, about 4 minutes on two cores) and every 8th of three pairs whose arcs are
// not graded towards the horizon (`--stride 8`, about 4 minutes). Their pairs differ, so each row
// is printed once; no texel may be over its claim (StrideSweep.TheBenchmarksFiguresAreThePages).
TEST(Docs, DISABLED_StrideRunsAreTheBenchmarks) {
  expectPagesQuote(boundsRuns("strides", {" --stride 1 --pair ggx+smith-correlated --pair ggx+schlick-ggx"
                                          " --pair ggx+kelemen --pair beckmann+schlick-ggx-direct",
                                          " --stride 8 --pair ggx+cook-torrance --pair beckmann+none"
                                          " --pair gaussian+neumann"}));
}

// `brdfbake-bench ARGS`, a run that prints one row per pair (`--all-pairs`, `--albedo-avg`): all 52
// microfacet pairs' rows, its line saying none is over its claim, and the summary the pages quote.
std::string pairBenchSummary(const std::string& name, const std::string& args, const std::string& noneOver) {
  const std::string out = runOk(freshDir("readme", name), kBench + args);
  const std::vector<PairRow> rows = pairRows(out);
  EXPECT_EQ(rows.size(), 52u);
  EXPECT_NE(out.find(noneOver), std::string::npos);
  return pairSummary(rows);
}

// docs/accuracy.md's figures for all 52 microfacet pairs' split sums, every 8th texel and every edge
// texel against the reference (`brdfbake-bench --all-pairs --stride 8`): the claims and their ratios
// to the largest error per kind of pair (AllPairsSweep.TheBenchmarksFiguresAreThePages).
TEST(Docs, DISABLED_AllPairsFiguresAreTheBenchmarks) {
  expectPagesQuote(pairBenchSummary("all-pairs", " --all-pairs --stride 8", ", 0 texels over their bound"));
}

// docs/accuracy.md's figures for every non-sheen pair's default 32-entry albedo-avg table against the
// reference at 10 of its r (`brdfbake-bench --albedo-avg`), summarised per kind of pair
// (AlbedoAvgSweep.TheBenchmarksFiguresAreThePages).
TEST(Docs, DISABLED_AlbedoAvgFiguresAreTheBenchmarks) {
  expectPagesQuote(pairBenchSummary("albedo-avg", " --albedo-avg", ", 0 values over their claim"));
}

// docs/rough-glass.md's figures: the rough dielectric's table against the reference and against
// Monte Carlo (`brdfbake-bench --dielectric`), dielectric-avg's claim against the same rule run
// tight (`--dielectric-avg`, for ggx + smith-correlated and beckmann + smith: each line labelled by
// its pair), and the default 32^3 dielectric and 16^2 dielectric-avg bakes' claims
// (GlassSweep.TheBenchmarksFiguresAreThePages).
TEST(Docs, DISABLED_GlassFiguresAreTheBenchmarks) {
  const fs::path d = freshDir("readme", "glass");
  std::string printed = runOk(d, kBench + " --dielectric");
  printed += labelled("ggx+smith-correlated: ", runOk(d, kBench + " --dielectric-avg"));
  printed += labelled("beckmann+smith: ", runOk(d, kBench + " --dielectric-avg --pair beckmann+smith"));
  printed += runOk(d, "'" BRDFBAKE_EXE "' bake --table dielectric -o glass32");
  printed +=
      runOk(d, "'" BRDFBAKE_EXE "' bake --table dielectric-avg --ndf ggx --gaf smith-correlated --size 16 -o avg16");
  printed += runOk(d, "'" BRDFBAKE_EXE "' info avg16/dielectric-avg_ggx_smith-correlated.exr");
  expectPagesQuote(printed);
}

// The largest misses of the sharpened estimates and the largest use of the float model that
// docs/accuracy.md and docs/reports.md quote are the maxima over every test of
// brdfbake-accuracy-tests, which a run of the whole binary in one process prints at its end (ctest
// runs its tests one by one, each seeing only its own)
// (AccuracySweep.TheWholeRunsMissesAreThePages).
TEST(Docs, DISABLED_AccuracyMissesAreTheWholeRuns) {
  const fs::path d = freshDir("readme", "accuracy");
  const std::string out = runOk(d, "'" BRDFBAKE_BINARY_DIR "/tests/brdfbake-accuracy-tests'");
  const size_t at = out.rfind("\nwhole run: ");
  ASSERT_NE(at, std::string::npos) << "no \"whole run:\" line at the end";
  expectPagesQuote(out.substr(at + 1, out.find('\n', at + 1) - at));
}

// docs/performance.md's figures from tools/outer_breaks.sh: the hemisphere rule with other outer
// breaks, compiled for the host in double (needs g++; under a minute on one core):
// OuterBreaksSweep.TheScriptsFiguresAreThePages.
TEST(Docs, DISABLED_OuterBreaksFiguresAreTheScripts) {
  const fs::path d = freshDir("readme", "outer-breaks");
  expectPagesQuote(runOk(d, "'" BRDFBAKE_SOURCE_DIR "/tools/outer_breaks.sh'"));
}

// docs/performance.md's node counts from tools/node_counts.sh: the default split sum's rule
// compiled for the host in float and counted by gcov (needs g++ and gcov; seconds), in the suite.
TEST(Docs, NodeCountsFiguresAreTheScripts) {
  const fs::path d = freshDir("readme", "node-counts");
  expectPagesQuote(runOk(d, "'" BRDFBAKE_SOURCE_DIR "/tools/node_counts.sh'"));
}

// docs/merl.md's two claim tables are the MERL benchmark's: four analytic materials written as MERL
// files by `brdfbake bake --table brdf3d --format merl`, each run through `brdfbake-bench --merl
// FILE` (the albedo table at 16 texel centres and the albedo-avg table baked as brdfbake bakes them,
// against rules above their ladders). The test prints each table's rows as markdown, and the page's
// rows must be among them, every claim at or above its error. 15 to 20 minutes on two cores, behind
// the `sweep` label (MerlSweep.TheBenchmarksTablesAreThePages).
TEST(Docs, DISABLED_MerlTablesAreTheBenchmarks) {
  struct Material {
    const char* label;
    const char* args;
  };
  const Material materials[] = {
      {"ggx r 0.3", "--roughness 0.3 --fresnel schlick --f0 0.04"},
      {"ggx r 0.8", "--roughness 0.8 --fresnel schlick --f0 0.04"},
      {"r 0.5 + Lambert, coloured",
       "--roughness 0.5 --fresnel schlick --f0 0.9,0.6,0.3 --diffuse lambert --rho 0.2,0.5,0.8"},
      {"beckmann r 0.15", "--ndf beckmann --gaf smith --roughness 0.15"},
  };
  const fs::path d = freshDir("readme", "merl-bench");
  std::string albedoRows, avgRows;
  for (size_t m = 0; m < std::size(materials); ++m) {
    const std::string dir = "m" + std::to_string(m);
    const CmdResult bake = shell("cd '" + d.string() + "' && '" BRDFBAKE_EXE "' bake --table brdf3d --format merl " +
                                 materials[m].args + " -o " + dir + " 2>&1");
    ASSERT_EQ(bake.code, 0) << bake.out;
    const CmdResult r =
        shell("cd '" + d.string() + "' && '" BRDFBAKE_BINARY_DIR "/brdfbake-bench' --merl " + dir + "/*.binary 2>&1");
    std::printf("%s: %s", materials[m].label, r.out.c_str());
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("\nevery claim holds"), std::string::npos) << r.out;
    for (const char* table : {"albedo", "albedo-avg"}) {
      const size_t at = r.out.find(std::string("\n") + table + " ");
      ASSERT_NE(at, std::string::npos) << "no " << table << " line in\n" << r.out;
      // table, seconds, brdf.error, largest error, ratio
      const double claim = numberAfter(r.out, at + 1 + std::strlen(table), 2);
      const double error = numberAfter(r.out, at + 1 + std::strlen(table), 3);
      ASSERT_TRUE(claim > 0 && error > 0) << r.out;
      EXPECT_GE(claim, error) << materials[m].label << " " << table;
      char row[200];
      std::snprintf(row, sizeof row, "| %s | %.2e | %.2e | %.2f |\n", materials[m].label, claim, error, claim / error);
      (std::strcmp(table, "albedo") == 0 ? albedoRows : avgRows) += row;
    }
  }
  std::printf("albedo, 16 texel centres:\n%salbedo-avg:\n%s", albedoRows.c_str(), avgRows.c_str());
  expectPagesQuote(albedoRows + avgRows);
}

// docs/accuracy.md's charlie table: `brdfbake-bench --bounds --stride 4 --pair charlie+charlie-smith
// --pair charlie+neubelt --tables splitsum,albedo,kp` (about 3 minutes on two cores; the averages'
// rows take the sheen reference far longer and are not on the page). Its rows must be the page's,
// with no texel over its claim (CharlieSweep.TheBenchmarksRowsAreThePages).
TEST(Docs, DISABLED_CharlieRowsAreTheBenchmarks) {
  const fs::path d = freshDir("readme", "charlie");
  const std::string out = runOk(
      d,
      kBench + " --bounds --stride 4 --pair charlie+charlie-smith --pair charlie+neubelt --tables splitsum,albedo,kp");
  EXPECT_NE(out.find("\n0 texels over their claimed bound"), std::string::npos);
  expectPagesQuote(out);
}
