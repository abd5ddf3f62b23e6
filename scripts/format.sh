#!/usr/bin/env bash
# Formats every C++ file of the tree in place with .clang-format (scripts/check_format.sh checks it).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/cpp_sources.sh

cpp_sources | xargs -0 -n 16 -P "$(nproc)" "$clang_format" --style=file -i
