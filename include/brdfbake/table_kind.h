// The table kinds a request can ask for. Each is described once, by the family that bakes it
// (host/tables/kind_info.h: its name, axes, channels, shader code, defaults); the registry
// (host/tables/registry.cpp) collects those descriptions, and the names below come from them.
#pragma once
#include <string>
#include <vector>

namespace brdfbake {

// An id per kind; its family's KindInfo says what the kind is. A new kind adds its id here and its
// description in its family (docs/architecture.md, "Adding a table kind").
enum class TableKind {
  SplitSum,
  Albedo,
  AlbedoAvg,
  Kp,
  FresnelAvg,
  Brdf3d,
  AshikhminShirley,
  Dielectric,
  DielectricAvg,
  Ltc
};
// How many kinds there are: the last id + 1.
constexpr int kTableKindCount = static_cast<int>(TableKind::Ltc) + 1;

// Every kind's name (as --table, scenes and a file's brdf.table spell it), in TableKind order.
const std::vector<std::string>& tableNames();
// Name -> kind; throws Error(kExitUsage) naming `field` and listing the valid names.
TableKind tableKind(const std::string& name, const std::string& field = "--table");
const std::string& tableName(TableKind kind);

}  // namespace brdfbake
