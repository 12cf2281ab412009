#!/usr/bin/env bash
# Unpacks Debian 13 (trixie)'s libcgal-dev 6.0.1 into DEST (default build/cgal6), next to the
# system's CGAL 5.5.1, and prints the CGAL_DIR to configure with.
#   bash scripts/fetch_cgal6.sh [--lab] [DEST]
# --lab: also libcgal-qt6-dev (CGAL's Qt6 headers) and libcgal-demo (demo.tar.gz, whose demo/Lab
# is CGAL Lab, the Qt6 demo that demo/CMakeLists.txt builds with our plugins against CGAL 6).
# apt-get runs on a private configuration under DEST (sources.list, package lists, cache):
# trixie is never added to the system's sources and nothing is installed; the .deb files are
# only unpacked with dpkg -x. Skips all work when DEST already holds what is asked for.
set -euo pipefail
cd "$(dirname "$0")/.."
with_lab=false
if [ "${1:-}" = --lab ]; then with_lab=true; shift; fi
dest="$(realpath -m "${1:-build/cgal6}")"
cgal_dir="$dest/usr/lib/x86_64-linux-gnu/cmake/CGAL"

fail() { echo "fetch_cgal6: $*" >&2; exit 1; }

has_cgal6() { grep -qs '#define CGAL_VERSION 6\.0\.1' "$dest/usr/include/CGAL/version.h"; }
has_lab() { [ -f "$dest/usr/include/CGAL/Qt/GraphicsItem.h" ] && [ -f "$dest/usr/share/doc/libcgal-demo/demo.tar.gz" ]; }

if has_cgal6 && [ -f "$cgal_dir/CGALConfig.cmake" ] && { ! $with_lab || has_lab; }; then
  echo "$cgal_dir"
  exit 0
fi

# The mirror host of the system's Debian sources, trixie's keys from debian-archive-keyring.
mirror="$(grep -hE '^[[:space:]]*(URIs:|deb )' /etc/apt/sources.list /etc/apt/sources.list.d/*.list \
            /etc/apt/sources.list.d/*.sources 2>/dev/null | grep -oE 'https?://[^ ]+/debian/?( |$)' \
            | head -n1 | tr -d ' ' || true)"
mirror="${mirror:-http://deb.debian.org/debian}"
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
[ -r "$keyring" ] || fail "$keyring is missing (apt-get install debian-archive-keyring)"

apt_dir="$dest/apt"
mkdir -p "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial" "$apt_dir/sources.list.d" \
         "$apt_dir/preferences.d" "$apt_dir/debs"
echo "deb [signed-by=$keyring] ${mirror%/} trixie main" > "$apt_dir/sources.list"
: > "$apt_dir/status"
apt_options=(
  -o "Dir::Etc::SourceList=$apt_dir/sources.list"
  -o "Dir::Etc::SourceParts=$apt_dir/sources.list.d"
  -o "Dir::Etc::Preferences=$apt_dir/preferences"
  -o "Dir::Etc::PreferencesParts=$apt_dir/preferences.d"
  -o "Dir::State::Lists=$apt_dir/lists"
  -o "Dir::State::status=$apt_dir/status"
  -o "Dir::Cache=$apt_dir/cache"
  -o "APT::Sandbox::User=root"
  -q
)

# apt-get update only warns when an index cannot be fetched: check that trixie's list is there.
apt-get "${apt_options[@]}" update > "$apt_dir/update.log" 2>&1 || true
ls "$apt_dir"/lists/*trixie*Release > /dev/null 2>&1 \
  || fail "apt-get update of trixie failed: $(grep -m1 -A1 -E '^(E|Err):' "$apt_dir/update.log" | tr -s ' \n' ' ')"
version="$(apt-cache "${apt_options[@]}" madison libcgal-dev | awk -F'|' '{gsub(/ /,"",$2); print $2}' \
             | grep -m1 '^6\.0\.1' || true)"
[ -n "$version" ] || fail "trixie has no libcgal-dev 6.0.1 (apt-cache madison libcgal-dev lists: $(apt-cache "${apt_options[@]}" madison libcgal-dev | awk -F'|' '{print $2}' | tr -d ' ' | tr '\n' ' '))"
# download_and_unpack PACKAGE: trixie's PACKAGE at version $version, unpacked into $dest
download_and_unpack() {
  (cd "$apt_dir/debs" && apt-get "${apt_options[@]}" download "$1=$version") > "$apt_dir/download.log" 2>&1 \
    || fail "apt-get download $1=$version failed: $(grep -E '^(E|Err):' "$apt_dir/download.log" | head -n1)"
  local deb
  deb="$(ls "$apt_dir"/debs/"$1"_*.deb 2>/dev/null | head -n1)"
  [ -n "$deb" ] || fail "no $1 .deb in $apt_dir/debs after the download"
  dpkg -x "$deb" "$dest" || fail "dpkg -x $deb failed"
}
download_and_unpack libcgal-dev
if $with_lab; then
  download_and_unpack libcgal-qt6-dev
  download_and_unpack libcgal-demo
  has_lab || fail "$dest has no CGAL/Qt/GraphicsItem.h or libcgal-demo's demo.tar.gz after unpacking"
fi
has_cgal6 || fail "$dest/usr/include/CGAL/version.h does not say 6.0.1 after unpacking libcgal-dev"
[ -f "$cgal_dir/CGALConfig.cmake" ] || fail "$cgal_dir/CGALConfig.cmake is missing in libcgal-dev"
echo "$cgal_dir"
