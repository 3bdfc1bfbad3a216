// The layout options and --mu-axis: see layout_args.h.
#include "cli/layout_args.h"

#include "cli/commands.h"
#include "common/errors.h"
#include "tables/registry.h"

namespace brdfbake {

bool parseLayoutOption(const std::string& opt, const std::function<const std::string&()>& value,
                       const std::function<void(const std::string&)>& once, BakeRequest& req) {
  if (opt == "--layout") {
    once("--layout");
    req.layoutPreset = layoutPreset(value()).name;
    req.layout = layoutPreset(*req.layoutPreset).layout;
  } else if (opt == "--axes" || opt == "--flip-x" || opt == "--flip-y" || opt == "--channels") {
    once(opt);
    if (opt == "--axes") {
      const std::string& v = value();
      if (v != "mu,r" && v != "r,mu")
        throw Error(kExitUsage, "--axes must be mu,r or r,mu, got '" + v + "'" + nearestValue("--axes", v));
      req.layout.rAlongX = v == "r,mu";
    } else if (opt == "--channels") {
      req.layout.channels = parseLayoutChannels(value());
    } else {
      (opt == "--flip-x" ? req.layout.flipX : req.layout.flipY) = true;
    }
  } else if (opt == "--mu-axis") {
    once("--mu-axis");
    const std::string& v = value();
    if (v != "linear" && v != "sqrt")
      throw Error(kExitUsage,
                  "--mu-axis must be linear (x = mu, the default) or sqrt (x = sqrt(mu): texel i holds "
                  "mu = u_i^2, as Unity HDRP's pre-integrated FGD), got '" +
                      v + "'" + nearestValue("--mu-axis", v));
    req.muSqrt = v == "sqrt";
  } else {
    return false;
  }
  return true;
}

void validateMuAxis(bool gridGiven, BakeRequest& req) {
  if (req.layoutPreset) {
    // the engine's addressing is part of its lookup: a file on another grid or mu axis reads wrong there
    const LayoutPreset& lp = layoutPreset(*req.layoutPreset);
    const std::string grid = lp.nodeGrid ? "node" : "texel-center", axis = lp.muSqrt ? "sqrt" : "linear";
    if (gridGiven && req.nodeGrid != lp.nodeGrid)
      throw Error(kExitUsage, "--grid " + std::string(req.nodeGrid ? "node" : "texel-center") + ": --layout " +
                                  lp.name + " samples a " + grid +
                                  " grid (the engine's lookup); leave --grid out or give " + grid);
    if (req.muSqrt && *req.muSqrt != lp.muSqrt)
      throw Error(kExitUsage, "--mu-axis " + std::string(*req.muSqrt ? "sqrt" : "linear") + ": --layout " + lp.name +
                                  " samples x = " + (lp.muSqrt ? "sqrt(NdotV)" : "NdotV") +
                                  " (the engine's lookup); leave --mu-axis out or give " + axis);
    req.nodeGrid = lp.nodeGrid;
    req.muSqrt = lp.muSqrt;
  }
  if (!req.muSqrt) req.muSqrt = false;
  if (!*req.muSqrt) return;
  const std::string o = "--mu-axis sqrt";
  if (req.diffuse >= 0)
    throw Error(kExitUsage, o + ": --diffuse " + diffuseNames()[req.diffuse] +
                                ": the diffuse albedo is baked on a linear mu axis only (accepted: --mu-axis linear); "
                                "bake the specular tables without --diffuse");
  if (!req.merl.empty())
    throw Error(kExitUsage, o + ": a measured material (--brdf merl:) is tabulated on a linear mu axis only "
                                "(accepted: --mu-axis linear)");
  if (!req.preset.empty())
    throw Error(kExitUsage, o + ": --preset " + req.preset +
                                " bakes what glTF samples, on a linear mu axis "
                                "(accepted: --mu-axis linear)");
  std::vector<TableKind> takers;  // the kinds over (mu, r), as their families describe them
  for (const KindInfo& k : allKinds())
    if (k.muRAxes) takers.push_back(k.kind);
  for (TableKind t : req.tables)
    if (!kindInfo(t).muRAxes)
      throw Error(kExitUsage, o + ": --table " + tableName(t) + " has no (mu, r) x axis to space in sqrt(mu); the " +
                                  "option applies to --table " + kindNames(takers, "and") + " (bake " + tableName(t) +
                                  " in a run without it, or give --mu-axis linear)");
}

}  // namespace brdfbake
