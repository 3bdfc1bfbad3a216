#!/bin/sh
# Where a split sum's integrand evaluations go: the hemisphere estimator's rule (kernels/integrate)
# compiled for the host in float, one lane (brdf32, host/common/brdf_host.h), with gcov counting
# the lines that evaluate the integrand, over every texel centre of an N x N table at the bake's
# target. On the host one call is one node, so the counts are nodes:
#   tools/node_counts.sh [NDF GAF [N]]      (default: GGX SMITH_CORRELATED 128; the macro suffixes)
# It prints the nodes on whole-circle trapezoids, on the trapezoids' batched phi = pi nodes and on
# the GK15 panels of partial arcs (plain and substituted), each as a share of all; then, per rule
# run (a texel's default rule, or its refined one), the outer panels, the azimuth integrals on whole
# circles (trapezoids) and on arcs, and the arcs' GK15 panels.
# Needs g++ and gcov (Debian: g++). Works in a scratch directory; the tree is not touched.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
ndf=${1:-GGX}
gaf=${2:-SMITH_CORRELATED}
n=${3:-128}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/counts.cpp" <<EOF
#include "common/brdf_host.h"
int main() {
  double sum = 0;
  for (int j = 0; j < $n; ++j)
    for (int i = 0; i < $n; ++i) {
      float mu = (i + 0.5f) / $n, r = (j + 0.5f) / $n;
      brdf32::HemiResult h = brdf32::hemisphere_texel(NDF_$ndf, GAF_$gaf, mu, r, (float)HEMI_BAKE_TARGET);
      sum += h.a + h.b;
    }
  return sum > 0 ? 0 : 1;
}
EOF
cd "$work"
g++ -std=c++17 -O1 --coverage -I"$root/kernels" -I"$root/host" counts.cpp -o counts
./counts
gcov -o . counts.cpp > /dev/null 2>&1
# the count gcov puts before a line of the named file that holds `text` (0 for a line never run);
# a text no longer in the kernel stops the script rather than count as 0
count() {
  line=$(grep -F -- "$2" "$1.gcov" | head -1)
  if [ -z "$line" ]; then
    echo "node_counts: '$2' is not in $1 any more; update this script" >&2
    exit 2
  fi
  c=$(echo "$line" | cut -d: -f1 | tr -d ' *')
  case "$c" in '#####'|'-') echo 0 ;; *) echo "$c" ;; esac
}
trap_n=$(count azimuth.h 'hemi_node(ndf, gaf, p, mu, s, h, sn, lane_load(cs, k), &fa, &fb);')
gk_plain=$(count azimuth.h 'hemi_node(ndf, gaf, p, mu, s, h, sn, cos_arc(mid + hw * x), fa, fb);')
gk_sub=$(count azimuth.h 'hemi_node(ndf, gaf, p, mu, s, h, sn, cos_arc(phi), fa, fb);')
pi_n=$(count hemisphere.h 'hemi_node_c(ndf, gaf, p, mu, s, lane_load(nc, k), lane_load(nsn, k), RC(-1.0), &fa, &fb);')
total=$((trap_n + gk_plain + gk_sub + pi_n))
echo "integrand nodes, $ndf + $gaf, ${n}x${n} texel centres (host, float, one lane per node):"
for v in trap_n pi_n gk_plain gk_sub; do
  eval "x=\$$v"
  case $v in
    trap_n) what="whole-circle trapezoids" ;;
    pi_n) what="their phi = pi nodes" ;;
    gk_plain) what="arc GK15 panels, plain" ;;
    gk_sub) what="arc GK15 panels, substituted" ;;
  esac
  awk -v w="$what" -v x="$x" -v t="$total" 'BEGIN { printf "  %-30s %12d  %5.1f%%\n", w, x, 100 * x / t }'
done
echo "  total                          $(printf '%12d' "$total")"
rules=$(count hemisphere.h 'sort_ascending(bp, nbp);')
outer=$(count hemisphere.h 'hemi_panel(ndf, gaf, p, mu, s, t1, v1, cur, next, partial, sq_lo, sq_hi, refine, &res);')
traps=$(count azimuth.h '  t.n = n;')
arcs=$(count azimuth.h 'sort_ascending(br, nb);')
panels=$(count azimuth.h 'real hw = RC(0.5) * (hi - lo);')
awk -v r="$rules" -v o="$outer" -v t="$traps" -v a="$arcs" -v g="$panels" 'BEGIN {
  printf "per rule run (%d runs): %.2f outer panels, %.1f trapezoids, %.1f arcs, %.2f GK15 panels per arc\n",
         r, o / r, t / r, a / r, (a > 0 ? g / a : 0) }'
