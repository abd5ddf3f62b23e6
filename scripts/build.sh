#!/usr/bin/env bash
# Configures and builds one flavour of hocav into build/<flavour>:
#   release  optimized, warnings as errors (default)
#   asan     AddressSanitizer + UndefinedBehaviorSanitizer, unit tests only
#   fuzz     clang + libFuzzer targets for the file readers
#   nogmsh   release without the optional gmsh and MPI (HOCAV_WITH_GMSH=OFF, HOCAV_WITH_MPI=OFF): unit,
#            end-to-end and Python tests (the distributed ones skip), no benchmarks
set -euo pipefail
cd "$(dirname "$0")/.."
flavour=${1:-release}
jobs=$(nproc)

case "$flavour" in
  release) options=(-DCMAKE_BUILD_TYPE=Release -DHOCAV_WERROR=ON) ;;
  asan) options=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DHOCAV_WERROR=ON -DHOCAV_SANITIZE=ON -DHOCAV_BENCH=OFF) ;;
  fuzz) options=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DHOCAV_FUZZ=ON -DHOCAV_TESTS=OFF -DHOCAV_BENCH=OFF) ;;
  nogmsh) options=(-DCMAKE_BUILD_TYPE=Release -DHOCAV_WERROR=ON -DHOCAV_WITH_GMSH=OFF -DHOCAV_WITH_MPI=OFF -DHOCAV_BENCH=OFF) ;;
  *) echo "build.sh: unknown flavour '$flavour' (release, asan, fuzz, nogmsh)" >&2; exit 2 ;;
esac

cmake -S . -B "build/$flavour" "${options[@]}" >/dev/null
cmake --build "build/$flavour" -j "$jobs"
