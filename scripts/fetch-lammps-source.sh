#!/usr/bin/env bash
# Fetch and unpack a LAMMPS source from Debian's source packages, using a
# private apt configuration so the system's own apt setup is left
# untouched.  Prints the unpacked tree's path.
#
#   scripts/fetch-lammps-source.sh CACHE_DIR [VERSION]
#
# VERSION: 4Feb2025 (default; lammps 20250204+dfsg.1, trixie) or 4Jul2026
# (lammps 20260704+dfsg, sid).  The tarball is verified by its md5 sum and
# kept in CACHE_DIR, so a second call downloads nothing.
set -euo pipefail

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
tree=$cache/lammps-$lammps_version
stamp=$cache/.unpacked-$md5_expected

mkdir -p "$cache"
if [ -f "$stamp" ] && [ -f "$tree/src/version.h" ]; then
  echo "$tree"
  exit 0
fi

tarball=$cache/$tarball_name
md5_of() { md5sum "$1" | cut -d' ' -f1; }

if [ ! -f "$tarball" ] || [ "$(md5_of "$tarball")" != "$md5_expected" ]; then
  apt_dir=$cache/apt
  mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$apt_dir/download"
  echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian $suite main" \
    > "$apt_dir/sources.list"
  apt_opts=(-o "Dir::Etc::SourceList=$apt_dir/sources.list"
            -o "Dir::Etc::SourceParts=/dev/null"
            -o "Dir::State::Lists=$apt_dir/lists"
            -o "Dir::Cache=$apt_dir/cache"
            -o "Debug::NoLocking=1"
            -o "APT::Sandbox::User=root")
  echo "fetching LAMMPS source package index (private apt state in $apt_dir)" >&2
  apt-get "${apt_opts[@]}" -q update >&2
  # pick the Debian revision of upstream $upstream that $suite offers now
  version=$(apt-cache "${apt_opts[@]}" showsrc lammps | awk '/^Version:/ {print $2}' \
              | grep -F "$upstream-" | head -n 1 || true)
  if [ -z "$version" ]; then
    echo "ERROR: Debian $suite offers no lammps source at upstream version $upstream" >&2
    exit 1
  fi
  # the .dsc may 404; the orig tarball is all we need, so ignore apt's exit code
  (cd "$apt_dir/download" && apt-get "${apt_opts[@]}" -q source --download-only "lammps=$version" >&2) || true
  if [ ! -f "$apt_dir/download/$tarball_name" ]; then
    echo "ERROR: download of $tarball_name failed" >&2
    exit 1
  fi
  mv "$apt_dir/download/$tarball_name" "$tarball"
  rm -rf "$apt_dir/download"
fi

md5=$(md5_of "$tarball")
if [ "$md5" != "$md5_expected" ]; then
  echo "ERROR: $tarball has md5 $md5, expected $md5_expected" >&2
  exit 1
fi

echo "unpacking $tarball_name" >&2
rm -rf "$tree" "$cache/unpack.tmp"
mkdir -p "$cache/unpack.tmp"
tar -xf "$tarball" -C "$cache/unpack.tmp"
if [ -n "$topdir" ]; then
  mv "$cache/unpack.tmp/$topdir" "$tree"
  rmdir "$cache/unpack.tmp"
else
  mv "$cache/unpack.tmp" "$tree"    # this tarball has no top directory
fi
touch "$stamp"
echo "$tree"
