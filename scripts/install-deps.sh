#!/usr/bin/env bash
# Installs what dispkin needs on a fresh Debian machine, and nothing that is already there:
# the Debian development packages (apt-get) and a Python virtual environment .venv with the
# build and test requirements (pip). Called by `make deps`, hence by `make demo` / `make test`.
set -euo pipefail
cd "$(dirname "$0")/.."

debian_packages=(
  cmake ninja-build g++ pkg-config
  libeigen3-dev          # linear algebra, quaternions
  libqhull-dev           # convex hulls
  nlohmann-json3-dev     # hexapod description files (JSON, header-only)
  liburdfdom-dev         # URDF parsing (serial-arm plugin)
  libtinyxml-dev         # urdfdom's XML parser: the URDF joint graph is checked first
  liborocos-kdl-dev      # chains, Jacobians, dynamics (serial-arm plugin)
  libsleef-dev           # vectorised atan2 of the closed-form IK (serial-arm plugin)
  libgtest-dev           # C++ tests
  libbenchmark-dev       # C++ benchmarks
  doxygen                # `make docs`: the C++ API reference (doc/api/Doxyfile)
  clang-format           # `make format` / `make lint`: the C++ style of .clang-format
  python3-venv
)
missing=()
for p in "${debian_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: apt-get install ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

python=${PYTHON:-python3}
if [ ! -x .venv/bin/python ]; then
  echo "install-deps: creating .venv with $($python --version)"
  "$python" -m venv .venv
fi
stamp=.venv/.requirements-installed
if [ ! -f "$stamp" ] || [ requirements-dev.txt -nt "$stamp" ]; then
  .venv/bin/python -m pip install -q --upgrade pip
  .venv/bin/python -m pip install -q -r requirements-dev.txt
  touch "$stamp"
fi
