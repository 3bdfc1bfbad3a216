// The options that arrange a table for an engine's lookup, parsed apart from the rest of the
// command line (cli/args.cpp): --layout NAME, --axes, --flip-x, --flip-y, --channels (the split sum's
// arrangement, formats/layout.h) and --mu-axis linear|sqrt (the coordinate the x texels are spaced
// in: mu itself, or u = sqrt(mu) as Unity HDRP's newer pre-integrated FGD samples it).
#pragma once
#include <functional>
#include <string>

#include "cli/args.h"

namespace brdfbake {

// True when `opt` is one of the options above (its value taken with value(); once(canonical)
// refuses a repeat), false otherwise. Throws Error(kExitUsage) naming the option and its accepted values.
bool parseLayoutOption(const std::string& opt, const std::function<const std::string&()>& value,
                       const std::function<void(const std::string&)>& once, BakeRequest& req);

// After the whole line, the tables resolved: a layout preset's grid and mu axis where the line gives
// none (a contradicting --grid or --mu-axis exits 64: the engine's lookup would misread the file);
// --mu-axis sqrt only for tables over (mu, r) the hemisphere kernel bakes (splitsum, albedo), not a
// diffuse model's albedo, a measured material or --preset gltf. req.muSqrt is set either way.
// `gridGiven`: --grid was on the line.
void validateMuAxis(bool gridGiven, BakeRequest& req);

}  // namespace brdfbake
