// Tests for host/exr/table_file: round trips, determinism, validation and errors.
#include "formats/exr/table_file.h"

#include <gtest/gtest.h>
#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include "common/errors.h"

namespace brdfbake {
namespace {

class ExrTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string base = ::testing::TempDir();
    if (base.empty() || base.back() != '/') base += '/';
    std::string pattern = base + "exr_test_XXXXXX";
    std::vector<char> buf(pattern.begin(), pattern.end());
    buf.push_back('\0');
    ASSERT_NE(::mkdtemp(buf.data()), nullptr) << "mkdtemp failed in " << base;
    dir_ = buf.data();
  }
  void TearDown() override {
    for (const std::string& name : listDir()) ::unlink((dir_ + "/" + name).c_str());
    ::rmdir(dir_.c_str());
  }

  std::string path(const std::string& name) const { return dir_ + "/" + name; }

  std::vector<std::string> listDir() const {
    std::vector<std::string> names;
    if (DIR* d = ::opendir(dir_.c_str())) {
      while (dirent* e = ::readdir(d)) {
        const std::string n = e->d_name;
        if (n != "." && n != "..") names.push_back(n);
      }
      ::closedir(d);
    }
    return names;
  }

  static std::string readBytes(const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }

  // 3x2 table, channels R and G, attributes of all three kinds.
  static TableImage sample() {
    TableImage img;
    img.width = 3;
    img.height = 2;
    img.channels = {"R", "G"};
    img.planes = {{0.0f, 0.125f, 1.0f / 3.0f, -2.5f, 1000.25f, 1e-3f}, {1.0f, 0.5f, 0.25f, 3.0f, -0.0625f, 42.0f}};
    img.strings = {{"brdfbake:model", "ggx"}, {"brdfbake:table", "dfg"}};
    img.v2f = {{"brdfbake:xRange", {0.0f, 1.0f}}, {"brdfbake:yRange", {0.03125f, 0.96875f}}};
    img.floats = {{"brdfbake:ior", 1.5f}, {"brdfbake:eps", 1e-7f}};
    return img;
  }

  template <class F>
  static ExitCode codeOf(F&& f) {
    try {
      f();
    } catch (const Error& e) {
      return e.code();
    }
    return kExitOk;
  }

  std::string dir_;
};

void expectSameAttributes(const TableImage& a, const TableImage& b) {
  EXPECT_EQ(a.strings, b.strings);
  EXPECT_EQ(a.v2f, b.v2f);
  EXPECT_EQ(a.floats, b.floats);
}

TEST_F(ExrTest, FloatRoundTrip) {
  const TableImage img = sample();
  const std::string p = path("table.exr");
  writeTableExr(p, img, false);
  EXPECT_EQ(listDir(), std::vector<std::string>{"table.exr"});

  const TableImage back = readTableExr(p);
  EXPECT_EQ(back.width, 3);
  EXPECT_EQ(back.height, 2);
  EXPECT_EQ(back.channels, img.channels);
  ASSERT_EQ(back.planes.size(), 2u);
  for (size_t c = 0; c < 2; ++c) {
    ASSERT_EQ(back.planes[c].size(), 6u);
    for (size_t i = 0; i < 6; ++i) EXPECT_EQ(back.planes[c][i], img.planes[c][i]) << "channel " << c << " texel " << i;
  }
  expectSameAttributes(back, img);
  EXPECT_FALSE(tableExrIsHalf(p));
}

TEST_F(ExrTest, HalfRoundTrip) {
  const TableImage img = sample();
  const std::string p = path("half.exr");
  writeTableExr(p, img, true);
  EXPECT_TRUE(tableExrIsHalf(p));

  const TableImage back = readTableExr(p);
  EXPECT_EQ(back.width, 3);
  EXPECT_EQ(back.height, 2);
  EXPECT_EQ(back.channels, img.channels);
  ASSERT_EQ(back.planes.size(), 2u);
  for (size_t c = 0; c < 2; ++c) {
    ASSERT_EQ(back.planes[c].size(), 6u);
    for (size_t i = 0; i < 6; ++i) {
      const float want = img.planes[c][i];
      // HALF has an 11-bit significand: relative error <= 2^-11 for normal values,
      // plus an absolute error for the smallest ones.
      const float tol = std::fabs(want) * (1.0f / 2048.0f) + 6.2e-5f;
      EXPECT_NEAR(back.planes[c][i], want, tol) << "channel " << c << " texel " << i;
    }
  }
  // Values exactly representable in HALF come back exactly.
  EXPECT_EQ(back.planes[0][1], 0.125f);
  EXPECT_EQ(back.planes[1][4], -0.0625f);
  expectSameAttributes(back, img);
  // HALF tables keep ZIP (it saves 70% of a split sum's bytes); FLOAT ones are uncompressed
  EXPECT_NE(describeTableExr(p).find("compression: ZIP\n"), std::string::npos) << describeTableExr(p);
}

