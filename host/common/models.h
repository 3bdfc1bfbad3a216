// Model names as MODELS.md and the command line spell them, and their ids in kernels/brdf (NDF_*,
// GAF_*). Table kinds and their names are the families' (brdfbake/table_kind.h).
#pragma once
#include <string>
#include <vector>

namespace brdfbake {

const std::vector<std::string>& ndfNames();  // index = NDF_* id
const std::vector<std::string>& gafNames();  // index = GAF_* id

// Name -> id; throws Error(kExitUsage) naming `field` and listing the valid names.
int ndfId(const std::string& name, const std::string& field = "--ndf");
int gafId(const std::string& name, const std::string& field = "--gaf");
// The index of `name` in `names`; throws Error(kExitUsage) "FIELD: unknown WHAT 'NAME' (did you mean
// ...); valid: ..." when it is none of them.
int nameIndex(const std::vector<std::string>& names, const std::string& name, const std::string& field,
              const char* what);

// How the NDF's own parameter follows from perceptual roughness r (brdf.roughness).
std::string roughnessMapping(int ndf);

std::string joinNames(const std::vector<std::string>& names);
// The closest of `valid` to `word` by edit distance (for "did you mean"), or "" if none is close:
// within 2 edits, or a third of the word's length for longer words.
std::string closestName(const std::string& word, const std::vector<std::string>& valid);
// " (did you mean 'x'?)" with the closest name, or "" if none is close.
std::string didYouMean(const std::string& word, const std::vector<std::string>& valid);

// Sheen models (MODELS.md "Sheen"): the charlie NDF and its visibilities charlie-smith, neubelt.
bool isSheenNdf(int ndf);
bool isSheenGaf(int gaf);
// Whether an NDF/GAF pair is a model: a sheen visibility pairs with charlie only, and charlie with
// the sheen visibilities, none and implicit. Every sweep over NDFs x GAFs skips the others.
bool pairSupported(int ndf, int gaf);
// Throws Error(kExitUsage) naming `field` for a pair that pairSupported refuses.
void checkPair(int ndf, int gaf, const std::string& field = "--ndf/--gaf");

}  // namespace brdfbake
