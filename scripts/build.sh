#!/usr/bin/env bash
# Configures and builds one flavour of hocav into build/<flavour>:
#   release  optimized, warnings as errors (default)
#   asan     AddressSanitizer + UndefinedBehaviorSanitizer, unit tests only
#   fuzz     clang + libFuzzer targets for the file readers
#   nogmsh   release without the optional gmsh and MPI (HOCAV_WITH_GMSH=OFF, HOCAV_WITH_MPI=OFF): unit,
#            end-to-end and Python tests (the distributed ones skip), no benchmarks
# release, asan and nogmsh are unity builds (CMAKE_UNITY_BUILD: the .cpp files compiled in batches,
# 306 s against 647 s for release on 2 cores, docs/benchmarks.md "Sixty-first session"); fuzz
# compiles the library file by file, which checks that each file includes what it uses (a plain
# CMake configure, the default for users, compiles them so).
set -euo pipefail
cd "$(dirname "$0")/.."
flavour=${1:-release}
jobs=$(nproc)

targets=()
case "$flavour" in
  release) options=(-DCMAKE_BUILD_TYPE=Release -DHOCAV_WERROR=ON -DCMAKE_UNITY_BUILD=ON) ;;
  asan) options=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DHOCAV_WERROR=ON -DHOCAV_SANITIZE=ON -DHOCAV_BENCH=OFF -DCMAKE_UNITY_BUILD=ON) ;;
  fuzz)
    options=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DHOCAV_FUZZ=ON -DHOCAV_TESTS=OFF -DHOCAV_BENCH=OFF)
    targets=(--target file_readers_fuzz)
    ;;
  nogmsh) options=(-DCMAKE_BUILD_TYPE=Release -DHOCAV_WERROR=ON -DHOCAV_WITH_GMSH=OFF -DHOCAV_WITH_MPI=OFF -DHOCAV_BENCH=OFF -DCMAKE_UNITY_BUILD=ON) ;;
  *) echo "build.sh: unknown flavour '$flavour' (release, asan, fuzz, nogmsh)" >&2; exit 2 ;;
esac

cmake -S . -B "build/$flavour" "${options[@]}" >/dev/null
cmake --build "build/$flavour" -j "$jobs" "${targets[@]}"
