#!/usr/bin/env bash
# The figures of docs/benchmarks.md ("Table 1 at scale"): every case at every size on 2 threads,
# the thread speedup (1 vs 2 threads, same output), and the side by side with gmsh.
# Usage: bash bench/table1.sh [HOCAV] [OUT_DIR] [SIZES]   (defaults: build/release/hocav, bench-results,
# 100k,1M,5M,20M). One big job at a time: run it on a quiet machine and note the load average.
set -euo pipefail
HOCAV=${1:-build/release/hocav}
OUT=${2:-bench-results}
SIZES=${3:-100k,1M,5M,20M}
mkdir -p "$OUT"
"$HOCAV" bench --sizes "$SIZES" --threads 2 --markdown "$OUT/table1.md" --json "$OUT/table1.json"
"$HOCAV" bench --cases cubed-shell,cube-shear --sizes 100k,1M --threads 1,2 --markdown "$OUT/threads.md" --json "$OUT/threads.json"
/usr/bin/python3 "$(dirname "$0")/gmsh_compare.py" "$HOCAV" 0.1 0.05 | tee "$OUT/gmsh.md"
