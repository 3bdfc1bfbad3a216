#!/bin/bash
# Times the same bake with two brdfbake binaries, interleaved, so that the machine's noise falls on
# both alike: after one warm-up run each, three rounds of OLD then NEW, each the sum of the `table`
# lines of `bake --timings` (the tables' compute, without process start, programs or writing).
#
#   tools/compare-bakes.sh OLD_BINARY NEW_BINARY [bake options...]
#   tools/compare-bakes.sh /tmp/old/build/brdfbake build/brdfbake --table splitsum,albedo --size 512
#
# Build OLD from another commit in a worktree: git worktree add /tmp/old REV, then cmake there.
set -euo pipefail
if [ $# -lt 2 ]; then
  sed -n '2,9p' "$0" >&2
  exit 64
fi
old=$1 new=$2
shift 2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
tables() {
  "$1" bake "${@:2}" --timings -o "$out/o" 2>&1 | awk '$2 == "table" { s += $1 } END { printf "%.3f", s }'
  rm -rf "$out/o"
}
tables "$old" "$@" > /dev/null
tables "$new" "$@" > /dev/null
for round in 1 2 3; do
  printf "round %d: old %s s  new %s s\n" "$round" "$(tables "$old" "$@")" "$(tables "$new" "$@")"
done
