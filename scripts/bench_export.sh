#!/usr/bin/env bash
# `roughtui export --preset fig2 --points N` against its NumPy/SciPy peer
# (scripts/closed_form_numpy.py), whole commands, stdout to /dev/null,
# alternated, RUNS runs each; prints each time, the medians and their ratio.
# `roughtui bench` runs the same comparison in its targets table.
#
#   cargo build --release
#   scripts/bench_export.sh [POINTS] [RUNS]        # 200000 3 by default
#
# ROUGHTUI names the binary (target/release/roughtui by default). Needs
# python3 with numpy and scipy. On a shared machine the times move with the
# load; the ratio of medians taken in one run is the figure to compare.
set -euo pipefail
cd "$(dirname "$0")/.."
points=${1:-200000}
runs=${2:-3}
bin=${ROUGHTUI:-target/release/roughtui}
[ -x "$bin" ] || { echo "no $bin: cargo build --release first" >&2; exit 2; }
python3 -c 'import numpy, scipy.special' || { echo "python3 needs numpy and scipy" >&2; exit 2; }

ms() { # wall-clock milliseconds of one run of "$@"
  local t0 t1
  t0=$(date +%s%N)
  "$@" >/dev/null
  t1=$(date +%s%N)
  echo $(( (t1 - t0) / 1000000 ))
}
median() { printf '%s\n' "$@" | sort -n | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

ours=() peer=()
for _ in $(seq "$runs"); do
  ours+=("$(ms "$bin" export --preset fig2 --points "$points")")
  peer+=("$(ms python3 scripts/closed_form_numpy.py --points "$points")")
done
mo=$(median "${ours[@]}")
mp=$(median "${peer[@]}")
echo "roughtui export: ${ours[*]} ms (median $mo)"
echo "NumPy peer:      ${peer[*]} ms (median $mp)"
awk -v a="$mp" -v b="$mo" 'BEGIN {printf "NumPy / roughtui: %.1fx\n", a / b}'
