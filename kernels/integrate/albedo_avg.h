/* albedo_avg.h: the average albedo's rule (the estimator of E it averages is hemisphere.h). */
/* Once per pass (compat.h "Passes"). */
#if defined(BRDF_SECOND_PASS) ? !defined(BRDF_ALBEDO_AVG_H_2) : !defined(BRDF_ALBEDO_AVG_H)
#ifdef BRDF_SECOND_PASS
#define BRDF_ALBEDO_AVG_H_2
#else
#define BRDF_ALBEDO_AVG_H
#endif
#include "brdf/gaf.h"
#include "integrate/quadrature.h"
/* Average albedo E_avg = 2 int_0^1 E(mu) mu dmu (Kulla and Conty 2017): the Gauss-Kronrod 15/31
 * rule on [0, 1] its panels use (the horizon layer's panel: GK15, quadrature.h), nodes AVG_MU,
 * Kronrod weights AVG_WK and Kronrod minus Gauss weights AVG_WD (the 15 Gauss nodes are the odd
 * ones), so that a panel's value is sum AVG_WK 2 mu E and its estimate |sum AVG_WD 2 mu E|. The
 * rule itself (panels, halving, bounds) runs on the host,
 * host/cl/runner_avg.cpp, which hands the device its nodes (kernels/bake.cl, mu_list). */
#define AVG_NODES 31
/* The inner bounds' share of E_avg's bound, split evenly over the nodes by weight: node k of an
 * n-node panel rule is refined when its bound exceeds AVG_TARGET / (n * 2 mu_k * wk_k)
 * (avg_target_share; but never below the albedo's own target, host/cl/runner_avg.cpp), so that
 * the inner term sum wk 2 mu err_E stays near AVG_TARGET. The grazing nodes (mu = 0.001, 0.006),
 * where E costs most, weigh least, and are refined least. AVG_TARGET is the albedo's own target
 * (HEMI_BAKE_TARGET, 3e-7) rather than the entries' goal, 8e-6: at 8e-6 the gaussian's few nodes
 * whose default-budget estimate is 1e4 times its error (1.8e-5 against 6e-10 at mu = 0.105,
 * r = 0.52) stay unrefined and make half its E_avg claims (1.2e-6, ggx's 2.2e-7); at 3e-7 the
 * gaussian + smith claims 4.0e-7 instead of 9.7e-7, in about the albedo table's time, and ggx's
 * nodes are the same at both. */
#define AVG_TARGET RC(3e-7)
/* Where alpha < AVG_LAYER_ALPHA the rule starts from two panels, [0, AVG_LAYER_BREAK alpha] and the
 * rest: E(mu) falls within a layer of width ~alpha at the horizon (the Smith and Schlick G1 go from
 * ~1 to ~mu/alpha there), which GK31 over [0, 1] samples with its first node or two only (mu =
 * 0.001, 0.006), and which the rescaled |K31 - G15| then underestimates: ggx + smith-correlated's
 * E_avg was off by 1.1e-7 at r = 1/32 (alpha = 1e-3) against an estimate of 2e-9, by 8e-8 at r =
 * 1/16, 1.8e-8 at r = 5/64, and by at most 7.7e-9 from r = 7/64 (alpha = 0.012) on. Split at 16
 * alpha, the error falls to at most 5e-9 at every r, evaluated in double at the same float nodes
 * (3e-9 at exact nodes; host/cl/runner_avg.cpp corrects for the difference), 4 to 64 alpha all
 * within 1.2e-8 of each other. The reference integrates with breaks at the same scale (host/
 * reference, lobeBreaks). Entries with alpha < 0.01 (r < 0.1) cost one more panel. */
