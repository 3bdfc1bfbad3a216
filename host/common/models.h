// Model and table names as MODELS.md and the command line spell them, and their ids in
// kernels/brdf (NDF_*, GAF_*).
#pragma once
#include <string>
#include <vector>

namespace brdfbake {

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

const std::vector<std::string>& ndfNames();    // index = NDF_* id
const std::vector<std::string>& gafNames();    // index = GAF_* id
const std::vector<std::string>& tableNames();  // in TableKind order

// Name -> id; throws Error(kExitUsage) naming `field` and listing the valid names.
int ndfId(const std::string& name, const std::string& field = "--ndf");
int gafId(const std::string& name, const std::string& field = "--gaf");
TableKind tableKind(const std::string& name, const std::string& field = "--table");
const std::string& tableName(TableKind kind);

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
