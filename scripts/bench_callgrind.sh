#!/usr/bin/env bash
# Instruction counts of the computations `roughtui bench` times, which do not
# move with the machine's load: examples/cost.rs under callgrind, once per
# WHAT, less the run that does nothing (all threads summed).
#
#   cargo build --profile profiling --example cost
#   scripts/bench_callgrind.sh
set -euo pipefail
cd "$(dirname "$0")/.."
bin=target/profiling/examples/cost
[ -x "$bin" ] || { echo "no $bin: cargo build --profile profiling --example cost first" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "valgrind not found" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
count() { # instructions of `cost $1 $2`
  valgrind --tool=callgrind --callgrind-out-file="$out/cg" "$bin" "$1" "$2" 2>&1 |
    awk '/refs:/ {gsub(",", "", $NF); print $NF}'
}
base=$(count none 1)
while read -r what n per unit; do
  c=$(count "$what" "$n")
  awk -v c="$c" -v b="$base" -v n="$n" -v per="$per" -v w="$what" -v u="$unit" \
    'BEGIN {printf "%-12s %12.0f instructions per %s\n", w, (c - b) / (n * per), u}'
done <<'LIST'
exact 20 1250 point
closed 20 1250 point
map-fig2 10 1 map
map-fig4 10 1 map
export-fig2 1 1 export
LIST
