#!/usr/bin/env bash
# Installs the Debian packages that building, testing and running TiledRayCast need, if any is
# missing: Debian 12's or Debian 13's set (Module/debian-release.sh; any other system is refused
# with a message). Needs root (or sudo) only when something must be installed.
#   Module/install-deps.sh --list   prints the packages for this release, installs nothing
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
. "$here/Module/debian-release.sh"
trc_release_or_die
packages=("${trc_packages[@]}")
if [ "${1:-}" = --list ]; then
  echo "${packages[*]}"
  exit 0
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "TiledRayCast: installing missing Debian $trc_debian packages: ${missing[*]}"
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    sudo="sudo"
  else
    echo "error: these packages are missing and this is not root: ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
