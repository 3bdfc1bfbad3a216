#!/usr/bin/env python3
"""Writes a scene manifest of N materials, for timing `brdfbake plan` (docs/reliability.md):
  tools/many_materials.py same N > a.toml     N materials differing in F0 only (one table set)
  tools/many_materials.py pairs N > b.toml    N materials over 16 NDF/GAF pairs and 500 etas
then `time ./build/brdfbake plan a.toml > /dev/null`."""
import sys

kind, n = sys.argv[1], int(sys.argv[2])
ndfs = ["ggx", "beckmann", "blinn-phong", "gaussian"]
gafs = ["smith", "smith-correlated", "schlick-ggx", "kelemen"]
print('[scene]\nname = "many"\n[output]\ndir = "out/many"\n[lighting]\nibl = true\nanalytic = true\nmultiscatter = true')
for i in range(n):
    if kind == "same":
        print('[[material]]\nname = "m%d"\nfresnel = "schlick"\nf0 = %g' % (i, 0.01 + (i % 90) / 100.0))
    else:
        print('[[material]]\nname = "m%d"\nfresnel = "dielectric"\neta = %g\nndf = "%s"\ngaf = "%s"'
              % (i, 1.01 + (i % 500) / 100.0, ndfs[i % 4], gafs[(i // 4) % 4]))
