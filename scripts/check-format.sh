#!/usr/bin/env bash
# Checks that the tracked C++ files are formatted as .clang-format says. Lists the files that
# differ and exits 1 if there are any; 0 when all match. Changes nothing.
#   bash scripts/check-format.sh            # every tracked .cpp and .h
#   bash scripts/check-format.sh FILE...    # only these
#   CLANG_FORMAT=clang-format-14 bash scripts/check-format.sh
# To fix a file: clang-format -i FILE (Debian: apt-get install clang-format).
set -euo pipefail
cd "$(dirname "$0")/.."
cf="${CLANG_FORMAT:-clang-format}"
if ! command -v "$cf" >/dev/null 2>&1; then
  echo "check-format: $cf not found (Debian: apt-get install clang-format)" >&2
  exit 2
fi
if [ $# -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(git ls-files '*.cpp' '*.h')
fi
bad=0
for f in "${files[@]}"; do
  if ! "$cf" --style=file --dry-run -Werror "$f" >/dev/null 2>&1; then
    changed=$("$cf" --style=file "$f" | diff "$f" - | grep -c '^<' || true)
    echo "$f: $changed line(s) differ (clang-format -i $f)"
    bad=$((bad + 1))
  fi
done
if [ "$bad" -gt 0 ]; then
  echo "check-format: $bad of ${#files[@]} file(s) are not formatted as .clang-format says" >&2
  exit 1
fi
echo "check-format: ${#files[@]} file(s) formatted as .clang-format says"
