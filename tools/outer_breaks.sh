#!/bin/bash
# What the split sum's outer breakpoints buy: the hemisphere rule (kernels/integrate) compiled for
# the host in double (brdf64, host/common/brdf_host.h) with other HEMI_BREAKS, over every texel
# centre of a 128^2 ggx + smith-correlated table: the integrand nodes per texel at the default
# budget, the texels whose estimate (floor included) exceeds the bake's target and would be
# refined, the default budget's estimates (quantiles, relative to max(1, value)), and on every 7th
# texel the largest error against the rule at level 2 and the largest ratio of that error to the
# estimate plus the floor. Works in a scratch copy of kernels/; the tree is not touched.
#   tools/outer_breaks.sh                      the kernel's breaks, then the variants below
# Needs g++. A few seconds per variant on one core (22 s for the five on a two-core machine).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -r "$root/kernels" "$work/"
python3 - "$work/kernels" <<'PY'
import sys
k = sys.argv[1]
p = k + "/integrate/hemisphere.h"
s = open(p).read()
old = "BRDF_CONST real HEMI_BREAKS[HEMI_NBREAKS] = {RC(1.0), RC(3.0), RC(7.0), RC(15.0), RC(40.0)};"
if old not in s: sys.exit("outer_breaks: HEMI_BREAKS changed in hemisphere.h; update this script")
s = s.replace(old, """#ifdef PARTIAL_BREAKS
BRDF_CONST real HEMI_BREAKS[HEMI_NBREAKS] = {PARTIAL_BREAKS};
#else
BRDF_CONST real HEMI_BREAKS[HEMI_NBREAKS] = {RC(1.0), RC(3.0), RC(7.0), RC(15.0), RC(40.0)};
#endif
#ifdef FULL_BREAKS
BRDF_CONST real HEMI_BREAKS_FULL[FULL_NBREAKS] = {FULL_BREAKS};
#else
#define FULL_NBREAKS HEMI_NBREAKS
#define HEMI_BREAKS_FULL HEMI_BREAKS
#endif""")
s = s.replace("#define HEMI_NBREAKS 5", "#ifndef HEMI_NBREAKS\n#define HEMI_NBREAKS 5\n#endif")
old = """  for (int k = 0; k < HEMI_NBREAKS; ++k) {
    real b = HEMI_BREAKS[k];
    if (b < v1"""
if old not in s: sys.exit("outer_breaks: the full region's loop changed in hemisphere.h; update this script")
s = s.replace(old, """  for (int k = 0; k < FULL_NBREAKS; ++k) {
    real b = HEMI_BREAKS_FULL[k];
    if (b < v1""")
open(p, "w").write(s)
p = k + "/integrate/azimuth.h"
s = open(p).read()
s = s.replace('#include "integrate/quadrature.h"\n', '#include "integrate/quadrature.h"\nextern long g_nodes;\n', 1)
for a, b in [("  real hw = RC(0.5) * (hi - lo);\n",  # hemi_phi_gk: once per GK15 panel
              "  real hw = RC(0.5) * (hi - lo);\n  g_nodes += 15;\n"),
             ("  t.n = n;\n", "  t.n = n;\n  g_nodes += n + 1;\n")]:
    if a not in s: sys.exit("outer_breaks: azimuth.h changed; update this script")
    s = s.replace(a, b, 1)
open(p, "w").write(s)
PY
cat > "$work/breaks.cpp" <<'CPP'
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>
namespace brdf32 { long g_nodes = 0; }
namespace brdf64 { long g_nodes = 0; }
#include "common/brdf_host.h"
using namespace brdf64;
int main() {
  const int n = 128, ndf = NDF_GGX, gaf = GAF_SMITH_CORRELATED;
  long nodes = 0, refined = 0;
  std::vector<double> est;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double mu = (i + 0.5) / n, r = (j + 0.5) / n;
      const long before = g_nodes;
      HemiResult h = hemi_rule(ndf, gaf, hemisphere_texel_params(ndf, gaf, mu, r), mu, 0);
      nodes += g_nodes - before;
      est.push_back(hemi_rel_error(h));
      hemi_add_relative(hemi_floor(0), &h);
      refined += hemi_rel_error(h) > HEMI_BAKE_TARGET;
    }
  std::sort(est.begin(), est.end());
  double worst = 0, ratio = 0;
  for (int j = 0; j < n; j += 7)
    for (int i = 0; i < n; i += 7) {
      const double mu = (i + 0.5) / n, r = (j + 0.5) / n;
      const BrdfParams p = hemisphere_texel_params(ndf, gaf, mu, r);
      const HemiResult h = hemi_rule(ndf, gaf, p, mu, 0), g = hemi_rule(ndf, gaf, p, mu, 2);
      const double e = std::max(std::fabs(h.a - g.a) / std::max(1.0, std::fabs(g.a)),
                                std::fabs(h.b - g.b) / std::max(1.0, std::fabs(g.b)));
      worst = std::max(worst, e);
      ratio = std::max(ratio, e / (hemi_rel_error(h) + hemi_floor(0)));
    }
  std::printf("%8.1f nodes/texel %6ld refined   estimates: median %.2g, 90%% %.2g, 99%% %.2g   every 7th: error <= %.2g, "
              "error/(estimate + floor) <= %.2f\n",
              double(nodes) / (n * n), refined, est[est.size() / 2], est[est.size() * 9 / 10], est[est.size() * 99 / 100],
              worst, ratio);
}
CPP
run() {  # label, then -D definitions
  local label=$1
  shift
  g++ -std=c++17 -O2 "$@" -I"$work/kernels" -I"$root/host" "$work/breaks.cpp" -o "$work/breaks"
  printf '%-44s' "$label"
  "$work/breaks"
}
run "1, 3, 7, 15, 40 (the kernel's)"
run "2, 6, 15, 40" -DHEMI_NBREAKS=4 "-DPARTIAL_BREAKS=RC(2.0),RC(6.0),RC(15.0),RC(40.0)"
run "3, 12, 40" -DHEMI_NBREAKS=3 "-DPARTIAL_BREAKS=RC(3.0),RC(12.0),RC(40.0)"
run "whole-circle region only: 2, 6, 15, 40" -DFULL_NBREAKS=4 "-DFULL_BREAKS=RC(2.0),RC(6.0),RC(15.0),RC(40.0)"
run "whole-circle region only: 3, 12, 40" -DFULL_NBREAKS=3 "-DFULL_BREAKS=RC(3.0),RC(12.0),RC(40.0)"