#define AVG_LAYER_ALPHA RC(0.01)
#define AVG_LAYER_BREAK RC(16.0)
/* E_avg's own floor, relative to the value, for the plain (unweighted) average of the pairs with a
 * rescaled estimate (every NDF; host/cl/runner_avg.cpp): added once to the sum of the outer
 * estimates and the
 * nodes' bare estimates (hemisphere_moments_chosen), in place of every node's floor
 * (HEMI_ERR_FLOOR_*, 1e-7 of E at the default budget), which assumed that each node missed by its
 * worst and all in one direction. Measured (tests/tables/microfacet/avg_rule_test.cpp with
 * BRDFBAKE_AVG_SWEEP=1: the
 * bake's rule with E in double at its nodes, every r of 32- and 64-entry tables and a 33-entry node
 * grid, against the reference): beyond the rule's bound E_avg is off by at most 2.1e-9 of its value
 * (beckmann and blinn-phong + schlick-ggx at r = 7/64, alpha = 0.012, just above
 * AVG_LAYER_ALPHA), 3.3e-10 for ggx, 5.3e-12 for the gaussian. The floor keeps a margin of 2.4.
 * For none, cook-torrance, kelemen and neumann (also rescaled) the same sweep over their 16 pairs
 * (BRDFBAKE_AVG_GAFS=0,2,3,4, 48 minutes on the loaded machine) finds at most 7.5e-10 (beckmann +
 * kelemen, r = 1/8), inside the floor. Charlie's averages the same: the same rule with bare
 * estimates in double against the sheen reference's E_avg (Gauss-
 * Legendre 20 and 30 on panels graded towards mu = 0 and split at 1/2, agreeing to 3.6e-9), every r
 * of a 32-entry table (charlie-smith; neubelt too, and its node grid's r = 1/32 to 1/2): never
 * beyond the rule's bound (neubelt's largest error 3.1e-10 of E_avg). */
#define AVG_ERR_FLOOR RC(5e-9)
/* The tabulated exact Lambda's share of E_avg (blinn-phong and the gaussian with smith-exact and
 * smith-correlated-exact). hemi_model_error's 6.6e-7 is the integrand's worst case at one point;
 * averaged over mu and the lobe, the table's errors of both signs largely cancel: in the same
 * sweep,
 * beyond the rule's bound, at most 2.7e-8 of E_avg for blinn-phong (smith-exact, r = 61/64) and
 * 1.16e-7 for the gaussian (smith-exact, r = 99/128). These keep the margin 2.2. */
#define AVG_SMITH_TABLE_ERR_BLINN_PHONG RC(6e-8)
#define AVG_SMITH_TABLE_ERR_GAUSSIAN RC(2.6e-7)
BRDF_FN real avg_model_error(int ndf, int gaf) {
  if (!gaf_lambda_tabulated(ndf, gaf)) return RC(0.0);
  return ndf == NDF_GAUSSIAN ? AVG_SMITH_TABLE_ERR_GAUSSIAN : AVG_SMITH_TABLE_ERR_BLINN_PHONG;
}
/* What E_avg's bound adds to its rule's, relative to the value, where the nodes' estimates are bare. */
BRDF_FN real avg_floor(int ndf, int gaf) { return AVG_ERR_FLOOR + avg_model_error(ndf, gaf); }
/* Where the rule's first panel ends at perceptual roughness r (alpha = r^2). */
BRDF_FN real avg_first_break(real r) {
  real alpha = r * r;
  return alpha > RC(0.0) && alpha < AVG_LAYER_ALPHA ? AVG_LAYER_BREAK * alpha : RC(1.0);
}
BRDF_CONST real AVG_MU[AVG_NODES] = {RC(0.000998850653301469857413579923864), RC(0.00600374098975728575521714070669),
                                     RC(0.0161304621604304328713260106078),   RC(0.0313633037996470478461205261449),
                                     RC(0.0513677338279590495587451717728),   RC(0.0758967082947863918996758396129),
                                     RC(0.104790749278767033516175352591),    RC(0.137791134319914976291906972693),
                                     RC(0.174501629351291514733132052343),    RC(0.214513913695730576231386631373),
                                     RC(0.257459068179880159653172129884),    RC(0.302924326461218315051396314509),
                                     RC(0.350409996423415593916609987867),    RC(0.399402953001282738849685848303),
                                     RC(0.449428966540641250486462884276),    RC(0.5),
                                     RC(0.550571033459358749513537115724),    RC(0.600597046998717261150314151697),
                                     RC(0.649590003576584406083390012133),    RC(0.697075673538781684948603685491),
                                     RC(0.742540931820119840346827870116),    RC(0.785486086304269423768613368627),
                                     RC(0.825498370648708485266867947657),    RC(0.862208865680085023708093027307),
                                     RC(0.895209250721232966483824647409),    RC(0.924103291705213608100324160387),
                                     RC(0.948632266172040950441254828227),    RC(0.968636696200352952153879473855),
                                     RC(0.983869537839569567128673989392),    RC(0.993996259010242714244782859293),
                                     RC(0.999001149346698530142586420076)};