TEST_F(ExrTest, HalfMaxIsAccepted) {
  TableImage img = sample();
  img.planes[0][0] = 65504.0f;
  img.planes[1][0] = -65504.0f;
  writeTableExr(path("max.exr"), img, true);
  const TableImage back = readTableExr(path("max.exr"));
  EXPECT_EQ(back.planes[0][0], 65504.0f);
  EXPECT_EQ(back.planes[1][0], -65504.0f);
}

TEST_F(ExrTest, WritingTwiceIsByteIdentical) {
  const TableImage img = sample();
  for (bool half : {false, true}) {
    const std::string a = path(half ? "a_half.exr" : "a.exr");
    const std::string b = path(half ? "b_half.exr" : "b.exr");
    writeTableExr(a, img, half);
    writeTableExr(b, img, half);
    const std::string bytesA = readBytes(a);
    EXPECT_FALSE(bytesA.empty());
    EXPECT_EQ(bytesA, readBytes(b)) << (half ? "HALF" : "FLOAT");
    // Overwriting an existing file gives the same bytes too.
    writeTableExr(a, img, half);
    EXPECT_EQ(bytesA, readBytes(a));
  }
}

TEST_F(ExrTest, NaNAndInfAreRefused) {
  const float bad[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                       -std::numeric_limits<float>::infinity()};
  for (float v : bad) {
    for (bool half : {false, true}) {
      TableImage img = sample();
      img.planes[1][4] = v;  // channel G, x=1, y=1
      const std::string p = path("bad.exr");
      try {
        writeTableExr(p, img, half);
        ADD_FAILURE() << "no error for value " << v;
      } catch (const Error& e) {
        EXPECT_EQ(e.code(), kExitDataErr);
        const std::string msg = e.what();
        EXPECT_NE(msg.find("channel G"), std::string::npos) << msg;
        EXPECT_NE(msg.find("x=1, y=1"), std::string::npos) << msg;
        EXPECT_NE(msg.find(p), std::string::npos) << msg;
      }
      EXPECT_TRUE(listDir().empty());
    }
  }
}

TEST_F(ExrTest, HalfOverflowIsRefused) {
  TableImage img = sample();
  img.planes[0][2] = 1e6f;  // channel R, x=2, y=0
  const std::string p = path("overflow.exr");
  try {
    writeTableExr(p, img, true);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), kExitDataErr);
    const std::string msg = e.what();
    EXPECT_NE(msg.find("channel R"), std::string::npos) << msg;
    EXPECT_NE(msg.find("x=2, y=0"), std::string::npos) << msg;
  }
  EXPECT_TRUE(listDir().empty());
  // The same value is fine as FLOAT.
  writeTableExr(p, img, false);
  EXPECT_EQ(readTableExr(p).planes[0][2], 1e6f);
}

TEST_F(ExrTest, InvalidShapesAreRefused) {
  auto code = [&](TableImage img) { return codeOf([&] { writeTableExr(path("shape.exr"), img, false); }); };
  TableImage img = sample();
  img.width = 0;
  EXPECT_EQ(code(img), kExitDataErr);
  img = sample();
  img.channels.clear();
  img.planes.clear();
  EXPECT_EQ(code(img), kExitDataErr);
  img = sample();
  img.planes[1].pop_back();
  EXPECT_EQ(code(img), kExitDataErr);
  img = sample();
  img.planes.pop_back();
  EXPECT_EQ(code(img), kExitDataErr);
  img = sample();
  img.channels = {"G", "R"};
  EXPECT_EQ(code(img), kExitDataErr);
  img = sample();
  img.channels = {"R", "Z"};
  EXPECT_EQ(code(img), kExitDataErr);
  img = sample();
  img.strings["compression"] = "none";
  EXPECT_EQ(code(img), kExitDataErr);
  img = sample();
  img.floats["brdfbake:model"] = 1.0f;  // same name as a string attribute
  EXPECT_EQ(code(img), kExitDataErr);
  EXPECT_TRUE(listDir().empty());
}

