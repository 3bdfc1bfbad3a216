// brdf.method: how a table was computed, generated from the constants the estimators use
// (kernels/integrate/*.h and tables/error_model.h), so that it describes the code that ran.
#include "tables/method_text.h"

#include <string>

#include "tables/error_model.h"
#include "cl/runner.h"
#include "common/brdf_host.h"
#include "common/format.h"

namespace brdf64 {
const double kPhiGrow = HEMI_PHI_GROW, kPhiGrowOwn = HEMI_PHI_GROW_OWN;  // RC() needs brdf64::real
const double kGkSharpC = GK_SHARP_C, kFloorSharp = HEMI_ERR_FLOOR_SHARP, kFloorRefined = HEMI_ERR_FLOOR_REFINED;
const double kAvgLayerAlpha = AVG_LAYER_ALPHA, kAvgLayerBreak = AVG_LAYER_BREAK, kAvgFloor = AVG_ERR_FLOOR;
}  // namespace brdf64
namespace brdfbake {
namespace {

// brdf.method, generated from the constants the estimators use (kernels/integrate/hemisphere.h),
// so that it describes the code that ran.
std::string hemisphereMethod() {
  auto model = [](FloatModel m) { return "(" + fmtG(m.k1) + ", " + fmtG(m.k0) + ")"; };
  std::string breaks;
  for (int k = 0; k < HEMI_NBREAKS; ++k) breaks += (k ? "," : "") + fmtG(brdf64::HEMI_BREAKS[k]);
  std::string cuts;
  for (double c : brdf64::HEMI_REFINE_CUTS) cuts += (cuts.empty() ? "" : ",") + fmtG(c);
  return "h-space quadrature: theta_h by v=-log(1-CDF_ndf) in GK15 panels (breaks " + breaks +
         " and at the visible-domain limits, sqrt ends substituted), phi_h by " + std::to_string(HEMI_TRAP_N) +
         "-interval trapezoid on the full circle or GK15 per smooth arc (graded x" + fmtG(brdf64::kPhiGrow) +
         " towards the horizon from n.i = mu; Smith and Schlick GAFs x" + fmtG(brdf64::kPhiGrowOwn) +
         " from n.i = 2 alpha; none, implicit, neumann and cook-torrance, polynomial in cos phi between their kinks, "
         "ungraded under Schlick's and F82's weights); texels estimated above " +
         fmtG(HEMI_BAKE_TARGET) + " redone with each outer panel cut at " + cuts + ", " +
         std::to_string(2 * HEMI_TRAP_N) + " trapezoid intervals, grading halved" +
         " and every arc panel halved; error: per texel, the rules' estimates (GK15: |K15-G7| rescaled as QUADPACK's "
         "qk15 with C=" +
         fmtG(brdf64::kGkSharpC) + " on panels split at the GAF's kinks; trapezoid: |T16-T8|^3/|T8-T4|) + a floor of " +
         fmtG(brdf64::kFloorSharp) + " (" + fmtG(brdf64::kFloorRefined) +
         " at the refined budget) of the value + float arithmetic (K1 min(1,|value|) + K0) u (u = 2^-24; " +
         "(K1, K0) = " + model(kHemiFloatGgx) + " ggx, " + model(kHemiFloatBeckmann) + " beckmann, " +
         model(kHemiFloatBlinnPhong) + " blinn-phong, " + model(kHemiFloat) + " gaussian, " + model(kFresnelFloat) +
         " every Fresnel-weighted moment B (F82-tint's at least 0.3 u E/max(1, |B|), E its F = 1 albedo), "
         "next to a total-internal-reflection kink plus u mu times F's slope over the "
         "lobe's spread in o.h, " +
         model(kSheenFloatNone) + " charlie with none, " + model(kSheenFloatBounded) + " with neubelt and implicit, " +
         model(kCharlieSmithFloat) + " with charlie-smith) + storage rounding";
}

}  // namespace

std::string diffuseMethod() {
  return "theta_i in GK15 panels (" + std::to_string(DIFFUSE_PANELS) +
         " each side of theta_o), phi by GK15 on [0,pi/2] and [pi/2,pi] where f_d depends on it; error |K15-G7| + " +
         "float arithmetic (K1 min(1,|E|) + K0) u (u = 2^-24; (K1, K0) = (" + fmtG(kDiffuseFloat.k1) + ", " +
         fmtG(kDiffuseFloat.k0) + "), (" + fmtG(kDiffuseFloatAsPrinted.k1) + ", " + fmtG(kDiffuseFloatAsPrinted.k0) +
         ") for shirley-as-printed) + storage rounding";
}

std::string methodText(TableKind kind) {
  switch (kind) {
    case TableKind::AlbedoAvg:
      return "E_avg = 2 int E(mu) mu dmu by Gauss-Kronrod panels on [0,1]: one GK31 panel, or where alpha < " +
             fmtG(brdf64::kAvgLayerAlpha) + " GK15 on [0," + fmtG(brdf64::kAvgLayerBreak) +
             " alpha] (the horizon layer) and GK31 on the rest; the worst halved until the bound is under " +
             fmtG(KernelRunner::kAvgGoal) + " (" + fmtG(KernelRunner::kAvgGoalSheen) + " for charlie)" +
             "; sums in double on the host, the nodes' float positions corrected to first order; error: the panels' "
             "|K-G| (rescaled where E is analytic) + the nodes' estimates (for the plain average: their bare "
             "estimates + " +
             fmtG(brdf64::kAvgFloor) + " of E_avg, measured on the averages, + " +
             fmtG(brdf64::avg_model_error(NDF_BLINN_PHONG, GAF_SMITH_EXACT)) + " (blinn-phong) or " +
             fmtG(brdf64::avg_model_error(NDF_GAUSSIAN, GAF_SMITH_EXACT)) +
             " (gaussian) with a tabulated Lambda; else each node's own floor) + their float arithmetic + the sum's "
             "rounding to float; E at each node by " +
             hemisphereMethod();
    case TableKind::Kp:
      return "k_p = int e^-v p/D_grid dv by GK15 panels on v in [0," + fmtG(brdf64::HEMI_BREAKS[HEMI_NBREAKS - 1]) +
             "] (breaks " +
             [] {
               std::string b;
               for (int k = 0; k < HEMI_NBREAKS; ++k) b += (k ? "," : "") + fmtG(brdf64::HEMI_BREAKS[k]);
               return b;
             }() +
             "); error |K15-G7| + float arithmetic " + fmtG(kKpFloat.k1) +
             " u min(1,|value|) (u = 2^-24) + storage rounding";
    default:
      return hemisphereMethod();
  }
}

}  // namespace brdfbake
