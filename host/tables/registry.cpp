#include "tables/registry.h"

#include <algorithm>

#include "common/errors.h"

namespace brdfbake {

// One line per family: a new table family is its module and a line here.
#define BRDFBAKE_FAMILIES(X) \
  X(fresnelAvgFamily)        \
  X(ashikhminFamily)         \
  X(microfacetFamily)        \
  X(measuredFamily)          \
  X(brdf3dFamily)            \
  X(dielectricFamily)

#define BRDFBAKE_DECLARE(f) const TableFamily& f();
BRDFBAKE_FAMILIES(BRDFBAKE_DECLARE)
#undef BRDFBAKE_DECLARE

const std::vector<const TableFamily*>& families() {
#define BRDFBAKE_LIST(f) &f(),
  static const std::vector<const TableFamily*> all = {BRDFBAKE_FAMILIES(BRDFBAKE_LIST)};
#undef BRDFBAKE_LIST
  return all;
}

const TableFamily& familyOf(TableKind kind) {
  for (const TableFamily* f : families()) {
    std::vector<TableKind> k = f->kinds();
    if (std::find(k.begin(), k.end(), kind) != k.end()) return *f;
  }
  throw Error(kExitSoftware, "internal: no table family bakes " + tableName(kind));
}

const TableFamily& familyFor(const BakeRequest& req, TableKind kind) {
  for (const TableFamily* f : families()) {
    std::vector<TableKind> k = f->kinds();
    if (f->takes(req) && std::find(k.begin(), k.end(), kind) != k.end()) return *f;
  }
  throw Error(kExitUsage, "--table " + tableName(kind) + ": no table family bakes it for this request" +
                              (req.merl.empty() ? "" : " (a measured material bakes albedo, albedo-avg or splitsum)"));
}

int defaultSize(TableKind kind) { return familyOf(kind).defaultSize(kind); }

}  // namespace brdfbake
