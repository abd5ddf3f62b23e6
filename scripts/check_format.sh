#!/usr/bin/env bash
# Fails, listing them, when C++ files of the tree differ from what clang-format makes of them with
# .clang-format; scripts/format.sh formats them in place. Run by scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/cpp_sources.sh

differing=$(cpp_sources | xargs -0 -n 1 -P "$(nproc)" sh -c '"$clang_format" --style=file "$0" | cmp -s - "$0" || echo "$0"' | sort)
if [ -n "$differing" ]; then
  echo "check_format: these files differ from .clang-format's layout (bash scripts/format.sh fixes them):" >&2
  echo "$differing" >&2
  exit 1
fi
echo "check_format: $(cpp_sources | tr -cd '\0' | wc -c) C++ files follow .clang-format"