TEST_F(ExrTest, UnwritablePathThrowsCantCreat) {
  const std::string p = path("no_such_dir/table.exr");
  try {
    writeTableExr(p, sample(), false);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), kExitCantCreat);
    EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
  }
  EXPECT_TRUE(listDir().empty());
}

TEST_F(ExrTest, RenameOntoDirectoryThrowsCantCreatAndCleansUp) {
  const std::string p = path("occupied");
  ASSERT_EQ(::mkdir(p.c_str(), 0755), 0);
  EXPECT_EQ(codeOf([&] { writeTableExr(p, sample(), false); }), kExitCantCreat);
  EXPECT_EQ(listDir(), std::vector<std::string>{"occupied"});
  ::rmdir(p.c_str());
}

TEST_F(ExrTest, MissingFileThrowsNoInput) {
  const std::string p = path("missing.exr");
  for (int which = 0; which < 3; ++which) {
    try {
      if (which == 0) readTableExr(p);
      if (which == 1) tableExrIsHalf(p);
      if (which == 2) describeTableExr(p);
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), kExitNoInput);
      EXPECT_EQ(std::string(e.what()).rfind("cannot read " + p + ": ", 0), 0u) << e.what();
    }
  }
}

// A file that is there but is not (or no longer) a valid OpenEXR file is a data error, 65, as in
// every other format; 66 is for what cannot be opened (missing, a directory).
TEST_F(ExrTest, NonExrFileIsADataError) {
  const std::string p = path("garbage.exr");
  {
    std::ofstream out(p, std::ios::binary);
    out << "this is not an OpenEXR file";
  }
  EXPECT_EQ(codeOf([&] { readTableExr(p); }), kExitDataErr);
  EXPECT_EQ(codeOf([&] { describeTableExr(p); }), kExitDataErr);
  EXPECT_EQ(codeOf([&] { readTableExr(dir_); }), kExitNoInput);
  EXPECT_EQ(codeOf([&] { readTableExr(path("missing.exr")); }), kExitNoInput);
}

TEST_F(ExrTest, TruncatedFileIsADataError) {
  const std::string p = path("table.exr");
  writeTableExr(p, sample(), false);
  const std::string bytes = readBytes(p);
  {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size() / 2));
  }
  EXPECT_EQ(codeOf([&] { readTableExr(p); }), kExitDataErr);
}

TEST_F(ExrTest, DescribeListsEverything) {
  const std::string p = path("table.exr");
  writeTableExr(p, sample(), false);
  const std::string d = describeTableExr(p);
  EXPECT_NE(d.find(p), std::string::npos) << d;
  EXPECT_NE(d.find("3x2"), std::string::npos) << d;
  EXPECT_NE(d.find("FLOAT"), std::string::npos) << d;
  // FLOAT tables are stored uncompressed, HALF ones with ZIP (exr_writer.cpp)
  EXPECT_NE(d.find("compression: NONE"), std::string::npos) << d;
  EXPECT_NE(d.find("  brdfbake:model (string): ggx\n"), std::string::npos) << d;
  EXPECT_NE(d.find("  brdfbake:table (string): dfg\n"), std::string::npos) << d;
  EXPECT_NE(d.find("  brdfbake:xRange (v2f): (0, 1)\n"), std::string::npos) << d;
  EXPECT_NE(d.find("  brdfbake:yRange (v2f): (0.03125, 0.96875)\n"), std::string::npos) << d;
  EXPECT_NE(d.find("  brdfbake:ior (float): 1.5\n"), std::string::npos) << d;
  EXPECT_NE(d.find("brdfbake:eps (float): 1.00000001e-07"), std::string::npos) << d;
  // Attributes are sorted by name.
  EXPECT_LT(d.find("brdfbake:eps"), d.find("brdfbake:ior"));
  EXPECT_LT(d.find("brdfbake:ior"), d.find("brdfbake:model"));
  EXPECT_LT(d.find("brdfbake:model"), d.find("brdfbake:xRange"));
  EXPECT_NE(d.find("channel R: min -2.5 max 1000.25"), std::string::npos) << d;
  EXPECT_NE(d.find("channel G: min -0.0625 max 42"), std::string::npos) << d;

  writeTableExr(p, sample(), true);
  EXPECT_NE(describeTableExr(p).find("HALF"), std::string::npos);
}

}  // namespace
}  // namespace brdfbake
