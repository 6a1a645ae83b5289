#!/usr/bin/env bash
# Installs iga's dependencies (Debian 12 packages only), configures a Release build in ./build and builds it.
# Safe to run again: installed packages and an up-to-date build are skipped.
# Environment: IGA_BUILD_DIR (default <repo>/build), IGA_JOBS (default: number of cores).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${IGA_BUILD_DIR:-$root/build}"
jobs="${IGA_JOBS:-$(nproc)}"

packages=(
  build-essential cmake
  libeigen3-dev libsuitesparse-dev libopenblas0-pthread libnlopt-cxx-dev libosd-dev libvtk9-dev
  libgtest-dev nlohmann-json3-dev libcli11-dev libmuparser-dev
  python3-matplotlib
)
missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo=""
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "setup: not root and no sudo: install ${missing[*]} first" >&2; exit 1; }
    sudo="sudo"
  fi
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
fi
cmake --build "$build" -j "$jobs"
