#!/usr/bin/env python3
"""The host reads as the pipeline it runs (docs/architecture.md): a file includes only files of its
own stage or a later one, and no files include each other, directly or around a loop. Prints each
violation and exits 1 when there is one. Run by ctest (Layout.IncludesRunDownThePipeline)."""
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..")
# stage of each top-level directory of host/ (and include/brdfbake): lower runs earlier, and may
# include higher; clients first, the base last
STAGES = {
    "main.cpp": 0, "cli": 0, "bench": 0,
    "scene": 1, "report": 1, "shader": 1, "render": 1,
    "api": 2, "brdfbake": 2,
    "bake": 3,
    "plan": 4,
    "tables": 5,
    "materials": 6, "reference": 6,
    "cl": 7,
    "formats": 8,
    "common": 9,
}
# public headers by what they are: the API, the request (and its observer) the planner and the families read, the
# table kinds the families describe, the error type every stage throws
FILE_STAGES = {"brdfbake/brdfbake.h": 2, "brdfbake/request.h": 5, "brdfbake/report.h": 5, "brdfbake/observer.h": 5,
               "brdfbake/table_kind.h": 5, "brdfbake/error.h": 9}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def stage_of_file(rel):
    if rel in FILE_STAGES:
        return FILE_STAGES[rel]
    parts = rel.split("/")
    return STAGES.get(parts[0])


def resolve(inc):
    """The include as a key of `files` ("cl/runner.h", "brdfbake/error.h"), or None (system, kernels, generated)."""
    for base in ("host", "include"):
        if os.path.exists(os.path.join(root, base, inc)):
            return inc
    return None


files = {}
for base in ("host", "include"):
    for dirpath, _, names in os.walk(os.path.join(root, base)):
        for n in names:
            if n.endswith((".h", ".cpp")):
                full = os.path.join(dirpath, n)
                rel = os.path.relpath(full, os.path.join(root, base))
                files[rel] = full

graph = {}
errors = []
for rel, full in sorted(files.items()):
    src = stage_of_file(rel)
    deps = []
    with open(full, encoding="utf-8") as f:
        for line in f:
            m = INCLUDE.match(line)
            if not m or resolve(m.group(1)) is None:
                continue
            inc = m.group(1)
            deps.append(inc)
            dst = stage_of_file(inc)
            if src is not None and dst is not None and dst < src:
                errors.append(f"{rel} includes {inc}: {inc.split('/')[0]}/ runs before {rel.split('/')[0]}/")
    graph[rel] = deps

# include loops (a file's own header and its .cpp are one unit: loops are between headers)
state = {}
stack = []


def visit(n):
    state[n] = 1
    stack.append(n)
    for d in graph.get(n, []):
        if state.get(d) == 1:
            errors.append("include loop: " + " -> ".join(stack[stack.index(d):] + [d]))
        elif d not in state:
            visit(d)
    stack.pop()
    state[n] = 2


for n in sorted(graph):
    if n not in state:
        visit(n)

for e in errors:
    print(e)
print(f"{len(files)} files, {len(errors)} violations")
sys.exit(1 if errors else 0)
