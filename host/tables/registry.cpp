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
  X(dielectricFamily)        \
  X(ltcFamily)

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
  throw Error(kExitUsage,
              "--table " + tableName(kind) + ": no table family bakes it for this request" +
                  (req.merl.empty() ? "" : " (a measured material bakes " + kindNames(kindsFor(req)) + ")"));
}

std::vector<TableKind> kindsFor(const BakeRequest& req) {
  std::vector<TableKind> v;
  for (const TableFamily* f : families())
    if (f->takes(req))
      for (TableKind k : f->kinds())
        if (std::find(v.begin(), v.end(), k) == v.end()) v.push_back(k);
  return v;
}

std::string kindNames(const std::vector<TableKind>& kinds, const std::string& last) {
  std::string s;
  for (size_t i = 0; i < kinds.size(); ++i)
    s += (i == 0 ? "" : i + 1 == kinds.size() ? " " + last + " " : ", ") + tableName(kinds[i]);
  return s;
}

// Every kind's description, indexed by its id; each id described by exactly one family.
const std::vector<KindInfo>& allKinds() {
  static const std::vector<KindInfo> all = [] {
    std::vector<KindInfo> v(kTableKindCount);
    std::vector<bool> described(kTableKindCount, false);
    for (const TableFamily* f : families())
      for (const KindInfo& info : f->describe()) {
        const int id = static_cast<int>(info.kind);
        // names are not known yet: messages name the id and the family
        if (id < 0 || id >= kTableKindCount || described[id] || info.name.empty())
          throw Error(kExitSoftware, "internal: family " + f->name() + " describes kind " + std::to_string(id) +
                                         (info.name.empty() ? " without a name" : " (" + info.name + ")") +
                                         ", which is out of range or described twice");
        v[id] = info;
        described[id] = true;
      }
    for (int id = 0; id < kTableKindCount; ++id)
      if (!described[id]) throw Error(kExitSoftware, "internal: no table family describes kind " + std::to_string(id));
    return v;
  }();
  return all;
}

const std::vector<std::string>& tableNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const KindInfo& k : allKinds()) v.push_back(k.name);
    return v;
  }();
  return names;
}

TableKind tableKind(const std::string& name, const std::string& field) {
  return static_cast<TableKind>(nameIndex(tableNames(), name, field, "table"));
}

const std::string& tableName(TableKind kind) { return allKinds()[static_cast<size_t>(kind)].name; }

std::vector<TableKind> kindsServing(unsigned uses) {
  std::vector<TableKind> v;
  for (const KindInfo& k : allKinds())
    if (k.sceneUses & uses) v.push_back(k.kind);
  return v;
}

std::vector<TableKind> kindsWhere(bool (*pick)(const KindInfo&)) {
  std::vector<TableKind> v;
  for (const KindInfo& k : allKinds())
    if (pick(k)) v.push_back(k.kind);
  return v;
}

const KindInfo& kindInfo(TableKind kind) { return allKinds()[static_cast<size_t>(kind)]; }

const KindInfo* findKind(const std::string& name) {
  for (size_t k = 0; k < tableNames().size(); ++k)
    if (tableNames()[k] == name) return &allKinds()[k];
  return nullptr;
}

int defaultSize(TableKind kind) { return kindInfo(kind).defaultSize; }

}  // namespace brdfbake
