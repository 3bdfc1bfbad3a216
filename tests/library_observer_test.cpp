// The library's observer (brdfbake/observer.h): bake() reports the device, each program and each
// table as they finish, in that order, as bakeToDirectory() does for `brdfbake bake --timings`.
#include <gtest/gtest.h>

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
