#!/bin/bash
# Where the split-sum kernel's time goes: times ggx + smith-correlated's 128^2 split sum
# (brdfbake-bench --times-only --repeat 5, three runs each) with parts of the hemisphere rule
# replaced by stand-ins, then restores the kernels and rebuilds:
#   full       the kernel as it is
#   no-refine  no texel refined (the refinement target at 1): what the refined texels cost
#   no-tails   each panel's error estimate left out (the GK15 resasc and gk_error, the trapezoids'
#              difference sums, in the transposed forms too): what the estimates cost beyond the nodes
#   no-nodes   every integrand node replaced by two multiplications, estimates zeroed (so that no
#              texel is refined): what the rule's structure costs without the integrand
#   skeleton   both: the outer nodes' set-up, the arcs' breakpoints and the control flow alone
# The stand-ins compute nonsense; only the times mean anything. Uses ./build (configured).
#   tools/kernel_shares.sh [VARIANT...]      (default: all five; about 6 minutes)
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
files="kernels/integrate/azimuth.h kernels/integrate/azimuth_lanes.h kernels/integrate/hemisphere.h"
for f in $files; do cp "$f" "$f.shares-orig"; done
restore() {
  for f in $files; do mv "$f.shares-orig" "$f"; touch "$f"; done
  cmake --build build --target brdfbake-bench -j2 >/dev/null 2>&1
}
trap restore EXIT
# replace FILE TEXT NEW: one exact replacement, or fail loudly (the kernel changed under the script)
replace() {
  python3 - "$@" <<'PY' || { echo "kernel_shares: text not found in $1: $2" >&2; exit 2; }
import sys
p, a, b = sys.argv[1:4]
s = open(p).read()
if a not in s: sys.exit(1)
open(p, "w").write(s.replace(a, b, 1))
PY
}
# the whole-circle trapezoids in lanes (hemi_trap_lanes): only the value sums, no estimates
trap_lanes_no_tails() {
  replace kernels/integrate/azimuth_lanes.h '  for (int m = 0; m < 3; ++m) {
    BRDF_TABLE real* w = wts[m];' '  for (int m = 0; m < 3; m += 3) {
    BRDF_TABLE real* w = wts[m];'
  replace kernels/integrate/azimuth_lanes.h '  *ea = trap_error16(fabs(sum[2]), fabs(sum[4])) * step;
  *eb = trap_error16(fabs(sum[3]), fabs(sum[5])) * step;' '  *ea = RC(0.0) * step;
  *eb = RC(0.0) * step;'
}
# the arcs in lanes (hemi_arcs_lanes): no resasc, no estimates
arc_lanes_no_tails() {
  replace kernels/integrate/azimuth_lanes.h '    for (int j = 0; j < 16; ++j) v[j] = GK15_WKL[j] * fabs(fa[j] - RC(0.5) * sa);
    lane_t ra = hemi_tree16(v);
    for (int j = 0; j < 16; ++j) v[j] = GK15_WKL[j] * fabs(fb[j] - RC(0.5) * sb);
    lane_t rb = hemi_tree16(v);' '    lane_t ra = RC(1.0), rb = RC(1.0);'
  replace kernels/integrate/azimuth_lanes.h '    lane_t ea_ = gk_error16(fabs(da), ra), eb_ = gk_error16(fabs(db), rb);' \
    '    lane_t ea_ = RC(0.0) * da, eb_ = RC(0.0) * db;'
}
no_tails() {
  trap_lanes_no_tails
  arc_lanes_no_tails
  replace kernels/integrate/azimuth.h '    float2 r2 = lane_sum2(wk * fabs(fa - RC(0.5) * sa), wk * fabs(fb - RC(0.5) * sb));
    ra = r2.x;
    rb = r2.y;
  }
  /* both moments'"'"' gk_error at once: lane by lane gk_error'"'"'s operations, so its bits */
  float2 g2 = gk_error4((float4)(fabs(da), fabs(db), RC(0.0), RC(0.0)), (float4)(ra, rb, RC(0.0), RC(0.0))).xy;
  real ga = g2.x, gb = g2.y;' '  }
  real ga = RC(0.0) * da, gb = RC(0.0) * db;'
  replace kernels/integrate/azimuth.h '  float4 r4 = lane_sum4(wk * fabs(fa1 - RC(0.5) * s1.x), wk * fabs(fb1 - RC(0.5) * s1.y),
                        wk * fabs(fa2 - RC(0.5) * s2.x), wk * fabs(fb2 - RC(0.5) * s2.y));
  float4 g4 = gk_error4((float4)(fabs(s1.z), fabs(s1.w), fabs(s2.z), fabs(s2.w)), r4);' \
    '  float4 g4 = RC(0.0) * (float4)(s1.z, s1.w, s2.z, s2.w);'
  replace kernels/integrate/azimuth.h '    float2 c2 = lane_sum2(ek * fa, ek * fb);' '    float2 c2 = (float2)(RC(0.0), RC(0.0));'
  replace kernels/integrate/azimuth.h '  *ea = trap_error(fabs(t.da), fabs(t.ca)) * step;
  *eb = trap_error(fabs(t.db), fabs(t.cb)) * step;' '  *ea = RC(0.0);
  *eb = RC(0.0);'
  replace kernels/integrate/hemisphere.h '  res->err_a += gk_error(fabs(pda), ra, 1) + pea;
  res->err_b += gk_error(fabs(pdb), rb, 1) + peb;' '  res->err_a += RC(0.0) * (ra + pea);
  res->err_b += RC(0.0) * (rb + peb);'
}
no_nodes() {
  replace kernels/integrate/azimuth_lanes.h '      hemi_node_c(ndf, gaf, p, mu, s, c, sn, cos_arc(phi), &fa[j], &fb[j]);' \
    '      fa[j] = phi * sn;
      fb[j] = phi * phi;'
  replace kernels/integrate/azimuth_lanes.h '    lane_t ea_ = gk_error16(fabs(da), ra), eb_ = gk_error16(fabs(db), rb);' \
    '    lane_t ea_ = RC(0.0) * gk_error16(fabs(da), ra), eb_ = RC(0.0) * gk_error16(fabs(db), rb);'
  replace kernels/integrate/azimuth_lanes.h 'for (int q = 0; q < 4; ++q) hemi_node_c(ndf, gaf, p, mu, s, c, sn, COS_PI16[js[q]], &fa[q], &fb[q]);' \
    'for (int q = 0; q < 4; ++q) { fa[q] = c * COS_PI16[js[q]] + RC(2.0); fb[q] = sn * sn; }'
  replace kernels/integrate/azimuth_lanes.h '  hemi_node_c(ndf, gaf, p, mu, s, c, sn, RC(-1.0), &fa, &fb);' '  fa = c;
  fb = sn;'
  replace kernels/integrate/azimuth_lanes.h '  *ea = trap_error16(fabs(sum[2]), fabs(sum[4])) * step;
  *eb = trap_error16(fabs(sum[3]), fabs(sum[5])) * step;' '  *ea = RC(0.0) * trap_error16(fabs(sum[2]), fabs(sum[4]));
  *eb = RC(0.0) * trap_error16(fabs(sum[3]), fabs(sum[5]));'
  replace kernels/integrate/azimuth.h 'hemi_node(ndf, gaf, p, mu, s, h, sn, cos_arc(mid + hw * x), fa, fb);' \
    '{ lane_t cc = mid + hw * x; *fa = cc * sn; *fb = cc * cc; }'
  replace kernels/integrate/azimuth.h 'hemi_node(ndf, gaf, p, mu, s, h, sn, cos_arc(phi), fa, fb);' '{ *fa = phi * sn; *fb = phi * phi; }'
  replace kernels/integrate/azimuth.h 'hemi_node(ndf, gaf, p, mu, s, h, sn, lane_load(cs, k), &fa, &fb);' \
    '{ lane_t cc = lane_load(cs, k); fa = cc * sn + RC(2.0); fb = cc * cc; }'
  replace kernels/integrate/hemisphere.h 'hemi_node_c(ndf, gaf, p, mu, s, lane_load(nc, k), lane_load(nsn, k), RC(-1.0), &fa, &fb);' \
    'fa = lane_load(nc, k); fb = lane_load(nsn, k);'
  # no texel refined: the estimates are zero
  replace kernels/integrate/azimuth.h '  *ea += ga * hw;
  *eb += gb * hw;' '  *ea += RC(0.0) * ga;
  *eb += RC(0.0) * gb;'
  replace kernels/integrate/azimuth.h '  float4 g4 = gk_error4(' '  float4 g4 = RC(0.0) * gk_error4('
  replace kernels/integrate/azimuth.h '  *ea = trap_error(fabs(t.da), fabs(t.ca)) * step;' '  *ea = RC(0.0) * trap_error(fabs(t.da), fabs(t.ca));'
  replace kernels/integrate/azimuth.h '  *eb = trap_error(fabs(t.db), fabs(t.cb)) * step;' '  *eb = RC(0.0) * trap_error(fabs(t.db), fabs(t.cb));'
  replace kernels/integrate/hemisphere.h '  res->err_a += gk_error(fabs(pda), ra, 1) + pea;
  res->err_b += gk_error(fabs(pdb), rb, 1) + peb;' '  res->err_a += RC(0.0) * (gk_error(fabs(pda), ra, 1) + pea);
  res->err_b += RC(0.0) * (gk_error(fabs(pdb), rb, 1) + peb);'
}
no_refine() {
  replace kernels/integrate/hemisphere.h '#define HEMI_BAKE_TARGET 3e-7' '#define HEMI_BAKE_TARGET 1.0'
}
skeleton() {
  no_nodes
  replace kernels/integrate/azimuth_lanes.h 'BRDF_FN lane_t hemi_tree16(const lane_t* v) {' 'BRDF_FN lane_t hemi_tree16(const lane_t* v) {
  return v[0];'
  replace kernels/integrate/azimuth_lanes.h '  for (int m = 0; m < 3; ++m) {
    BRDF_TABLE real* w = wts[m];' '  for (int m = 0; m < 3; m += 3) {
    BRDF_TABLE real* w = wts[m];'
  replace kernels/integrate/azimuth_lanes.h '  *ea = RC(0.0) * trap_error16(fabs(sum[2]), fabs(sum[4]));
  *eb = RC(0.0) * trap_error16(fabs(sum[3]), fabs(sum[5]));' '  *ea = RC(0.0) * step;
  *eb = RC(0.0) * step;'
  replace kernels/integrate/azimuth.h '  float4 s1 = lane_sum4(wk * fa1, wk * fb1, wd * fa1, wd * fb1);
  float4 s2 = lane_sum4(wk * fa2, wk * fb2, wd * fa2, wd * fb2);
  float4 r4 = lane_sum4(wk * fabs(fa1 - RC(0.5) * s1.x), wk * fabs(fb1 - RC(0.5) * s1.y),
                        wk * fabs(fa2 - RC(0.5) * s2.x), wk * fabs(fb2 - RC(0.5) * s2.y));
  float4 g4 = RC(0.0) * gk_error4((float4)(fabs(s1.z), fabs(s1.w), fabs(s2.z), fabs(s2.w)), r4);' \
    '  float4 s1 = (float4)(wk.s0 * fa1.s0, wk.s1 * fb1.s1, RC(0.0), RC(0.0));
  float4 s2 = (float4)(wk.s0 * fa2.s0, wk.s1 * fb2.s1, RC(0.0), RC(0.0));
  float4 g4 = (float4)(RC(0.0));'
  replace kernels/integrate/azimuth.h '    float2 r2 = lane_sum2(wk * fabs(fa - RC(0.5) * sa), wk * fabs(fb - RC(0.5) * sb));
    ra = r2.x;
    rb = r2.y;
  }
  /* both moments'"'"' gk_error at once: lane by lane gk_error'"'"'s operations, so its bits */
  float2 g2 = gk_error4((float4)(fabs(da), fabs(db), RC(0.0), RC(0.0)), (float4)(ra, rb, RC(0.0), RC(0.0))).xy;
  real ga = g2.x, gb = g2.y;' '  }
  real ga = RC(0.0), gb = RC(0.0);'
  replace kernels/integrate/azimuth.h '    float4 s4 = lane_sum4(wk * fa, wk * fb, wd * fa, wd * fb);' \
    '    float4 s4 = (float4)(wk.s0 * fa.s0, wk.s1 * fb.s1, RC(0.0), RC(0.0));'
  replace kernels/integrate/azimuth.h '    float4 s4 = lane_sum4(wk * fa, wk * fb, dk * fa, dk * fb); /* compat.h */
    float2 c2 = lane_sum2(ek * fa, ek * fb);' '    float4 s4 = (float4)(wk.s0 * fa.s0, fb.s0, RC(0.0), RC(0.0));
    float2 c2 = (float2)(RC(0.0), RC(0.0));'
}
time_it() {
  if ! cmake --build build --target brdfbake-bench -j2 >/tmp/kernel-shares-build.log 2>&1; then
    echo "kernel_shares: $1 did not build"; tail -5 /tmp/kernel-shares-build.log; exit 2
  fi
  ./build/brdfbake-bench --times-only --pair ggx+smith-correlated --repeat 1 >/dev/null 2>&1  # compiles the program
  local t=""
  for r in 1 2 3; do
    t="$t $(./build/brdfbake-bench --times-only --pair ggx+smith-correlated --repeat 5 2>&1 |
            sed -n 's/.*quadrature (OpenCL) \([0-9.]*\) s.*(\([0-9]*\) texels refined.*/\1/p')"
  done
  printf '%-10s %s s\n' "$1" "$t"
}
variants=${*:-full no-refine no-tails no-nodes skeleton}
for v in $variants; do
  for f in $files; do cp "$f.shares-orig" "$f"; done
  case "$v" in
    full) ;;
    no-refine) no_refine ;;
    no-tails) no_tails ;;
    no-nodes) no_nodes ;;
    skeleton) skeleton ;;
    *) echo "kernel_shares: unknown variant $v (full, no-refine, no-tails, no-nodes, skeleton)" >&2; exit 64 ;;
  esac
  time_it "$v"
done
