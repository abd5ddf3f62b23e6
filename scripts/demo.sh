#!/usr/bin/env bash
# The main job on a built-in case, from a fresh Debian machine: packages, build, then the paper's
# "Meshes 1" pipeline on the volume between two spheres — an isotropic mesh, a surface metric
# (small size along the normal) carried into the volume by gradation, and the P2 curving by vertex
# reinsertion with boundary curvature from the P3 surrogate. Output files go to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh release >/dev/null
hocav=build/release/hocav
mkdir -p out
"$hocav" generate sphere-shell --h 0.1 -o out/sphere-shell.meshb
"$hocav" metric out/sphere-shell.meshb --surface 0.01 0.1 --gradation 1.5 -o out/sphere-shell.solb
"$hocav" curve out/sphere-shell.meshb --metric out/sphere-shell.solb --surface p3 --threads "$(nproc)" \
  -o out/sphere-shell-p2.meshb --vtu out/sphere-shell-p2.vtu --report out/sphere-shell-report.json
echo "wrote out/sphere-shell-p2.meshb (curved P2 mesh), out/sphere-shell-p2.vtu (open in ParaView with"
echo "Nonlinear Subdivision Level >= 2; cell data: min_normalized_jacobian, scaled_jacobian) and"
echo "out/sphere-shell-report.json"
