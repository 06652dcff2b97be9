#!/usr/bin/env bash
# Install the Debian packages GRFLOW needs to build, test and analyse.
# Runs apt-get only when something is missing.
set -euo pipefail

pkgs=(build-essential cmake ninja-build ccache xz-utils ca-certificates patch
      libopenmpi-dev openmpi-bin libgtest-dev libjpeg-dev libpng-dev
      python3 python3-numpy python3-matplotlib python3-pytest clang-format snakemake
      python3-venv python3-setuptools)   # the analysis's venv and build backend

missing=()
for p in "${pkgs[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep "install ok installed" > /dev/null; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "installing: ${missing[*]}"
sudo=()
[ "$(id -u)" -ne 0 ] && sudo=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
