#!/usr/bin/env bash
# The main job on a built-in case, from a fresh Debian machine: packages, build, then generate the
# sphere-shell case as a P2 mesh and print its statistics. Output files go to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh release >/dev/null
mkdir -p out
build/release/hocav generate sphere-shell --h 0.25 --order 2 -o out/sphere-shell.meshb
build/release/hocav convert out/sphere-shell.meshb out/sphere-shell.vtu
build/release/hocav stats out/sphere-shell.meshb
echo "wrote out/sphere-shell.meshb and out/sphere-shell.vtu (open the .vtu in ParaView)"
