#!/usr/bin/env bash
# Everything from a fresh Debian machine to a full test run: packages, the layout of the C++ files
# (.clang-format), the optimized build and its tests (unit, end-to-end, third-party readers,
# ParaView, Python), the same without gmsh and MPI, the sanitizer build and its tests, and a bounded fuzzing
# run of the file readers.
set -euo pipefail
cd "$(dirname "$0")/.."
fuzz_seconds=${HOCAV_FUZZ_SECONDS:-60}

bash scripts/setup.sh

# ctest, then how many tests were skipped and why (scripts/skipped_tests.py: ctest's skipped tests,
# pytest's, and parts of tests; a bare clone, without ../shared/data beside the repository, skips
# the tests of third-party files). Every test's output goes into the results, uncut.
run_ctest() {
  local results status=0
  results=$(mktemp --suffix=.xml)
  ctest "$@" --test-output-size-passed 1048576 --output-junit "$results" || status=$?
  /usr/bin/python3 scripts/skipped_tests.py "$results"
  rm -f "$results"
  return "$status"
}

echo "== C++ layout (.clang-format; bash scripts/format.sh applies it)"
bash scripts/check_format.sh

echo "== release build and tests"
bash scripts/build.sh release
run_ctest --test-dir build/release --output-on-failure -j "$(nproc)"

echo "== without gmsh and MPI (HOCAV_WITH_GMSH=OFF, HOCAV_WITH_MPI=OFF): build and tests (those that need them skip)"
bash scripts/build.sh nogmsh
run_ctest --test-dir build/nogmsh --output-on-failure -j "$(nproc)"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
bash scripts/build.sh asan
run_ctest --test-dir build/asan --output-on-failure -j "$(nproc)" -E '^python\.'

echo "== fuzzing the file readers (${fuzz_seconds}s)"
bash scripts/build.sh fuzz
bash scripts/fuzz.sh "$fuzz_seconds"
