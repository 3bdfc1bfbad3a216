// The table families brdfbake knows (tables/family.h), in the order a plan lists their jobs.
#pragma once
#include <vector>

#include "tables/family.h"

namespace brdfbake {

const std::vector<const TableFamily*>& families();
// The family that bakes `kind`.
const TableFamily& familyOf(TableKind kind);
// The family that bakes `kind` for `req` (a measured material's, or the one that lists it).
const TableFamily& familyFor(const BakeRequest& req, TableKind kind);
// --size's default for `kind` (splitsum and the Ashikhmin-Shirley textures 128, fresnel-avg 128, others 32).
int defaultSize(TableKind kind);

}  // namespace brdfbake
