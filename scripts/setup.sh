#!/usr/bin/env bash
# Installs the Debian packages hocav needs to build, test and run (only those missing).
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libcli11-dev libgtest-dev libgmock-dev libbenchmark-dev
  libgmsh-dev python3-gmsh python3-meshio python3-numpy
  pybind11-dev python3-dev python3-pytest python3-matplotlib  # the Python module, its tests and docs/python.md's example
  clang libclang-rt-14-dev
  # the distributed adaptation (docs/distributed.md) and its mpirun tests: OpenMPI, Scotch (int64)
  libopenmpi-dev openmpi-bin libptscotch-dev
  clang-format  # scripts/check_format.sh (the test command) and scripts/format.sh: version 14, as clang
  # tests/io/paraview_vtu_test.py: ParaView reads and draws the curved .vtu; Debian's ParaView
  # renders through X only, so headless under Xvfb (about 2.5 minutes of apt-get on CI).
  paraview python3-paraview xvfb
)

missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done

if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
