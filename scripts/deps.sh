#!/usr/bin/env bash
# Installs the Debian 12 packages pathspace needs, if any is missing.
# As root: apt-get. Otherwise with sudo if there is one. Otherwise: print the apt line, stop.
#   bash scripts/deps.sh              # what the build and the tests need
#   bash scripts/deps.sh PACKAGE ...  # these instead (the lecturer's tools: scripts/site.sh, slides.sh)
set -euo pipefail
PACKAGES=(cmake make g++ libglm-dev libstb-dev libtinyobjloader-dev doctest-dev libtinyexr-dev ccache bubblewrap)
[ $# -gt 0 ] && PACKAGES=("$@")

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

line="apt-get install -y --no-install-recommends ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  echo "pathspace: installing ${missing[*]}" >&2
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive $line
elif command -v sudo >/dev/null 2>&1; then
  echo "pathspace: installing ${missing[*]} (sudo)" >&2
  sudo apt-get update -qq && sudo DEBIAN_FRONTEND=noninteractive $line
else
  echo "pathspace: missing packages: ${missing[*]}" >&2
  echo "run as root:  apt-get update && $line" >&2
  exit 1
fi
