#!/usr/bin/env bash
# The main job, from a fresh Debian machine: packages, the release build, then `hocav demo` — the
# paper's "Meshes 1" pipeline on the volume between two spheres (an isotropic mesh, a surface
# metric graded into the volume, P2 curving by vertex reinsertion with the boundary curvature of the
# P3 surrogate), the same curving on a 2D annulus, and pictures of both (SVG). Files go to out/;
# extra arguments go to `hocav demo` (e.g. -o DIR, --h 0.05, --threads 1).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh release >/dev/null
build/release/hocav demo "$@"
