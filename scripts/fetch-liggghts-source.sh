#!/usr/bin/env bash
# Fetch and unpack the LIGGGHTS 3.8.0 source from Debian's source package
# (bookworm: liggghts 3.8.0+repack1), using a private apt configuration so
# the system's own apt setup is left untouched (scripts/debian-source.sh).
# Prints the unpacked tree's path (CACHE_DIR/liggghts-3.8.0: src/,
# examples/, doc/).
#
#   scripts/fetch-liggghts-source.sh CACHE_DIR
#
# The orig tarball is verified by its md5 and sha256 sums and kept in
# CACHE_DIR, so a second call downloads nothing.  Only the orig tarball is
# used: Debian's packaging (and its patches) is not.
set -euo pipefail
# shellcheck source=scripts/debian-source.sh
source "$(dirname "${BASH_SOURCE[0]}")/debian-source.sh"

cache=${1:?usage: fetch-liggghts-source.sh CACHE_DIR}
debian_source_tree "$cache" bookworm liggghts 3.8.0+repack1 liggghts_3.8.0+repack1.orig.tar.xz \
  246e46e26e63446fa77ae79e84810aec c18721d9a870c5170f03b91e4f1ffe13335c66ed1f0ff2c64ebd3be91c37867a \
  LIGGGHTS-PUBLIC-3.8.0 "$cache/liggghts-3.8.0" src/version_liggghts.txt
