#!/usr/bin/env bash
# Fetches this Debian release's ParaView (paraview, python3-paraview, paraview-dev: 5.11 on
# Debian 12, 5.13 on Debian 13, Module/debian-release.sh) and unpacks it into a private root, ${TRC_PARAVIEW_ROOT:-build/paraview/root}; the .deb files are kept in
# build/paraview/debs and reused. It never installs ParaView: python3-paraview declares
# Conflicts: python3-vtk9, so installing it would remove VTK's Python modules and libvtk9-dev,
# which the VTK module is built against (docs/paraview.md). The shared libraries ParaView needs
# and this system lacks (Debian packages that do not conflict with anything) are installed with
# apt-get, as Module/install-deps.sh installs the module's own dependencies.
#
# Exit status: 0 when the root is ready (fetched now or reused), 125 when it cannot be fetched
# here (no apt-get, no network, not root where something must be installed): the reason is
# printed, and the ParaView tests report themselves skipped, never passed. On a release other
# than Debian 12 or 13: a message and 1. python3-paraview declares Conflicts: python3-vtk9 on
# both releases.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${TRC_BUILD_DIR:-$here/build}"
root="${TRC_PARAVIEW_ROOT:-$build/paraview/root}"
debs="$build/paraview/debs"
. "$here/Module/debian-release.sh"
trc_release_or_die
packages=(paraview python3-paraview paraview-dev)
version="$trc_paraview_deb"

skip() {
  echo "TiledRayCast: cannot fetch ParaView here: $*" >&2
  exit 125
}

if [ -f "$root/.complete" ]; then
  case "$(cat "$root/.complete")" in
    "$trc_paraview".*) ;;
    *) echo "TiledRayCast: the private ParaView root $root holds ParaView $(cat "$root/.complete")," \
      "not Debian $trc_debian's $trc_paraview: remove it (and $debs) first" >&2
      exit 1 ;;
  esac
  echo "TiledRayCast: reusing the private ParaView root $root ($(cat "$root/.complete"))"
  exit 0
fi
command -v apt-get >/dev/null 2>&1 || skip "no apt-get (a Debian $trc_debian system is needed)"
command -v dpkg >/dev/null 2>&1 || skip "no dpkg"

sudo=""
if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null 2>&1; then
  sudo="sudo"
fi

# The package lists must know ParaView (a fresh system, or a root made by mmdebstrap, may have
# none): read them again once if they do not.
if ! apt-cache show "${packages[0]}" >/dev/null 2>&1; then
  if [ "$(id -u)" -ne 0 ] && [ -z "$sudo" ]; then
    skip "the package lists do not know ${packages[0]}, and this is not root (apt-get update)"
  fi
  $sudo apt-get update -q >/dev/null 2>&1 || skip "apt-get update failed (no network?)"
  apt-cache show "${packages[0]}" >/dev/null 2>&1 ||
    skip "Debian $trc_debian's package lists have no ${packages[0]}"
fi

# The libraries that paraview and python3-paraview link, where missing: every "lib*" dependency
# of theirs but alternatives (libqt5gui5 | libqt5gui5-gles: only the GUI needs either). The
# Python and Qt tool dependencies are not needed by pvbatch, pvpython or the plugin's build.
missing=()
while read -r dep; do
  if ! dpkg-query -W -f='${Status}' "$dep" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$dep")
  fi
