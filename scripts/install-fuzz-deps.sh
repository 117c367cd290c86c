#!/usr/bin/env bash
# Installs what the libFuzzer targets (tests/fuzz, `make fuzz`) need on top of
# scripts/install-deps.sh: Debian's clang and its compiler runtime, which carries libFuzzer
# (libclang_rt.fuzzer) and the address/undefined sanitizer runtimes. Only `make fuzz` calls
# this, so the normal build and `make test` never need clang.
set -euo pipefail
cd "$(dirname "$0")/.."

debian_packages=(
  clang-14               # the compiler (-fsanitize=fuzzer is clang-only)
  libclang-rt-14-dev     # compiler-rt: libclang_rt.fuzzer, asan, ubsan runtimes
)
missing=()
for p in "${debian_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-fuzz-deps: apt-get install ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
