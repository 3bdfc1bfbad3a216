#!/usr/bin/env python3
"""Rewrites the hemisphere and azimuth rules to take the texel's view as one struct, HemiView
{ndf, gaf, p, mu, s} passed by value, in place of five arguments: the alternative measured in
docs/performance.md ("Kernel choices", the rules' arguments). It edits kernels/ in the tree given
(default: this checkout), so run it in a scratch worktree, build there, and compare:

  git worktree add /tmp/hv HEAD && python3 tools/try_hemi_view_struct.py /tmp/hv
  cmake -S /tmp/hv -B /tmp/hv/build -DCMAKE_BUILD_TYPE=Release && cmake --build /tmp/hv/build -j2 --target brdfbake
  tools/compare-bakes.sh build/brdfbake /tmp/hv/build/brdfbake --table splitsum,albedo --size 512

The tables are the same bits either way (the goldens pass in the worktree but the scene's hash of
the kernel text)."""
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
RULES = ["hemi_phi_gk_values", "hemi_phi_gk", "hemi_phi_gk_pair", "hemi_phi_trap", "hemi_phi", "hemi_trap_quad",
         "hemi_trap_lanes", "hemi_arcs_lanes", "hemi_outer_panel", "hemi_panel"]
FILES = ["azimuth.h", "azimuth_lanes.h", "hemisphere.h", "sheen.h"]
PREFIX = r"int\s+ndf,\s*int\s+gaf,\s*BrdfParams\s+p,\s*real\s+mu,\s*real\s+s,\s*"
CALL = r"\(ndf,\s*gaf,\s*p,\s*mu,\s*s,\s*"
UNPACK = "\n  const int ndf = view.ndf, gaf = view.gaf;\n  const BrdfParams p = view.p;\n  const real mu = view.mu, s = view.s;"
STRUCT = """typedef struct HemiView {
  int ndf, gaf;
  BrdfParams p;
  real mu, s;
} HemiView;
BRDF_FN HemiView hemi_view_at(int ndf, int gaf, BrdfParams p, real mu, real s) {
  HemiView v;
  v.ndf = ndf;
  v.gaf = gaf;
  v.p = p;
  v.mu = mu;
  v.s = s;
  return v;
}
"""

changed = 0
for name in FILES:
    path = os.path.join(root, "kernels", "integrate", name)
    text = open(path).read()
    for rule in RULES:
        # the definition: the view's five arguments become one, read back into locals of their names
        # (the compiler drops the unused ones)
        pattern = re.compile(r"(BRDF_FN\s+\w+\s+" + rule + r"\()" + PREFIX + r"([^{]*\{)")
        text, n = pattern.subn(lambda m: m.group(1) + "HemiView view, " + m.group(2) + UNPACK, text)
        changed += n
        # calls from a rule pass its view on; calls from elsewhere build one
        text = re.sub(r"\b" + rule + CALL, rule + "(hemi_view_at(ndf, gaf, p, mu, s), ", text)
    if name == "azimuth.h":
        anchor = "BRDF_FN int hemi_gaf_alpha_layer"
        assert anchor in text, "azimuth.h: no place for the struct"
        text = text.replace(anchor, STRUCT + anchor, 1)
    open(path, "w").write(text)
if changed != len(RULES):
    sys.exit("rewrote %d of %d rules: the kernels have moved on from this script" % (changed, len(RULES)))
print("rewrote %d rules in %s" % (changed, os.path.join(root, "kernels")))
