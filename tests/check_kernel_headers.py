#!/usr/bin/env python3
"""Kernel headers include what they use (kernels/brdf/compat.h "Passes"): each header under
kernels/brdf and kernels/integrate compiles on its own in C++, in both passes (double, then float
with BRDF_SECOND_PASS, as host/common/brdf_host.h includes them), every #include "..." in kernels/
names a file there, and no kernel files include each other, directly or around a loop.
Usage: check_kernel_headers.py CXX [ROOT]. Prints each failure and exits 1 when there is one.
Run by ctest (Layout.KernelHeadersIncludeWhatTheyUse)."""
import os
import re
import subprocess
import sys
import tempfile

cxx = sys.argv[1]
root = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__), "..")
kernels = os.path.join(root, "kernels")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')

sources = sorted(os.path.relpath(os.path.join(d, n), kernels)
                 for d, _, names in os.walk(kernels) for n in names if n.endswith((".h", ".cl")))
errors = []
graph = {}
for rel in sources:
    with open(os.path.join(kernels, rel), encoding="utf-8") as f:
        graph[rel] = [m.group(1) for m in map(INCLUDE.match, f) if m]
    for inc in graph[rel]:
        if inc not in sources:
            errors.append(f"{rel}: includes \"{inc}\", not a file under kernels/")

# loops: depth-first search, reporting each back edge's cycle once
state = {}
def visit(node, path):
    state[node] = 1
    for nxt in graph.get(node, []):
        if state.get(nxt) == 1:
            errors.append("include loop: " + " -> ".join(path[path.index(nxt):] + [nxt]))
        elif nxt in graph and not state.get(nxt):
            visit(nxt, path + [nxt])
    state[node] = 2
for rel in sources:
    if not state.get(rel):
        visit(rel, [rel])

with tempfile.TemporaryDirectory() as tmp:
    for rel in sources:
        if not rel.endswith(".h") or rel == "brdf/compat.h":
            continue
        tu = os.path.join(tmp, "tu.cpp")
        with open(tu, "w", encoding="utf-8") as f:
            f.write('#include "brdf/compat.h"\n#define BRDF_HOST_NAMESPACE 1\n'
                    f'namespace first {{\ntypedef double real;\n#include "{rel}"\n}}\n'
                    '#define BRDF_SECOND_PASS 1\n'
                    f'namespace second {{\ntypedef float real;\n#include "{rel}"\n}}\n')
        r = subprocess.run([cxx, "-std=c++17", "-fsyntax-only", "-I", kernels, tu],
                           capture_output=True, text=True)
        if r.returncode != 0:
            errors.append(f"{rel} does not compile on its own:\n" + r.stderr.strip())

for e in errors:
    print(e)
print(f"{len(sources)} kernel files, {len(errors)} problem(s)")
sys.exit(1 if errors else 0)
