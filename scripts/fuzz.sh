#!/usr/bin/env bash
# Runs the libFuzzer target of the file readers for a bounded time, seeded with valid files that
# the release build writes. Usage: scripts/fuzz.sh [seconds]. Needs build/release and build/fuzz.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
hocav=build/release/hocav
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
corpus="$work/corpus"
mkdir -p "$corpus"

# A seed is one format byte (see fuzz/file_readers_fuzz.cpp) followed by the file's bytes.
seed() {  # seed FORMAT_BYTE FILE
  { printf "\\x$(printf %02x "$1")"; cat "$2"; } >"$corpus/$(basename "$2").$1"
}
"$hocav" generate square --h 0.5 -o "$work/square.mesh" >/dev/null
"$hocav" generate cube --h 0.5 --order 2 -o "$work/cube.mesh" >/dev/null
"$hocav" convert "$work/cube.mesh" "$work/cube.meshb" >/dev/null
"$hocav" convert "$work/cube.mesh" "$work/cube.msh" >/dev/null
"$hocav" convert "$work/square.mesh" "$work/square.msh" >/dev/null
printf 'MeshVersionFormatted 2\nDimension 2\nSolAtVertices\n2\n1 3\n1 0 1\n2 0 2\nEnd\n' >"$work/metric.sol"
seed 0 "$work/square.mesh"
seed 0 "$work/cube.mesh"
seed 1 "$work/cube.meshb"
seed 2 "$work/cube.msh"
seed 2 "$work/square.msh"
seed 3 "$work/metric.sol"

build/fuzz/fuzz/file_readers_fuzz "$corpus" -max_total_time="$seconds" -max_len=65536 -rss_limit_mb=2048 \
  -print_final_stats=1 2>"$work/fuzz.log" || { tail -n 60 "$work/fuzz.log"; exit 1; }
grep -a -E "stat::number_of_executed_units|Done" "$work/fuzz.log" | sed "s/^/fuzz: /" || true
