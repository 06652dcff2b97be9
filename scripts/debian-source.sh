# shellcheck shell=bash
# Shared by scripts/fetch-*-source.sh (source it, do not run it): fetch an
# upstream tarball from Debian's source packages through a PRIVATE apt state
# (its own sources.list, lists and cache under CACHE_DIR/apt/SUITE), so the
# system's apt setup is left untouched; verify it; unpack it once.
#
#   debian_source_tree CACHE_DIR SUITE PACKAGE UPSTREAM TARBALL MD5 SHA256 TOPDIR TREE MARKER
#
# Prints TREE (the unpacked tree) on stdout, all else on stderr.
# SUITE: a Debian suite (bookworm, trixie, sid); PACKAGE: the source
# package; UPSTREAM: its upstream version (whichever Debian revision of it
# SUITE offers now is taken); TARBALL: the orig tarball's file name; MD5,
# SHA256: its sums (SHA256 may be empty: then md5 only); TOPDIR: the
# tarball's top directory (empty: it has none); MARKER: a file inside TREE
# that shows it is unpacked.  The tarball is kept in CACHE_DIR, so a second
# call downloads nothing, and a verified unpacked tree is not unpacked again.
# Call it from a script under set -e (an error returns 1).

debian_source_md5() { md5sum "$1" | cut -d' ' -f1; }

# true if FILE has MD5 and, when given, SHA256
debian_source_verified() {
  local file=$1 md5=$2 sha256=$3
  [ -f "$file" ] && [ "$(debian_source_md5 "$file")" = "$md5" ] || return 1
  [ -z "$sha256" ] || [ "$(sha256sum "$file" | cut -d' ' -f1)" = "$sha256" ]
}

debian_source_download() {
  local cache=$1 suite=$2 package=$3 upstream=$4 tarball_name=$5
  local apt_dir=$cache/apt/$suite version
  mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$apt_dir/download"
  echo "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian $suite main" \
    > "$apt_dir/sources.list"
  local apt_opts=(-o "Dir::Etc::SourceList=$apt_dir/sources.list"
                  -o "Dir::Etc::SourceParts=/dev/null"
                  -o "Dir::State::Lists=$apt_dir/lists"
                  -o "Dir::Cache=$apt_dir/cache"
                  -o "Debug::NoLocking=1"
                  -o "APT::Sandbox::User=root")
  echo "fetching $package source package index (private apt state in $apt_dir)" >&2
  apt-get "${apt_opts[@]}" -q update >&2
  # pick the Debian revision of upstream $upstream that $suite offers now
  version=$(apt-cache "${apt_opts[@]}" showsrc "$package" | awk '/^Version:/ {print $2}' \
              | grep -F "$upstream-" | head -n 1 || true)
  if [ -z "$version" ]; then
    echo "ERROR: Debian $suite offers no $package source at upstream version $upstream" >&2
    return 1
  fi
  # the .dsc or .debian.tar.xz may 404; the orig tarball is all we need, so
  # ignore apt's exit code
  (cd "$apt_dir/download" && apt-get "${apt_opts[@]}" -q source --download-only "$package=$version" >&2) || true
  if [ ! -f "$apt_dir/download/$tarball_name" ]; then
    echo "ERROR: download of $tarball_name failed" >&2
    return 1
  fi
  mv "$apt_dir/download/$tarball_name" "$cache/$tarball_name"
  rm -rf "$apt_dir/download"
}

debian_source_tree() {
  local cache=$1 suite=$2 package=$3 upstream=$4 tarball_name=$5
  local md5_expected=$6 sha256_expected=$7 topdir=$8 tree=$9 marker=${10}
  local stamp=$cache/.unpacked-$md5_expected tarball=$cache/$tarball_name md5

  mkdir -p "$cache"
  # one fetch at a time per cache (held until the calling script exits)
  exec {debian_source_lock}> "$cache/.lock"
  flock "$debian_source_lock"
  if [ -f "$stamp" ] && [ -f "$tree/$marker" ]; then
    echo "$tree"
    return 0
  fi

  if ! debian_source_verified "$tarball" "$md5_expected" "$sha256_expected"; then
    debian_source_download "$cache" "$suite" "$package" "$upstream" "$tarball_name"
  fi
  md5=$(debian_source_md5 "$tarball")
  if [ "$md5" != "$md5_expected" ]; then
    echo "ERROR: $tarball has md5 $md5, expected $md5_expected" >&2
    return 1
  fi
  if ! debian_source_verified "$tarball" "$md5_expected" "$sha256_expected"; then
    echo "ERROR: $tarball has sha256 $(sha256sum "$tarball" | cut -d' ' -f1), expected $sha256_expected" >&2
    return 1
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
}
