// Model and table names as MODELS.md and the command line spell them, and their ids in
// kernels/brdf (NDF_*, GAF_*).
#pragma once
#include <string>
#include <vector>

namespace brdfbake {

enum class TableKind { SplitSum, Albedo, AlbedoAvg, Kp, FresnelAvg, Brdf3d, AshikhminShirley, Dielectric, DielectricAvg };

const std::vector<std::string>& ndfNames();   // index = NDF_* id
const std::vector<std::string>& gafNames();   // index = GAF_* id
const std::vector<std::string>& tableNames();  // in TableKind order

// Name -> id; throws Error(kExitUsage) naming `field` and listing the valid names.
int ndfId(const std::string& name, const std::string& field = "--ndf");
int gafId(const std::string& name, const std::string& field = "--gaf");
TableKind tableKind(const std::string& name, const std::string& field = "--table");
const std::string& tableName(TableKind kind);

// How the NDF's own parameter follows from perceptual roughness r (brdf.roughness).
std::string roughnessMapping(int ndf);

std::string joinNames(const std::vector<std::string>& names);

}  // namespace brdfbake