BRDF_CONST real AVG_WK[AVG_NODES] = {RC(0.00268873993646167449389602571506), RC(0.0075039736646580612691873815379),
                                     RC(0.0127304236633576600934370005098),  RC(0.0176731803956879231110189742392),
                                     RC(0.0222948756623824383041136496866),  RC(0.0267407623454640436326715736197),
                                     RC(0.0310047839003353201425696154804),  RC(0.0349270606593641293547600385496),
                                     RC(0.0384248403788601894472163887413),  RC(0.0415402514115665105191446236431),
                                     RC(0.0442822215281058853236377218469),  RC(0.0465632990854126606127434363737),
                                     RC(0.0483213634918118392525899538138),  RC(0.0495867993608959796661965867423),
                                     RC(0.0503849227619377975224733313088),  RC(0.0506650035073957745086873963837),
                                     RC(0.0503849227619377975224733313088),  RC(0.0495867993608959796661965867423),
                                     RC(0.0483213634918118392525899538138),  RC(0.0465632990854126606127434363737),
                                     RC(0.0442822215281058853236377218469),  RC(0.0415402514115665105191446236431),
                                     RC(0.0384248403788601894472163887413),  RC(0.0349270606593641293547600385496),
                                     RC(0.0310047839003353201425696154804),  RC(0.0267407623454640436326715736197),
                                     RC(0.0222948756623824383041136496866),  RC(0.0176731803956879231110189742392),
                                     RC(0.0127304236633576600934370005098),  RC(0.0075039736646580612691873815379),
                                     RC(0.00268873993646167449389602571506)};
BRDF_CONST real AVG_WD[AVG_NODES] = {RC(0.00268873993646167449389602571506), RC(-0.0078726473334005729081268152507),
                                     RC(0.0127304236633576600934370005098),  RC(-0.0175098433483661392436147339862),
                                     RC(0.0222948756623824383041136496866),  RC(-0.0268388478881219238732631997232),
                                     RC(0.0310047839003353201425696154804),  RC(-0.0348582783037130278691423587059),
                                     RC(0.0384248403788601894472163887413),  RC(-0.0415943514969304562574558065976),
                                     RC(0.0442822215281058853236377218469),  RC(-0.0465172009223684449006568445595),
                                     RC(0.0483213634918118392525899538138),  RC(-0.0496289433026598085618625764796),
                                     RC(0.0503849227619377975224733313088),  RC(-0.0506241174553848619316227036),
                                     RC(0.0503849227619377975224733313088),  RC(-0.0496289433026598085618625764796),
                                     RC(0.0483213634918118392525899538138),  RC(-0.0465172009223684449006568445595),
                                     RC(0.0442822215281058853236377218469),  RC(-0.0415943514969304562574558065976),
                                     RC(0.0384248403788601894472163887413),  RC(-0.0348582783037130278691423587059),
                                     RC(0.0310047839003353201425696154804),  RC(-0.0268388478881219238732631997232),
                                     RC(0.0222948756623824383041136496866),  RC(-0.0175098433483661392436147339862),
                                     RC(0.0127304236633576600934370005098),  RC(-0.0078726473334005729081268152507),
                                     RC(0.00268873993646167449389602571506)};

/* Node mu's refinement target (AVG_TARGET above) in an n-node panel rule, w its weight on [0, 1]
 * (any panel: its inner term stays within AVG_TARGET times its length). */
BRDF_FN real avg_target_share(int n, real mu, real w) { return AVG_TARGET / (RC(2.0) * (real)n * mu * w); }
#endif /* BRDF_ALBEDO_AVG_H */
