#!/usr/bin/env python3
"""A bake's wall time as its caller sees it, against the stages it counts itself.

Runs `BRDFBAKE bake -o DIR --timings [ARGS...]` N times (default 15) into a scratch directory and
prints the best and the median of the process's wall time (fork to reap, Python's
subprocess.run), of the `total` line `--timings` prints (from the command's start to its report),
and of their difference: the process's start (exec, the dynamic loader, glibc's start-up) and its
end (the report, the libraries' destructors, the address space torn down).

  tools/bake_wall.py [--runs N] [BRDFBAKE] [-- ARGS...]     (default: ./build/brdfbake)

Comparing two builds: run it for each, alternating, several times (docs/performance.md).
"""
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time


def main(argv):
    runs, exe, extra = 15, "./build/brdfbake", []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    if len(argv) >= 2 and argv[0] == "--runs":
        runs, argv = int(argv[1]), argv[2:]
    if argv:
        exe = argv[0]
    walls, totals = [], []
    with tempfile.TemporaryDirectory() as out:
        for _ in range(runs):
            t0 = time.perf_counter()
            p = subprocess.run([exe, "bake", "-o", os.path.join(out, "t"), "--timings"] + extra,
                               capture_output=True, text=True)
            wall = time.perf_counter() - t0
            if p.returncode != 0:
                sys.exit("bake_wall: %s exited %d: %s" % (exe, p.returncode, p.stderr.strip()))
            m = re.search(r"([\d.]+)\s+total", p.stderr)
            if not m:
                sys.exit("bake_wall: no `total` line in --timings' output")
            walls.append(wall)
            totals.append(float(m.group(1)))
    outside = [w - t for w, t in zip(walls, totals)]
    for name, v in (("wall", walls), ("--timings total", totals), ("outside the stages", outside)):
        print("%-20s best %.4f s  median %.4f s  (%d runs)" % (name, min(v), statistics.median(v), runs))


if __name__ == "__main__":
    main(sys.argv[1:])
