#include "common/models.h"

#include <algorithm>

#include "common/brdf_host.h"
#include "common/errors.h"

namespace brdfbake {

const std::vector<std::string>& ndfNames() {
  static const std::vector<std::string> n = {"ggx", "beckmann", "blinn-phong", "gaussian", "charlie"};
  return n;
}

const std::vector<std::string>& gafNames() {
  static const std::vector<std::string> n = {"none",
                                             "implicit",
                                             "cook-torrance",
                                             "kelemen",
                                             "neumann",
                                             "ashikhmin-premoze",
                                             "schlick-beckmann",
                                             "schlick-ggx",
                                             "schlick-ggx-direct",
                                             "smith",
                                             "smith-correlated",
                                             "smith-exact",
                                             "smith-correlated-exact",
                                             "charlie-smith",
                                             "neubelt"};
  return n;
}

std::string joinNames(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

std::string closestName(const std::string& word, const std::vector<std::string>& valid) {
  std::string best;
  size_t bestD = std::string::npos;
  for (const auto& v : valid) {
    // Levenshtein distance
    std::vector<size_t> prev(v.size() + 1), cur(v.size() + 1);
    for (size_t j = 0; j <= v.size(); ++j) prev[j] = j;
    for (size_t i = 1; i <= word.size(); ++i) {
      cur[0] = i;
      for (size_t j = 1; j <= v.size(); ++j)
        cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (word[i - 1] == v[j - 1] ? 0 : 1)});
      std::swap(prev, cur);
    }
    if (prev[v.size()] < bestD) {
      bestD = prev[v.size()];
      best = v;
    }
  }
  if (bestD <= std::max<size_t>(2, word.size() / 3)) return best;
  // the start of exactly one name ('kulla' for 'kulla-conty'), three letters or more
  std::string prefixed;
  for (const auto& v : valid)
    if (word.size() >= 3 && v.size() > word.size() && v.compare(0, word.size(), word) == 0) {
      if (!prefixed.empty()) return std::string();
      prefixed = v;
    }
  return prefixed;
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& valid) {
  const std::string near = closestName(word, valid);
  return near.empty() ? std::string() : " (did you mean '" + near + "'?)";
}

int nameIndex(const std::vector<std::string>& names, const std::string& name, const std::string& field,
              const char* what) {
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  throw Error(kExitUsage, field + ": unknown " + what + " '" + name + "'" + didYouMean(name, names) +
                              "; valid: " + joinNames(names));
}

int ndfId(const std::string& name, const std::string& field) { return nameIndex(ndfNames(), name, field, "NDF"); }
int gafId(const std::string& name, const std::string& field) { return nameIndex(gafNames(), name, field, "GAF"); }

std::string roughnessMapping(int ndf) {
  switch (ndf) {
    case 0:
      return "alpha=r^2";
    case 1:
      return "alpha=r^2 (Beckmann m=alpha)";
    case 2:
      return "e=2/alpha^2-2, alpha=r^2";
    case 4:
      return "alpha=r^2 (sheenRoughness^2, KHR_materials_sheen; Filament's linear roughness)";
    default:
      return "c=1/alpha, alpha=r^2";
  }
}

bool isSheenNdf(int ndf) { return ndf == NDF_CHARLIE; }
bool isSheenGaf(int gaf) { return gaf == GAF_CHARLIE_SMITH || gaf == GAF_NEUBELT; }

// The sheen visibilities pair with the sheen NDF only; charlie takes them, and the two GAFs without
// a Lambda of their own (none: G = 1; implicit: G = (n.i)(n.o), the unshadowed sheen f = D/4).
bool pairSupported(int ndf, int gaf) {
  if (isSheenGaf(gaf)) return isSheenNdf(ndf);
  if (isSheenNdf(ndf)) return gaf == GAF_NONE || gaf == GAF_IMPLICIT;
  return true;
}

void checkPair(int ndf, int gaf, const std::string& field) {
  if (pairSupported(ndf, gaf)) return;
  if (isSheenGaf(gaf))
    throw Error(kExitUsage, field + ": gaf '" + gafNames()[gaf] + "' is a sheen visibility with a non-sheen NDF ('" +
                                ndfNames()[ndf] + "'); it pairs with --ndf charlie only");
  throw Error(kExitUsage, field +
                              ": ndf 'charlie' (sheen) takes the sheen visibilities charlie-smith, neubelt (or none, "
                              "implicit), not gaf '" +
                              gafNames()[gaf] + "'");
}

}  // namespace brdfbake
