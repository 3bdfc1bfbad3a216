#!/bin/bash
# Shows that a test bites: applies one named mutation to a source file in place, rebuilds, runs the
# tests that must then fail, and restores the file (and the build) whatever happens.
#   tools/bite.sh NAME     one mutation;  tools/bite.sh all   every one;  tools/bite.sh list
# Exit 0 when every mutation's tests failed, 1 when one survived (its tests passed).
# Uses ./build (configured); runs ctest with POCL_CACHE_DIR=build/pocl-cache.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
# each mutation: name, file, text, replacement, the ctest regex that must then fail
mutation() {
  case "$1" in
    browser-image) set -- "$1" host/report/report_page.cpp '.svg\" alt=' '.svg-missing\" alt=' \
                     "CliEvidence.VerifyPassesTheDefaultPair" ;;
    program-identity) set -- "$1" host/cl/program_cache.cpp 'if (!id || *id != identity) continue;' \
                        'if (!id) continue;' "FirstRun.StaleForeignOrTornEntries" ;;
    program-checksum) set -- "$1" host/cl/program_cache.cpp 'sum != entryHash(bin.data(), bin.size()) || ' 'false || ' \
                        "FirstRun.StaleForeignOrTornEntries" ;;
    progress-on-pipe) set -- "$1" host/cli/console.cpp 'const bool progress = (!quiet && terminal) || forceProgress;' \
                        'const bool progress = !quiet || forceProgress;' "FirstRun.ProgressLineOnATerminalOnly" ;;
    driver-guards) set -- "$1" host/main.cpp '  installDriverGuards();' '' "Hostile.TheDriversOwnFailuresAreSaid" ;;
    exr-header-sizes) set -- "$1" host/formats/exr/exr_reader.cpp 'checkHeaderSizes(path, checkInputFile(path, "", kCapTable));' \
                        'checkInputFile(path, "", kCapTable);' "FormatsRead.MutatedRealFilesAreReadOrRefused" ;;
    scene-size-keys) set -- "$1" host/scene/scene_plan.cpp 'if (!k || !k->inScenes) {' 'if (!k) {' \
                       "Scene.OutputSizeKeysAreTheKindsScenesPlan" ;;
    kind-twice) set -- "$1" host/tables/microfacet/microfacet.cpp 'return {splitsum, albedo, avg, kp};' \
                  'return {splitsum, albedo, avg, kp, kp};' "Registry.EveryKindIsDescribedOnceByAFamilyThatBakesIt" ;;
    library-holds-a-client) set -- "$1" CMakeLists.txt '  host/tables/registry.cpp' \
                              '  host/tables/registry.cpp host/report/energy.cpp' "CMakePackage.Consumer_installed" ;;
    render-lobe) set -- "$1" host/render/furnace.cpp 'v = vec3(e + a);' 'v = vec3(e + 0.9 * a);' \
                   "Render.DefaultBoundsAreLocalAndTight" ;;
    render-glass) set -- "$1" host/render/furnace.cpp 'v = vec3(glassE(mu, r));' 'v = vec3(glassE(mu, r) * 1.001);' \
                    "Render.FurnaceRowsVanish" ;;
    render-single) set -- "$1" host/render/furnace.cpp 'v = vec3(ab.x + ab.y);' 'v = vec3(ab.x + 0.95 * ab.y);' \
                     "Render.DefaultBoundsAreLocalAndTight" ;;
    render-glass-dark) set -- "$1" host/render/furnace.cpp 'v = vec3(glassE(mu, r));' 'v = vec3(glassE(mu, r) * 0.97);' \
                         "Render.DefaultBoundsAreLocalAndTight" ;;
    glass-eta-axis) set -- "$1" host/shader/atlas_lookups.cpp 's += "  float s = (eta - 1.0) / (eta + 1.0);\n";' \
                      's += "  float s = (eta - 1.0) / (eta + 1.5);\n";' "GlPipeline.GeneratedGlslSamplesTheDielectricTablesByEta" ;;
    beckmann-fit) set -- "$1" kernels/brdf/ndf.h 'RC(0.56851845943975654)' 'RC(0.5685)' \
                    "FloatForms.BeckmannLambda" ;;
    beckmann-compensation) set -- "$1" kernels/brdf/ndf.h '* (RC(1.0) + RC(2.0) * d);' ';' \
                             "FloatForms.BeckmannLambdaRoundingIsCompensated" ;;
    cos-arc) set -- "$1" kernels/integrate/azimuth.h 'RC(-0.16666666592166149)' 'RC(-0.1666667)' \
               "FloatForms.CosArc" ;;
    view-once) set -- "$1" kernels/integrate/integrand.h 'p.view_cl = gaf_view_cLambda(gaf, ndf, p, mu, s * s);' \
                 'p.view_cl = gaf_view_cLambda(gaf, ndf, p, mu, s);' "FloatForms.ViewSetOncePerTexel" ;;
    polynomial-arc) set -- "$1" kernels/brdf/gaf.h 'gaf == GAF_NEUMANN || gaf == GAF_COOK_TORRANCE;' \
                      'gaf == GAF_NEUMANN || gaf == GAF_COOK_TORRANCE || gaf == GAF_KELEMEN;' \
                      "AllPairs/PairTest.*/ggx_kelemen" ;;
    canonical-gaf) set -- "$1" kernels/brdf/gaf.h 'if (ndf != NDF_GGX && ndf != NDF_BECKMANN) return gaf;' \
                     'if (ndf != NDF_GGX && ndf != NDF_BECKMANN && ndf != NDF_BLINN_PHONG) return gaf;' \
                     "Gaf.CanonicalGivesTheSameBits|KernelReuse.RepeatsReturnWhatRunningGives" ;;
    trap-pi-batch) set -- "$1" kernels/integrate/hemisphere.h 'lane_load(nsn, k), RC(-1.0), &fa, &fb);' \
                     'lane_load(nsn, k), RC(-0.999), &fa, &fb);' "AllPairs/PairTest.HemisphereMatchesReference/ggx_smith_correlated" ;;
    ggx-one-division) set -- "$1" kernels/brdf/gaf.h 'g = ni * q / (ni * q * (no + clo) + RC(0.5) * no * x);' \
                        'g = ni * q / (ni * q * (no + clo) + RC(0.5) * x);' "Gaf.KernelFormsMatchTheReferencesOwnFormulas" ;;
    trap-lanes) set -- "$1" kernels/integrate/azimuth_lanes.h '  int js[4] = {i, i + 8, i + 1, i + 9};' \
                  '  int js[4] = {i, i + 1, i + 8, i + 9};' "Golden.MicrofacetTables" ;;
    arc-lanes) set -- "$1" kernels/integrate/azimuth_lanes.h '    int16 on = (int16)(m) < count;' '    int16 on = (int16)(m) <= count;' \
                 "Golden.MicrofacetTables" ;;
    gk-pair) set -- "$1" kernels/integrate/azimuth.h '  *ka += s2.x * hw2;' '  *ka += s2.x * hw1;' \
               "AllPairs/PairTest.HemisphereMatchesReference/ggx_smith_correlated" ;;
    lane-sum4) set -- "$1" kernels/brdf/compat.h 'float16 x = (float16)(ab.even + ab.odd, cd.even + cd.odd);' \
                 'float16 x = (float16)(cd.even + cd.odd, ab.even + ab.odd);' \
                 "AllPairs/PairTest.HemisphereMatchesReference/ggx_smith_correlated" ;;
    devices-stale) set -- "$1" host/cl/program_cache.cpp 'current = f == hex64(entryHash(want)) + ".clbin" && *id == want;' \
                     'current = f == hex64(entryHash(want)) + ".clbin";' "FirstRun.DevicesPreparesAndListsPrograms" ;;
    node-reuse) set -- "$1" host/cl/runner_launch.cpp '(*known[k])[q] : out[q][next];' '(*known[k])[q] : out[q][0];' \
                  "KernelReuse.NodesOverlapping" ;;
    fresnel-eta-z) set -- "$1" host/cl/runner_launch.cpp 'w.z = static_cast<float>(' 'w.z = 0 * static_cast<float>(' \
                     "FresnelEdge.FloatEtaAloneMissesByHundredsOfClaims" ;;
    fresnel-kink-offset) set -- "$1" kernels/integrate/integrand.h '  return fresnel_F_g2(p.fresnel, p.fr_x, p.fr_z, oh, dc * (oh + ck));' \
                           '  return fresnel_F_g2(p.fresnel, p.fr_x, p.fr_z, oh, oh * oh - ck * ck);' "FresnelEdge.TheSweepsEdgesHold" ;;
    fresnel-float-model) set -- "$1" host/tables/error_model.h 'constexpr FloatModel kFresnelFloat{10, 4};' \
                           'constexpr FloatModel kFresnelFloat{6, 3};' "FresnelEdge.TheSweepsEdgesHold" ;;
    fresnel-layer) set -- "$1" kernels/brdf/fresnel.h '  return w < FRESNEL_GRADE_MAX ? w : RC(0.0);' '  return RC(0.0);' \
                     "FresnelEdge.StiffCornerWithinItsClaim" ;;
    fresnel-claim-inflated) set -- "$1" kernels/bake.cl '    out_err[t] = hemi_rel_error(h);' \
                              '    out_err[t] = 10.0f * hemi_rel_error(h);' "FresnelEdge.StiffCornerWithinItsClaim" ;;
    ltc-polygon-transposed) set -- "$1" host/shader/shader_gen.cpp '"(invM.x * l.x + invM.z * l.z, l.y, invM.y * l.x + invM.w * l.z);' \
                              '"(invM.x * l.x + invM.y * l.z, l.y, invM.z * l.x + invM.w * l.z);' "Ltc.QuadLightRender" ;;
    ltc-distance-halved) set -- "$1" kernels/integrate/ltc_fit.h '    real t = RC(0.5) * ltc_l1(L, l, n, su, sv, &below);' \
                           '    real t = RC(0.25) * ltc_l1(L, l, n, su, sv, &below);' "Ltc.DistanceEstimateHolds" ;;
    ltc-distance-in-float) set -- "$1" host/tables/ltc/ltc_fit.cpp '      if (e[t] >= kLtcNegligibleE && ltcMeasuredInDouble(lobe, x, y, n)) at.push_back(t);' \
                             '      if (false) at.push_back(t);' "Ltc.DistanceEstimateHoldsAgainstTheReference" ;;
    ltc-variance-one-pass) set -- "$1" kernels/integrate/ltc_fit.h '  real var = m2 / (real)(reps > 1 ? reps - 1 : 1);' \
                             '  real var = RC(0.0) * m2;' "Ltc.DistanceEstimateHoldsAgainstTheReference" ;;
    ltc-claim-without-tenth) set -- "$1" kernels/integrate/ltc_fit.h ' + RC(0.1) * fabs(mean);' ';' \
                               "LtcSweep.DistanceEstimateHoldsAtEverySecondRow" ;;
    ltc-e-claim-without-float) set -- "$1" host/tables/ltc/ltc_fit.cpp 'f.eBound[t] = p[1][t] + floatArithmeticError(' \
                                 'f.eBound[t] = p[1][t] + 0 * floatArithmeticError(' "Ltc.MagnitudeWithinItsClaim" ;;
    avg-kink-breaks) set -- "$1" host/cl/runner_avg.cpp '  if (kink > 0) {' '  if (false) {' \
                       "FresnelEdge.AverageAlbedoAtTheStiffCorner" ;;
    glass-reference-kink) set -- "$1" host/reference/dielectric_reference.cpp '  if (s.eta < 1) kinks.push_back(' \
                            '  if (false) kinks.push_back(' "Dielectric.ReferencesAgreeNextToTheCriticalCosine" ;;
    f82-share-of-e) set -- "$1" host/tables/error_model.h 'return cancels ? std::max(plain, 0.3 * kUnitRoundoff' \
                      'return cancels ? std::max(plain, 0.0 * kUnitRoundoff' "FresnelEdge.TheSweepsEdgesHold" ;;
    corner-block-offset) set -- "$1" tests/tables/microfacet/fresnel_edge_test.cpp 'hi = static_cast<float>(bi + 4) / n;' \
                           'hi = static_cast<float>(bi + 4.001) / n;' "FresnelEdge.CornerBlocksAreTheTable" ;;
    doc-figure) set -- "$1" docs/materials.md '  F_avg (2 int F mu dmu, closed form): 0.0857143' \
                  '  F_avg (2 int F mu dmu, closed form): 0.0957143' "Docs.ShownCommandsPrintWhatThePagesShow" ;;
    favg-tir-part) set -- "$1" host/reference/fresnel_reference.cpp '  return oc * oc + detail::adapt(graded' \
                     '  return detail::adapt(graded' "Fresnel.AverageFresnelClosedFormsAndQuadrature" ;;
    glass-reference-outer) set -- "$1" host/reference/dielectric_reference.cpp 'br[k + 1], 1e-9, 14, 1e-9);' \
                             'br[k + 1], 1e-8, 10, 1e-8);' "CliEvidence.StressIsCleanAndWritesItsPage" ;;
    doc-quoted-figure) set -- "$1" docs/convergence.md '0.42 at 8, 16 and 32 texels per axis' \
                         '0.24 at 8, 16 and 32 texels per axis' "Docs.QuotedFiguresAreWhatTheirCommandsPrint" ;;
    doc-figure-note) set -- "$1" docs/convergence.md '<!-- figure 0.85 after "16 texels per axis" #3' \
                       '<!-- figure 0.97 after "16 texels per axis" #3' "Docs.QuotedFiguresAreWhatTheirCommandsPrint" ;;
    doc-figure-form) set -- "$1" docs/convergence.md '<!-- figure 0.85 after "16 texels per axis" #3 from: brdfbake' \
                       '<!-- figure 0.85 after "16 texels per axis" #3 from brdfbake' "Docs.QuotedFiguresAreWhatTheirCommandsPrint" ;;
    doc-test-figure) set -- "$1" tests/tables/dielectric/dielectric_test.cpp \
                       'worst device error against the reference %.2e\n", worst);' \
                       'worst device error against the reference %.2e\n", 2 * worst);' \
                       "Docs.QuotedFiguresAreWhatTheirCommandsPrint" ;;
    doc-test-name) set -- "$1" docs/rough-glass.md 'from: ctest -R Dielectric.KernelMatchesReference -V' \
                     'from: ctest -R Dielectric.KernelMatchesReferenc -V' "Docs.QuotedFiguresAreWhatTheirCommandsPrint" ;;
    doc-bench-figure) set -- "$1" docs/accuracy.md '<!-- figure 2.59e-7 after "splitsum" #2 from: brdfbake-bench' \
                        '<!-- figure 2.59e-7 after "splitsum" #3 from: brdfbake-bench' "Docs.QuotedFiguresAreWhatTheirCommandsPrint" ;;
    doc-test-named) set -- "$1" docs/ltc.md '`Ltc.DistanceEstimateHoldsAgainstTheReference`' \
                      '`Ltc.DistanceEstimateHoldsAgainstAQuadrature`' "Docs.NamedTestsExist" ;;
    avg-claim-inflated) set -- "$1" host/cl/runner_avg.cpp '        (sums[j].bound + floor * std::fabs(sum)' \
                          '        (10 * sums[j].bound + floor * std::fabs(sum)' "FresnelEdge.AverageAlbedoAtTheStiffCorner" ;;
    doc-table-row) set -- "$1" docs/layouts.md '| `bevy` (32^2, ktx2) | 4.31e-3 |' '| `bevy` (32^2, ktx2) | 4.51e-3 |' \
                     "GlPipeline.LayoutPresetsMatchEachEnginesOwnLookup" ;;
    doc-rows-unchecked) set -- "$1" tests/mu_axis_test.cpp '  testing_docs::expectPagesQuote(table);' '' \
                          "Docs.InNotesNameTestsThatCheckThePages" ;;
    doc-figure-untied) set -- "$1" docs/shader-code.md '<!-- inputs: 1e-5 -->' '' \
                         "Docs.EveryFigureOnEveryPageIsTiedOrAnInput" ;;
    doc-build-path) set -- "$1" docs/ashikhmin-shirley.md '`./build/tests/brdfbake-ashikhmin-tests' \
                      '`build-as/tests/brdfbake-ashikhmin-tests' "Docs.NamedBuildPathsExist" ;;
    doc-rows-from) set -- "$1" docs/benchmarks-materials.md '| burley E_d, r in [0, 1] | ~0.0022 | ~0.0058 | ~0.38 | 2.12e-7 |' \
                     '| burley E_d, r in [0, 1] | ~0.0022 | ~0.0058 | ~0.38 | 2.32e-7 |' "Docs.QuotedFiguresAreWhatTheirCommandsPrint" ;;
    doc-in-figure) set -- "$1" tests/tables/brdf3d/brdf3d_test.cpp '|f|)\n", worstRel,' '|f|)\n", 2 * worstRel,' \
                     "Brdf3d.KernelMatchesHostEvaluation" ;;
    doc-bounds-row) set -- "$1" docs/accuracy.md '| ggx+schlick-ggx | albedo | 6.09e-7 | 1.40e-7 | 4.3 |' \
                      '| ggx+schlick-ggx | albedo | 6.09e-7 | 1.40e-7 | 3.8 |' "BoundsSweep.TheBenchmarksTableIsThePages" ;;
    doc-merl-figure) set -- "$1" tests/tables/measured/merl_test.cpp '        e.nodes - 1, tight, std::fabs(e.e[0] - tight), e.err[0]);' \
                       '        e.nodes - 1, tight, 2 * std::fabs(e.e[0] - tight), e.err[0]);' \
                       "MerlAlbedo.EstimateHoldsOnAFilesInterpolantAtGrazingViews" ;;
    doc-merl-row) set -- "$1" docs/merl.md '| ggx r 0.8 | 3.56e-9 | 2.79e-9 | 1.28 |' '| ggx r 0.8 | 3.56e-9 | 2.79e-9 | 1.48 |' \
                    "MerlSweep.TheBenchmarksTablesAreThePages" ;;
    merl-claim-storage) set -- "$1" host/materials/merl_albedo.cpp '(est[i].err[c] + std::fabs(stored - est[i].e[c]))' \
                          '(est[i].err[c])' "MerlSweep.TheBenchmarksTablesAreThePages" ;;
    doc-outer-breaks) set -- "$1" tools/outer_breaks.sh 'est[est.size() / 2], est[est.size() * 9 / 10]' \
                        'est[est.size() / 3], est[est.size() * 9 / 10]' "OuterBreaksSweep.TheScriptsFiguresAreThePages" ;;
    doc-avg-miss) set -- "$1" tests/tables/microfacet/avg_rule_test.cpp 'ndfNames()[ndf].c_str(), gafNames()[gaf].c_str(), miss, at,' \
                    'ndfNames()[ndf].c_str(), gafNames()[gaf].c_str(), 1.5 * miss, at,' \
                    "MicrofacetNdfs/AvgRule.BoundHoldsWithTheFloorsMeasuredOnTheAverage/beckmann" ;;
    doc-whole-run) set -- "$1" tests/tables/microfacet/accuracy_test.cpp 'gWorstFloat, gWorstFloatAt.c_str(), gWorstMiss[0], gWorstMiss[1]);' \
                     'gWorstFloat, gWorstFloatAt.c_str(), gWorstMiss[0], 2 * gWorstMiss[1]);' \
                     "AccuracySweep.TheWholeRunsMissesAreThePages" ;;
    bench-tables-ignored) set -- "$1" host/bench/bounds_bench.cpp '      if (!wanted(kind)) continue;' '' \
                            "Bench.BoundsTablesPicksTheRowsAndRefusesOthers" ;;
    doc-in-test-parameterised) set -- "$1" tests/readme_test.cpp "sourceSuite = suite.substr(suite.find('/') + 1)" \
                                 'sourceSuite = suite' "Docs.InNotesNameTestsThatCheckThePages" ;;
    doc-decimal-unmarked) set -- "$1" docs/performance.md '| default set (4 tables), warm | ~0.073,' \
                            '| default set (4 tables), warm | 0.073,' \
                            "Docs.EveryFigureOnEveryPageIsTiedOrAnInput" ;;
    doc-ltc-distance) set -- "$1" tests/tables/ltc/ltc_distance_test.cpp 'lobe.name().c_str(), n, texels.size(), worst, inDouble);' \
                        'lobe.name().c_str(), n, texels.size(), 1.3 * worst, inDouble);' \
                        "Ltc.DistanceEstimateHoldsAgainstTheReference" ;;
    doc-per-ndf-u) set -- "$1" tests/tables/microfacet/accuracy_test.cpp 'ndfNames()[ndf].c_str(), w.u, w.at.c_str()' \
                     'ndfNames()[ndf].c_str(), 0.8 * w.u, w.at.c_str()' \
                     "AccuracySweep.TheWholeRunsMissesAreThePages" ;;
    doc-float-eta) set -- "$1" tests/tables/microfacet/fresnel_edge_test.cpp \
                     'rel(atFloat, want) / claim, claim,' 'rel(atFloat, want) / claim / 1.3, claim,' \
                     "FresnelEdge.FloatEtaAloneMissesByHundredsOfClaims" ;;
    doc-corner-limit) set -- "$1" tests/tables/microfacet/accuracy_test.cpp 'lookup, ref, at(0, 0));' \
                        'lookup, ref, 0.9 * at(0, 0));' "Docs.QuotedFiguresAreWhatTheirCommandsPrint" ;;
    doc-fresnel-sweep-max) set -- "$1" tests/tables/microfacet/fresnel_edge_test.cpp \
                             'worst.all.ratio, worst.ratioAt.c_str(), worst.all.claimOver, worst.overAt.c_str());' \
                             'worst.all.ratio, worst.ratioAt.c_str(), 0.9 * worst.all.claimOver, worst.overAt.c_str());' \
                             "FresnelSweep.EveryPairEverySize" ;;
    doc-ratio-operand) set -- "$1" docs/materials.md '<!-- ratio 3.6 = 6.93e-7 / 1.91e-7 -->' \
                         '<!-- ratio 3.6 = 6.77e-7 / 1.91e-7 -->' "Docs.EveryFigureOnEveryPageIsTiedOrAnInput" ;;
    sheen-avg-float-model) set -- "$1" host/tables/error_model.h 'constexpr FloatModel kAvgFloatSheen{0, 4};' \
                             'constexpr FloatModel kAvgFloatSheen{0, 2.9};' "Sheen.FloatArithmeticWithinItsModels" ;;
    doc-node-counts) set -- "$1" tools/node_counts.sh 'printf "  %-30s %12d  %5.1f%%\n", w, x, 100 * x / t' \
                       'printf "  %-30s %12d  %5.1f%%\n", w, x, 90 * x / t' "Docs.NodeCountsFiguresAreTheScripts" ;;
    sheen-lobe-break) set -- "$1" host/cl/runner_avg.cpp 'if (sheen && r < 1.0f / 64) out.push_back(16.0 * r);' \
                        'if (false && r < 1.0f / 64) out.push_back(16.0 * r);' "Sheen.AlbedoAvgHoldsItsLobeAtTheSmallestR" ;;
    sheen-lobe-break-shown) set -- "$1" tests/tables/microfacet/host_avg_rule.h 'breaks.sheen = breaks.sheen && sheenLobeBreak;' \
                              'breaks.sheen = breaks.sheen || sheenLobeBreak;' "Sheen.AlbedoAvgHoldsItsLobeAtTheSmallestR" ;;
    doc-example-option) set -- "$1" docs/rough-glass.md '--eta-range 0.5,2 --size 16 --half' \
                          '--eta-rang 0.5,2 --size 16 --half' "Docs.EveryPageExampleRuns" ;;
    dry-run-status) set -- "$1" host/bake/bake_report.cpp 'there ? "replaces" : "new"' '"new"' \
                      "Cli.DryRunListsWhatABakeWouldWriteAndWritesNothing" ;;
    kind-name) set -- "$1" host/tables/microfacet/microfacet.cpp 'KindInfo avg{TableKind::AlbedoAvg, "albedo-avg"}' \
                 'KindInfo avg{TableKind::AlbedoAvg, "albedo_avg"}' "Registry.EveryKindIsDescribedOnceByAFamilyThatBakesIt" ;;
    *) return 64 ;;
  esac
  run_one "$@"
}
names="browser-image program-identity program-checksum progress-on-pipe render-lobe render-glass render-single render-glass-dark glass-eta-axis
       beckmann-fit beckmann-compensation cos-arc view-once polynomial-arc
       canonical-gaf trap-pi-batch ggx-one-division trap-lanes arc-lanes gk-pair lane-sum4 node-reuse devices-stale
       fresnel-eta-z fresnel-layer fresnel-claim-inflated fresnel-kink-offset fresnel-float-model
       driver-guards exr-header-sizes kind-twice scene-size-keys library-holds-a-client
       ltc-polygon-transposed ltc-distance-halved ltc-distance-in-float ltc-variance-one-pass ltc-claim-without-tenth
       ltc-e-claim-without-float avg-kink-breaks glass-reference-kink
       favg-tir-part glass-reference-outer f82-share-of-e doc-figure corner-block-offset
       doc-quoted-figure doc-figure-note doc-figure-form doc-test-figure doc-test-name doc-bench-figure doc-test-named avg-claim-inflated
       doc-table-row doc-rows-unchecked doc-figure-untied doc-build-path doc-rows-from doc-in-figure doc-bounds-row
       doc-merl-figure doc-merl-row merl-claim-storage doc-outer-breaks doc-avg-miss doc-whole-run
       bench-tables-ignored doc-in-test-parameterised doc-decimal-unmarked doc-ltc-distance doc-per-ndf-u doc-float-eta doc-corner-limit doc-fresnel-sweep-max doc-ratio-operand
       sheen-avg-float-model doc-node-counts sheen-lobe-break sheen-lobe-break-shown
       doc-example-option dry-run-status kind-name"