done < <(apt-cache depends --no-recommends --no-suggests --no-conflicts --no-breaks \
  --no-replaces --no-enhances "${packages[@]:0:2}" 2>/dev/null |
  awk '$1 == "|Depends:" { alternative = 1; next }
       $1 == "Depends:" && alternative { alternative = 0; next }  # a choice: leave it to the GUI
       $1 == "Depends:" && $2 ~ /^lib/ && $2 !~ /-dev$/ { print $2 }' | sort -u)
if [ ${#missing[@]} -gt 0 ]; then
  echo "TiledRayCast: installing libraries ParaView needs: ${missing[*]}"
  if [ "$(id -u)" -ne 0 ] && [ -z "$sudo" ]; then
    skip "these libraries are missing and this is not root: ${missing[*]}"
  fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get install -y -q --no-install-recommends "${missing[@]}" >/dev/null ||
    { $sudo apt-get update -q >/dev/null 2>&1 &&
      $sudo apt-get install -y -q --no-install-recommends "${missing[@]}" >/dev/null; } ||
    skip "apt-get could not install ${missing[*]}"
fi

# The packages themselves, downloaded once into build/paraview/debs.
mkdir -p "$debs"
need=()
for p in "${packages[@]}"; do
  if ! ls "$debs/${p}_"*.deb >/dev/null 2>&1; then
    need+=("$p")
  fi
done
if [ ${#need[@]} -gt 0 ]; then
  start=$(date +%s.%N)
  # apt-get download runs as the invoking user; _apt cannot write to a root-owned build tree.
  if ! (cd "$debs" && apt-get download -q -o APT::Sandbox::User=root "${need[@]}" 2>/dev/null); then
    if [ "$(id -u)" -eq 0 ] || [ -n "$sudo" ]; then
      $sudo apt-get update -q >/dev/null 2>&1 || true
    fi
    (cd "$debs" && apt-get download -q -o APT::Sandbox::User=root "${need[@]}") ||
      skip "apt-get download ${need[*]} failed (no network or no Debian $trc_debian package lists?)"
  fi
  end=$(date +%s.%N)
  echo "TiledRayCast: downloaded ${need[*]}: $(du -cb "$debs"/*.deb | tail -1 | cut -f1) bytes" \
    "in $(awk "BEGIN { printf \"%.1f\", $end - $start }") s"
fi
for p in "${packages[@]}"; do
  v="$(dpkg-deb -f "$debs/${p}_"*.deb Version)"
  if [ "$v" != "$version" ]; then
    echo "TiledRayCast: note: $p is version $v, not $version, the version this was tested with"
  fi
done

# Unpacked into a fresh directory, then moved into place: an interrupted run leaves no root
# that looks complete.
start=$(date +%s.%N)
rm -rf "$root.partial"
mkdir -p "$root.partial"
for p in "${packages[@]}"; do
  dpkg -x "$debs/${p}_"*.deb "$root.partial"
done
# ParaView 5.13's CMake files (paraview-dev) name its Python extension modules as built
# (vtkmodules/vtkCommonCore.so), but the package installs them under Python's tagged names
# (vtkCommonCore.cpython-313-x86_64-linux-gnu.so), and find_package(ParaView) stops on the first
# missing file. Each such name gets a link to the installed module, in the private root only.
linked=0
while read -r rel; do
  f="$root.partial/usr/${rel#/}"
  tagged="${f%.so}.cpython-${trc_python/./}-x86_64-linux-gnu.so"
  if [ ! -e "$f" ] && [ -e "$tagged" ]; then
    ln -s "$(basename "$tagged")" "$f"
    linked=$((linked + 1))
  fi
done < <(cat "$root.partial/usr/lib/x86_64-linux-gnu/cmake/paraview-$trc_paraview"/{,*/}*-targets-*.cmake |
  { grep -oE '"\$\{_IMPORT_PREFIX\}/lib/python3/dist-packages/[^"]+\.so"' || true; } |
  sed -E 's/^"\$\{_IMPORT_PREFIX\}//; s/"$//' | sort -u)
if [ "$linked" -gt 0 ]; then
  echo "TiledRayCast: linked $linked Python modules under the names ParaView's CMake files use"
fi
rm -rf "$root"
mv "$root.partial" "$root"
end=$(date +%s.%N)
dpkg-deb -f "$debs/paraview_"*.deb Version > "$root/.complete"
echo "TiledRayCast: unpacked ParaView $(cat "$root/.complete") into $root" \
  "($(du -sh "$root" | cut -f1)) in $(awk "BEGIN { printf \"%.1f\", $end - $start }") s"
