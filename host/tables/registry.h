// The table families brdfbake knows (tables/family.h), in the order a plan lists their jobs.
#pragma once
#include <string>
#include <vector>

#include "tables/family.h"

namespace brdfbake {

const std::vector<const TableFamily*>& families();
// The family that bakes `kind`.
const TableFamily& familyOf(TableKind kind);
// The family that bakes `kind` for `req` (a measured material's, or the one that lists it).
const TableFamily& familyFor(const BakeRequest& req, TableKind kind);
// The kinds the families that take `req` bake (a measured material's: albedo, albedo-avg, splitsum).
std::vector<TableKind> kindsFor(const BakeRequest& req);
// "a, b or c" (`last` "or"; "and": "a, b and c"): the kinds' names for messages, in the order given.
std::string kindNames(const std::vector<TableKind>& kinds, const std::string& last = "or");
// The kinds that serve a scene use (SceneUse bits, any of `uses`), in TableKind order.
std::vector<TableKind> kindsServing(unsigned uses);
// The kinds whose description satisfies `pick`, in TableKind order.
std::vector<TableKind> kindsWhere(bool (*pick)(const KindInfo&));
// The description of `kind`, from the family that defines it (tables/kind_info.h).
const KindInfo& kindInfo(TableKind kind);
// The description of the kind named `name` (a file's brdf.table), or nullptr when none is.
const KindInfo* findKind(const std::string& name);
// Every kind's description, in TableKind order.
const std::vector<KindInfo>& allKinds();
// --size's default for `kind` (its KindInfo's).
int defaultSize(TableKind kind);

}  // namespace brdfbake
