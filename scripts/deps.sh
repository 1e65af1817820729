#!/usr/bin/env bash
# Installs the Debian 12 packages pathspace needs, if any is missing.
# As root: apt-get. Otherwise with sudo if there is one. Otherwise: print the apt line, stop.
#   bash scripts/deps.sh                 what the build, the tests and the fuzzers need
#   bash scripts/deps.sh --portability   and clang 19 (scripts/portability.sh), clang-query (check-order.sh)
#   bash scripts/deps.sh PACKAGE ...     these instead (the lecturer's tools: scripts/site.sh, slides.sh)
set -euo pipefail
# clang (14) with libc++ and LLVM's OpenMP (libomp) builds everything a second time as a macOS
# student's compiler would (scripts/portability.sh); clang++ also builds the fuzzers.
PACKAGES=(cmake make g++ libglm-dev libstb-dev libtinyobjloader-dev doctest-dev libtinyexr-dev ccache bubblewrap binutils
          clang libomp-dev libc++-dev libc++abi-dev)
# clang 19 only, not its libc++ or libomp: Debian's libc++-19-dev and libomp-19-dev conflict with
# (and replace) the version-14 packages above, which clang 14 and the fuzzers need; portability.sh
# unpacks libomp 19's two packages into its build folder instead (apt-get download, dpkg -x).
if [ "${1:-}" = --portability ]; then
  PACKAGES+=(clang-19 clang-tools)  # clang 19 (Debian 12: 1:19.1.7-3~deb12u1); clang-query (check-order.sh)
elif [ $# -gt 0 ]; then
  PACKAGES=("$@")
fi

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
