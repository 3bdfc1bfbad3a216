// brdf.method texts of the microfacet tables (tables/microfacet/microfacet.cpp computeTable) (tables/method_text.cpp).
#pragma once
#include <string>

#include "brdfbake/table_kind.h"

namespace brdfbake {

// the hemisphere estimators' (split-sum, albedo), E_avg's and k_p's method
std::string methodText(TableKind kind);
// the diffuse albedo kernel's
std::string diffuseMethod();

}  // namespace brdfbake
