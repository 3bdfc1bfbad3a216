// The production readers (host/formats/readers) against the specification-checking readers of the
// tests (ktx2_reader.h, dds_reader.h), which stay the independent check: the same texels and the same
// key/value data for every precision, 2D and 3D; PNG and the header format against the float32 EXR
// of the same bake. And the readers on damaged input: every truncation and thousands of corrupted
// bytes give Error(kExitDataErr) or a file read, never a crash or another exception.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <cstring>
#include <random>
#include <sys/resource.h>
#include <unistd.h>

#include "cli_run.h"
#include "common/errors.h"
#include "dds_reader.h"
#include "formats/exr/table_file.h"
#include "formats/readers/table_reader.h"
#include "formats/merl.h"
#include "ktx2_reader.h"

namespace fs = std::filesystem;
namespace {

using namespace brdfbake;
using testing_cli::bytes;
using testing_cli::run;

fs::path bakeInto(const std::string& name, const std::string& args) {
  fs::path d = testing_cli::freshDir("read", name);
  testing_cli::CmdResult r = run("bake " + args + " -o '" + d.string() + "'");
  EXPECT_EQ(r.code, 0) << r.out;
  return d;
}

const char* kStems[] = {"splitsum_ggx_smith-correlated", "albedo_ggx_smith-correlated",
                        "albedo-avg_ggx_smith-correlated"};

TEST(FormatsRead, Ktx2AndDdsReadTheTexelsTheSpecificationReadersRead) {
  for (const char* precision : {"float32", "float16", "unorm16", "unorm8"}) {
    const fs::path d =
        bakeInto(std::string("spec_") + precision, std::string("--table splitsum,albedo,albedo-avg --size 12 "
                                                               "--format ktx2,dds --precision ") +
                                                       precision);
    for (const char* stem : kStems) {
      const std::string k = (d / (std::string(stem) + ".ktx2")).string(),
                        s = (d / (std::string(stem) + ".dds")).string();
      const ktx2check::Texture kc = ktx2check::read(k);
      const ddscheck::Texture dc = ddscheck::read(s);
      ASSERT_TRUE(kc.problems.empty() && dc.problems.empty()) << k;
      const TableFile kf = readTableFile(k), df = readTableFile(s);
      EXPECT_EQ(kf.format, FileFormat::Ktx2);
      EXPECT_EQ(df.format, FileFormat::Dds);
      EXPECT_EQ(precisionName(kf.precision), precision) << k;
      EXPECT_EQ(precisionName(df.precision), precision) << s;
      ASSERT_EQ(kf.table.width, static_cast<int>(kc.width));
      ASSERT_EQ(df.table.height, static_cast<int>(dc.height));
      ASSERT_EQ(static_cast<int>(kf.table.planes.size()), kc.components);
      ASSERT_EQ(static_cast<int>(df.table.planes.size()), dc.components);
      for (size_t i = 0; i < kc.texels.size(); ++i) {
        ASSERT_EQ(kf.table.planes[i % kc.components][i / kc.components], static_cast<float>(kc.texels[i]))
            << k << " " << i;
        ASSERT_EQ(df.table.planes[i % dc.components][i / dc.components], static_cast<float>(dc.texels[i]))
            << s << " " << i;
      }
      std::map<std::string, std::string> kv(kf.text.begin(), kf.text.end());
      EXPECT_EQ(kv, kc.kv) << k;
      EXPECT_EQ(kf.table.strings.at("brdf.precision"), precision);
      EXPECT_TRUE(df.text.empty()) << "DDS has no metadata";
    }
  }
}

TEST(FormatsRead, ThreeDimensionalTexturesReadSliceBySlice) {
  const fs::path d = bakeInto("volume", "--table brdf3d --size 6,5,4 --format ktx2,dds,header --precision float16");
  const std::string stem = (d / "brdf3d_ggx_smith-correlated_angles").string();
  const ktx2check::Texture kc = ktx2check::read(stem + ".ktx2");
  ASSERT_TRUE(kc.problems.empty());
  for (const char* ext : {".ktx2", ".dds", ".h", ".mjs"}) {
    const TableFile f = readTableFile(stem + ext);
    EXPECT_EQ(f.depth, 4) << ext;
    ASSERT_EQ(f.table.width, 6) << ext;
    ASSERT_EQ(f.table.height, 5) << ext;
    ASSERT_EQ(f.table.planes[0].size(), size_t{6 * 5 * 4}) << ext;
    for (size_t i = 0; i < kc.texels.size(); ++i) {
      const size_t c = i % kc.components;
      if (c >= f.table.planes.size()) continue;  // the header keeps R, G, B; KTX2 and DDS pad A = 1
      ASSERT_EQ(f.table.planes[c][i / kc.components], static_cast<float>(kc.texels[i])) << ext << " " << i;
    }
  }
}

TEST(FormatsRead, PngAndHeaderHoldTheExrsValues) {
  const fs::path d = bakeInto("png_header", "--table splitsum,albedo,kp --size 12 --format exr,png16,header");
  for (const char* stem : {"splitsum_ggx_smith-correlated", "albedo_ggx_smith-correlated", "kp_ggx"}) {
    const TableImage exr = readTableExr((d / (std::string(stem) + ".exr")).string());
    const TableFile png = readTableFile((d / (std::string(stem) + ".png")).string());
    const double scale = png.table.floats.at("brdf.mapping.scale");
    EXPECT_EQ(std::string(stem) == "kp_ggx", scale > 1) << "k_p (up to 2.77) is the table png16 scales";
    for (const char* ext : {".h", ".mjs"}) {
      const TableFile h = readTableFile((d / (std::string(stem) + ext)).string());
      ASSERT_EQ(h.table.planes.size(), exr.planes.size()) << ext;
      for (size_t c = 0; c < exr.planes.size(); ++c) EXPECT_EQ(h.table.planes[c], exr.planes[c]) << stem << ext;
    }
    ASSERT_EQ(png.table.planes.size(), exr.planes.size());
    for (size_t c = 0; c < exr.planes.size(); ++c)
      for (size_t i = 0; i < exr.planes[c].size(); ++i)
        ASSERT_NEAR(png.table.planes[c][i], exr.planes[c][i], 0.5 / 65535 * scale + 1e-7)
            << stem << " " << c << " " << i;
  }
}

// Every prefix of a file and `flips` single-byte corruptions: read, or Error(kExitDataErr).
void damage(const std::string& path, int flips) {
  const std::string whole = bytes(path);
  const std::string probe = path + ".damaged" + fs::path(path).extension().string();
  auto attempt = [&](const std::string& content, const std::string& what) {
    {
      std::ofstream out(probe, std::ios::binary | std::ios::trunc);
      out << content;
    }
    try {
      readTableFile(probe);
    } catch (const Error& e) {
      ASSERT_EQ(e.code(), kExitDataErr) << what << ": " << e.what();
      ASSERT_EQ(std::string(e.what()).rfind("cannot read " + probe + ": ", 0), 0u) << e.what();
    } catch (const std::exception& e) {
      FAIL() << what << ": " << e.what();
    }
  };
  // every prefix through the headers (the first 160 bytes), then 100 more across the file
  const size_t step = std::max<size_t>(1, whole.size() / 100);
  for (size_t n = 0; n < whole.size(); n += (n < 160 ? 1 : step))
    attempt(whole.substr(0, n), "prefix " + std::to_string(n));
  std::mt19937 rng(12);
  for (int k = 0; k < flips; ++k) {
    std::string c = whole;
    const size_t at = std::uniform_int_distribution<size_t>(0, std::min<size_t>(c.size(), 400) - 1)(rng);
    c[at] = static_cast<char>(std::uniform_int_distribution<int>(0, 255)(rng));
    attempt(c, "byte " + std::to_string(at));
  }
}

TEST(FormatsRead, DamagedFilesAreRefusedWithExit65NeverACrash) {
  const fs::path d = bakeInto("damage", "--table splitsum --size 8 --format exr,ktx2,dds,png16,header");
  for (const char* ext : {".ktx2", ".dds", ".png", ".h", ".mjs"})
    damage((d / (std::string("splitsum_ggx_smith-correlated") + ext)).string(), 250);
}

// Mutated real files, beyond single bytes: every offset of the first 256 bytes overwritten with
// the 32-bit values that break sizes and counts (0, 1, 0x7fffffff, 0x80000000, 0xffffffff, 65536),
// and 400 random mutations anywhere in the file (1 to 8 bytes set, a span copied elsewhere, or a
// span removed), for each format the baker writes, 2D and 3D, and the EXR atlas. Each read
// succeeds or throws Error(kExitDataErr) naming the file, touching at most 64 MiB of fresh memory
// (minor page faults; OpenEXR had taken 2 GB for an attribute size of 0x7fffffff); a crash,
// another exception or an allocation failure fails the test.
void mutate(const std::string& path, int randomTries) {
  const std::string whole = bytes(path);
  ASSERT_GT(whole.size(), 16u) << path;
  const std::string probe = path + ".mutated" + fs::path(path).extension().string();
  int refused = 0, read = 0;
  auto attempt = [&](const std::string& content, const std::string& what) {
    {
      std::ofstream out(probe, std::ios::binary | std::ios::trunc);
      out << content;
    }
    struct rusage before {
    }, after{};
    getrusage(RUSAGE_SELF, &before);
    try {
      readTableFile(probe);
      ++read;
    } catch (const Error& e) {
      ASSERT_EQ(e.code(), kExitDataErr) << path << " " << what << ": " << e.what();
      ASSERT_EQ(std::string(e.what()).rfind("cannot read " + probe + ": ", 0), 0u) << e.what();
      ++refused;
    } catch (const std::exception& e) {
      FAIL() << path << " " << what << ": " << e.what();
    }
    getrusage(RUSAGE_SELF, &after);
    const long pages = after.ru_minflt - before.ru_minflt, limit = (64l << 20) / sysconf(_SC_PAGESIZE);
    ASSERT_LE(pages, limit) << path << " " << what << ": " << pages << " pages touched";
  };
  const uint32_t values[] = {0u, 1u, 0x7fffffffu, 0x80000000u, 0xffffffffu, 65536u};
  for (size_t at = 0; at + 4 <= std::min<size_t>(whole.size(), 256); ++at)
    for (uint32_t v : values) {
      std::string c = whole;
      std::memcpy(&c[at], &v, 4);
      attempt(c, "u32 " + std::to_string(v) + " at " + std::to_string(at));
      if (::testing::Test::HasFatalFailure()) return;
    }
  std::mt19937 rng(7);
  auto uniform = [&](size_t lo, size_t hi) { return std::uniform_int_distribution<size_t>(lo, hi)(rng); };
  for (int k = 0; k < randomTries; ++k) {
    std::string c = whole;
    const size_t at = uniform(0, c.size() - 1), len = uniform(1, 8);
    std::string what;
    switch (k % 3) {
      case 0:
        for (size_t i = at; i < std::min(c.size(), at + len); ++i) c[i] = static_cast<char>(uniform(0, 255));
        what = "bytes set at " + std::to_string(at);
        break;
      case 1: {
        const size_t from = uniform(0, c.size() - 1), n = std::min({len * 8, c.size() - from, c.size() - at});
        c.replace(at, n, whole.substr(from, n));
        what = "span copied to " + std::to_string(at);
        break;
      }
      default:
        c.erase(at, len * 8);
        what = "span removed at " + std::to_string(at);
    }
    attempt(c, what);
    if (::testing::Test::HasFatalFailure()) return;
  }
  EXPECT_GT(refused, 0) << path << ": no mutation was refused";
  fs::remove(probe);
}

TEST(FormatsRead, MutatedRealFilesAreReadOrRefused) {
  const fs::path d = bakeInto("mutate2d", "--table splitsum,kp --size 8 --format exr,ktx2,dds,png16,header");
  for (const char* ext : {".exr", ".ktx2", ".dds", ".png", ".h", ".mjs"}) {
    mutate((d / (std::string("splitsum_ggx_smith-correlated") + ext)).string(), 400);
    mutate((d / (std::string("kp_ggx") + ext)).string(), 100);
  }
  const fs::path v =
      bakeInto("mutate3d", "--table brdf3d --size 6,5,4 --format exr,ktx2,dds,header --precision float16");
  for (const char* ext : {".exr", ".ktx2", ".dds", ".h"})
    mutate((v / (std::string("brdf3d_ggx_smith-correlated_angles") + ext)).string(), 200);
}

// A MERL file (35 MB, made here: 90 90 180 and constant values): its header's counts overwritten,
// a NaN or an infinity among the values, and truncations. Each read succeeds or throws
// Error(kExitDataErr); a missing file is Error(kExitNoInput).
TEST(FormatsRead, MutatedMerlFilesAreReadOrRefused) {
  const fs::path d = testing_cli::freshDir("read", "merl");
  std::string whole(kMerlFileBytes, '\0');
  const int32_t dims[3] = {kMerlThetaH, kMerlThetaD, kMerlPhiD};
  std::memcpy(&whole[0], dims, 12);
  for (size_t i = 0; i < 3 * kMerlBins; ++i) {
    const double v = 0.1 / kMerlScale[i / kMerlBins];
    std::memcpy(&whole[12 + 8 * i], &v, 8);
  }
  const std::string path = (d / "m.binary").string();
  auto tryRead = [&](const std::string& content, const std::string& what, bool mustRefuse) {
    {
      std::ofstream out(path, std::ios::binary | std::ios::trunc);
      out << content;
    }
    try {
      readMerl(path);
      EXPECT_FALSE(mustRefuse) << what;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), kExitDataErr) << what << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << what << ": " << e.what();
    }
  };
  tryRead(whole, "the file as made", false);
  const uint32_t values[] = {0u, 1u, 89u, 0x7fffffffu, 0x80000000u, 0xffffffffu};
  for (size_t at = 0; at < 12; at += 4)
    for (uint32_t v : values) {
      std::string c = whole;
      std::memcpy(&c[at], &v, 4);
      tryRead(c, "header u32 " + std::to_string(v) + " at " + std::to_string(at), true);
    }
  for (double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
    std::string c = whole;
    std::memcpy(&c[12 + 8 * 123457], &bad, 8);
    tryRead(c, "a non-finite value", true);
  }
  for (size_t n : {size_t{0}, size_t{11}, size_t{12}, kMerlFileBytes / 2, kMerlFileBytes - 1})
    tryRead(whole.substr(0, n), "truncated to " + std::to_string(n), true);
  tryRead(whole + "x", "one byte more", true);
}

TEST(FormatsRead, MissingFileOrDirectoryIsNoInput) {
  const fs::path d = testing_cli::freshDir("read", "missing");
  for (const std::string& p : {(d / "none.ktx2").string(), d.string()}) {
    try {
      readTableFile(p);
      ADD_FAILURE() << p;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), kExitNoInput) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("cannot read " + p + ": ", 0), 0u) << e.what();
    }
  }
}

}  // namespace
