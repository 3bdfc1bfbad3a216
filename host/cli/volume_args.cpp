// The options of --table brdf3d (3D isotropic BRDF tables): parsing and the checks that need the
// whole command line.
#include "cli/volume_args.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>

#include "cli/commands.h"
#include "common/errors.h"
#include "common/format.h"
#include "tables/registry.h"

namespace brdfbake {

namespace {
std::vector<std::string> splitAt(const std::string& s, char sep) {
  std::vector<std::string> out;
  size_t start = 0;
  while (true) {
    size_t at = s.find(sep, start);
    out.push_back(s.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) break;
    start = at + 1;
  }
  return out;
}
}  // namespace

void parseVolumeSize(const std::string& v, BakeRequest& req, std::vector<std::string>& given) {
  std::vector<std::string> parts = splitAt(v, ',');
  // NX,NY,NZ: a 3D table's resolution per axis
  if (parts.size() != 3)
    throw Error(kExitUsage, "--size takes N or NX,NY,NZ (a brdf3d or dielectric table's axes), got '" + v + "'");
  std::array<int, 3> n{};
  for (int a = 0; a < 3; ++a) {
    errno = 0;
    char* end = nullptr;
    long x = std::strtol(parts[a].c_str(), &end, 10);
    if (parts[a].empty() || *end != '\0' || errno != 0 || x < 1 || x > kMaxVolumeSize)
      throw Error(kExitUsage, "--size: each axis of a brdf3d or dielectric table must be an integer in 1.." +
                                  std::to_string(kMaxVolumeSize) + ", got '" + parts[a] + "'");
    n[a] = static_cast<int>(x);
  }
  req.volume.size = n;
  given.push_back("--size NX,NY,NZ");
}

bool parseVolumeOption(const std::string& opt, const std::function<const std::string&()>& value, BakeRequest& req,
                       std::vector<std::string>& given) {
  auto once = [&](const std::string& o) {
    if (std::find(given.begin(), given.end(), o) != given.end())
      throw Error(kExitUsage, o + " given twice; give it once");
  };
  if (opt == "--param") {
    once(opt);
    std::string v = value();
    if (v == "angles")
      req.volume.param = Brdf3dParam::Angles;
    else if (v == "rusinkiewicz")
      req.volume.param = Brdf3dParam::Rusinkiewicz;
    else
      throw Error(kExitUsage, "--param must be angles or rusinkiewicz, got '" + v + "'" + nearestValue("--param", v));
    given.push_back(opt);
  } else if (opt == "--theta-h") {
    once(opt);
    std::string v = value();
    if (v == "sqrt")
      req.volume.thetaHSqrt = true;
    else if (v != "linear")
      throw Error(kExitUsage,
                  "--theta-h must be linear or sqrt (MERL's index), got '" + v + "'" + nearestValue("--theta-h", v));
    given.push_back(opt);
  } else if (opt == "--value") {
    once(opt);
    std::string v = value();
    if (v == "f-cos")
      req.volume.timesCos = true;
    else if (v != "f")
      throw Error(kExitUsage,
                  "--value must be f or f-cos (f times cos theta_i), got '" + v + "'" + nearestValue("--value", v));
    given.push_back(opt);
  } else if (opt == "--roughness") {
    once(opt);
    std::vector<double> v = parseValues(opt, value());
    if (v.size() != 1 || !(v[0] >= kMinVolumeRoughness && v[0] <= 1.0))
      throw Error(kExitUsage,
                  "--roughness must be one value in [0.01, 1] (perceptual r; below 0.01 the lobe is "
                  "narrower than any table resolves)");
    req.volume.roughness = v[0];
    given.push_back(opt);
  } else if (opt == "--rho") {
    once(opt);
    std::vector<double> v = parseValues(opt, value());
    for (double x : v)
      if (!(x >= 0 && x <= 1))
        throw Error(kExitUsage, "--rho must be one value or three (R,G,B) in [0, 1], got '" + fmtG(x) + "'");
    req.volume.rho = v;
    given.push_back(opt);
  } else if (opt == "--atlas") {
    once(opt);
    std::string v = value();
    size_t x = v.find('x');
    char* e1 = nullptr;
    char* e2 = nullptr;
    long c = x == std::string::npos ? 0 : std::strtol(v.substr(0, x).c_str(), &e1, 10);
    long r = x == std::string::npos ? 0 : std::strtol(v.substr(x + 1).c_str(), &e2, 10);
    if (x == std::string::npos || x == 0 || x + 1 >= v.size() || *e1 != '\0' || *e2 != '\0' || c < 1 || r < 1 ||
        c > kMaxVolumeSize || r > kMaxVolumeSize)
      throw Error(kExitUsage, "--atlas must be COLUMNSxROWS, each 1..1024 (e.g. 8x4), got '" + v + "'");
    req.volume.atlas = std::make_pair(static_cast<int>(c), static_cast<int>(r));
    given.push_back(opt);
  } else {
    return false;
  }
  return true;
}

// The brdf3d options: only with --table brdf3d; --format merl fixes the layout MERL's files have.
void validateVolumeOptions(bool bake, BakeRequest& req, const std::vector<std::string>& given) {
  auto& v = req.volume;
  if (given.empty()) return;
  // the 3D textures take every option; other kinds with three size axes (the rough-dielectric cube,
  // tables/dielectric/dielectric.cpp) take NX,NY,NZ and no other
  const auto has = [&](bool (*pick)(const KindInfo&)) {
    return std::any_of(req.tables.begin(), req.tables.end(), [&](TableKind t) { return pick(kindInfo(t)); });
  };
  const bool volume = has([](const KindInfo& k) { return k.volume; });
  const bool cube = has([](const KindInfo& k) { return k.sizeAxes == 3 && !k.volume; });
  if (bake && cube && !volume && given.size() == 1 && given[0] == "--size NX,NY,NZ") return;
  if (!bake || !volume)
    throw Error(kExitUsage, given[0] + ": only --table brdf3d takes it" +
                                (bake ? std::string(" (bake --table brdf3d ...)") : std::string(" (a bake option)")));
  if (v.thetaHSqrt && v.param != Brdf3dParam::Rusinkiewicz)
    throw Error(kExitUsage, "--theta-h: only --param rusinkiewicz has a theta_h axis");
  if (v.merl) {
    if (req.tables.size() != 1)
      throw Error(kExitUsage, "--format merl writes one brdf3d table per pair; bake the other tables in another run");
    for (const char* f : {"--size NX,NY,NZ", "--atlas", "--value", "--theta-h"})
      if (std::find(given.begin(), given.end(), f) != given.end())
        throw Error(kExitUsage, std::string(f) +
                                    ": --format merl has MERL's fixed layout (rusinkiewicz, sqrt theta_h "
                                    "index, 90x90x180 bins, f); leave it out");
    if (req.size || req.precision || req.nodeGrid)
      throw Error(kExitUsage,
                  "--size/--half/--precision/--grid: --format merl has MERL's fixed layout (90x90x180 doubles, bins "
                  "sampled at their lower edges); leave them out");
    if (v.param == Brdf3dParam::Angles && std::find(given.begin(), given.end(), "--param") != given.end())
      throw Error(kExitUsage, "--param angles: --format merl is over the Rusinkiewicz angles; leave --param out");
    v.param = Brdf3dParam::Rusinkiewicz;
    v.thetaHSqrt = true;
  }
}

}  // namespace brdfbake
