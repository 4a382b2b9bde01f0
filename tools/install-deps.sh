#!/usr/bin/env bash
# Installs the Debian packages FairSplines needs, only those missing (Debian 12).
set -euo pipefail
packages=(
  cmake g++ make
  freecad
  libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev libocct-data-exchange-dev
  pybind11-dev libeigen3-dev libgtest-dev swig
  python3-dev python3-numpy python3-pytest python3-hypothesis python3-matplotlib python3-pil python3-flake8
  xvfb xauth
)
# `install-deps.sh sanitizers` (make fuzz, make test-sanitize): also clang with its
# sanitizer and libFuzzer runtimes, and llvm for llvm-symbolizer (stack traces).
sanitizer_packages=(clang libclang-rt-dev llvm)
# `install-deps.sh format` (make format, make format-check): clang-format (14 on Debian 12).
format_packages=(clang-format)
if [ "${1:-}" = sanitizers ]; then
  packages+=("${sanitizer_packages[@]}")
fi
if [ "${1:-}" = format ]; then
  packages+=("${format_packages[@]}")
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "deps: all Debian packages present"
  exit 0
fi
echo "deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
