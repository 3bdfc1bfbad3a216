#include "common/models.h"

#include "common/errors.h"

namespace brdfbake {

const std::vector<std::string>& ndfNames() {
  static const std::vector<std::string> n = {"ggx", "beckmann", "blinn-phong", "gaussian"};
  return n;
}

const std::vector<std::string>& gafNames() {
  static const std::vector<std::string> n = {"none",  "implicit", "cook-torrance", "kelemen",
                                             "neumann", "ashikhmin-premoze", "schlick-beckmann",
                                             "schlick-ggx", "schlick-ggx-direct", "smith",
                                             "smith-correlated", "smith-exact",
                                             "smith-correlated-exact"};
  return n;
}

const std::vector<std::string>& tableNames() {
  static const std::vector<std::string> n = {"splitsum", "albedo", "albedo-avg", "kp", "fresnel-avg", "brdf3d",
                                             "ashikhmin-shirley", "dielectric", "dielectric-avg"};
  return n;
}

std::string joinNames(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

namespace {
int lookup(const std::vector<std::string>& names, const std::string& name, const std::string& field,
           const char* what) {
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  throw Error(kExitUsage, field + ": unknown " + what + " '" + name + "'; valid: " + joinNames(names));
}
}  // namespace

int ndfId(const std::string& name, const std::string& field) { return lookup(ndfNames(), name, field, "NDF"); }
int gafId(const std::string& name, const std::string& field) { return lookup(gafNames(), name, field, "GAF"); }
TableKind tableKind(const std::string& name, const std::string& field) {
  return static_cast<TableKind>(lookup(tableNames(), name, field, "table"));
}
const std::string& tableName(TableKind kind) { return tableNames()[static_cast<int>(kind)]; }

std::string roughnessMapping(int ndf) {
  switch (ndf) {
    case 0: return "alpha=r^2";
    case 1: return "alpha=r^2 (Beckmann m=alpha)";
    case 2: return "e=2/alpha^2-2, alpha=r^2";
    default: return "c=1/alpha, alpha=r^2";
  }
}

}  // namespace brdfbake
