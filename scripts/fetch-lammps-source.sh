#!/usr/bin/env bash
# Fetch and unpack a LAMMPS source from Debian's source packages, using a
# private apt configuration so the system's own apt setup is left
# untouched (scripts/debian-source.sh).  Prints the unpacked tree's path.
#
#   scripts/fetch-lammps-source.sh CACHE_DIR [VERSION]
#
# VERSION: 4Feb2025 (default; lammps 20250204+dfsg.1, trixie) or 4Jul2026
# (lammps 20260704+dfsg, sid).  The tarball is verified by its md5 sum and
# kept in CACHE_DIR, so a second call downloads nothing.
set -euo pipefail
# shellcheck source=scripts/debian-source.sh
source "$(dirname "${BASH_SOURCE[0]}")/debian-source.sh"

cache=${1:?usage: fetch-lammps-source.sh CACHE_DIR [4Feb2025|4Jul2026]}
lammps_version=${2:-4Feb2025}
case "$lammps_version" in
  4Feb2025)
    suite=trixie upstream=20250204+dfsg.1 tarball_name=lammps_20250204+dfsg.1.orig.tar.xz
    md5_expected=40ded6203700ac1fda931c76d1308eb2 topdir=lammps-4Feb2025 ;;
  4Jul2026)
    suite=sid upstream=20260704+dfsg tarball_name=lammps_20260704+dfsg.orig.tar.gz
    md5_expected=b635f5a814b3f8db20d39bf4494b79a2 topdir= ;;
  *) echo "ERROR: unknown LAMMPS version $lammps_version: use 4Feb2025 or 4Jul2026" >&2; exit 1 ;;
esac

debian_source_tree "$cache" "$suite" lammps "$upstream" "$tarball_name" "$md5_expected" "" \
  "$topdir" "$cache/lammps-$lammps_version" src/version.h