run_one() {
  local name=$1 file=$2 from=$3 to=$4 tests=$5
  cp "$file" "$file.bite-orig"
  # restored with a fresh time stamp, so that the next build recompiles it without the mutation
  trap 'mv "$file.bite-orig" "$file"; touch "$file"; trap - RETURN' RETURN
  python3 - "$file" "$from" "$to" <<'PY' || { echo "bite $name: the text to mutate is not in $file"; return 2; }
import sys
p, a, b = sys.argv[1:4]
s = open(p).read()
if a not in s: sys.exit(1)
open(p, "w").write(s.replace(a, b, 1))
PY
  if ! cmake --build build -j2 >/tmp/bite-build.log 2>&1; then echo "bite $name: did not build"; tail -5 /tmp/bite-build.log; return 2; fi
  if (cd build && POCL_CACHE_DIR=$PWD/pocl-cache ctest -R "$tests" >/tmp/bite-test.log 2>&1); then
    echo "bite $name: SURVIVED ($tests passed)"; return 1
  fi
  echo "bite $name: caught by $tests"
}
case "${1:-}" in
  list) for m in $names; do echo "$m"; done ;;
  all|"")
    status=0
    for m in $names; do mutation "$m" || status=1; done
    cmake --build build -j2 >/dev/null 2>&1
    exit $status ;;
  *)
    mutation "$1"; s=$?
    [ $s -eq 64 ] && { echo "unknown mutation $1 (tools/bite.sh list)" >&2; exit 64; }
    cmake --build build -j2 >/dev/null 2>&1
    exit $s ;;
esac
