// The options of --table brdf3d, parsed apart from the rest of the command line (cli/args.cpp).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "cli/args.h"

namespace brdfbake {

// Each records the options it took in `given` (what validateVolumeOptions checks), which is the
// command line's, not the request's.
// --size NX,NY,NZ (each 1..kMaxVolumeSize) into req.volume.size.
void parseVolumeSize(const std::string& text, BakeRequest& req, std::vector<std::string>& given);
// --param, --theta-h, --value, --roughness, --rho, --atlas (--format merl: cli/args.cpp): true when `opt` is one of
// them (its value taken with value()), false otherwise. Throws Error(kExitUsage) naming the flag
// and its accepted values.
bool parseVolumeOption(const std::string& opt, const std::function<const std::string&()>& value, BakeRequest& req,
                       std::vector<std::string>& given);
// After the whole line: brdf3d options only with --table brdf3d (and only for bake); --format merl
// fixes the parameterisation (rusinkiewicz, sqrt theta_h index) and rejects what would change it.
void validateVolumeOptions(bool bake, BakeRequest& req, const std::vector<std::string>& given);

}  // namespace brdfbake
