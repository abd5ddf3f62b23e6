# Sourced by scripts/format.sh and scripts/check_format.sh: the C++ files that .clang-format governs,
# and the clang-format that formats them.

# The C++ sources and headers of the tree, NUL-separated.
cpp_sources() {
  find src tests bench python fuzz -type f \( -name '*.cpp' -o -name '*.hpp' \) -print0 | sort -z
}

# clang-format 14 (Debian 12's, as the fuzz build's clang): another major version formats some
# constructs differently, so its output is not comparable.
clang_format=$(command -v clang-format-14 || command -v clang-format || true)
if [ -z "$clang_format" ]; then
  echo "$(basename "$0"): clang-format not found (Debian: apt-get install clang-format; scripts/setup.sh does)" >&2
  exit 2
fi
if ! "$clang_format" --version | grep -q 'version 14\.'; then
  echo "$(basename "$0"): $clang_format is not clang-format 14: $("$clang_format" --version)" >&2
  exit 2
fi
export clang_format
