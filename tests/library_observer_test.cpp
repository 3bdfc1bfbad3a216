// The library's observer (brdfbake/observer.h): bake() reports the device, each program and each
// table as they finish, in that order, as bakeToDirectory() does for `brdfbake bake --timings`.
#include <gtest/gtest.h>

#include <unistd.h>

#include <string>
#include <vector>

#include "brdfbake/brdfbake.h"

namespace {
struct Recorder : brdfbake::BakeObserver {
  std::vector<std::string> kinds, whats;
  void stage(const std::string& kind, const std::string& what, double seconds) override {
    EXPECT_GE(seconds, 0.0) << kind;
    kinds.push_back(kind);
    whats.push_back(what);
  }
};
}  // namespace

TEST(LibraryObserver, BakeReportsDeviceProgramsAndTables) {
  brdfbake::BakeRequest req = brdfbake::defaultRequest();
  req.tables = {brdfbake::tableKind("albedo"), brdfbake::tableKind("kp")};
  req.size = 8;
  auto rec = std::make_shared<Recorder>();
  req.observer = rec;
  std::vector<brdfbake::Table> tables = brdfbake::bake(req);
  ASSERT_EQ(tables.size(), 2u);
  ASSERT_GE(rec->kinds.size(), 4u);
  EXPECT_EQ(rec->kinds.front(), "device");
  EXPECT_EQ(rec->kinds[1], "program");
  EXPECT_NE(rec->whats[1].find("ggx + smith-correlated: "), std::string::npos) << rec->whats[1];
  EXPECT_EQ(rec->kinds[rec->kinds.size() - 2], "table");
  EXPECT_EQ(rec->whats[rec->whats.size() - 2], tables[0].path);
  EXPECT_EQ(rec->kinds.back(), "table");
  EXPECT_EQ(rec->whats.back(), tables[1].path);
}

// A table's errorBound in memory is what its file claims once written: for float16 the storage
// rounding (2.4e-4 near 1) over the values' own bound (below 1e-6), as the file's brdf.error has it.
TEST(Library, ErrorBoundIsWhatTheFileClaims) {
  const std::string dir = testing::TempDir() + "/brdfbake_library_bound_" + std::to_string(::getpid());
  for (const auto p : {brdfbake::Precision::Float16, brdfbake::Precision::Float32}) {
    brdfbake::BakeRequest req = brdfbake::defaultRequest();
    req.tables = {brdfbake::tableKind("albedo")};
    req.size = 16;
    req.precision = p;
    req.outDir = dir;
    std::vector<brdfbake::Table> t = brdfbake::bake(req);
    ASSERT_EQ(t.size(), 1u);
    brdfbake::write(t);
    const brdfbake::Table back = brdfbake::readTable(t[0].path);
    EXPECT_FLOAT_EQ(static_cast<float>(t[0].errorBound), std::stof(back.metadata.at("brdf.error")));
    if (p == brdfbake::Precision::Float16)
      EXPECT_GT(t[0].errorBound, 1e-4);
    else
      EXPECT_LT(t[0].errorBound, 1e-5);
  }
}
