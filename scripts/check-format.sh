#!/usr/bin/env bash
# Checks that the tracked C++ files are formatted as .clang-format says. Lists the files that
# differ and exits 1 if there are any; 0 when all match. Changes nothing. assignments/ is left
# out: it is generated from solutions/ (tools/skeleton.cpp), whose format is checked.
#   bash scripts/check-format.sh            # every tracked .cpp and .h
#   bash scripts/check-format.sh FILE...    # only these
#   CLANG_FORMAT=clang-format-14 bash scripts/check-format.sh
# .clang-format is written for clang-format 14 (Debian 12's): another major version formats some
# constructs differently, so without version 14 the check is skipped with a note (exit 0).
# To fix a file: clang-format -i FILE (Debian: apt-get install clang-format).
set -euo pipefail
cd "$(dirname "$0")/.."
# Control characters in text files: a LaTeX "\\frac", "\\beta" or "\\theta" written through a
# string with escapes becomes a form feed, a backspace or a tab, and the equation is garbled in
# the lesson or on the slide without any error. No such byte in tracked text (tabs only in code).
ctrl=$(git ls-files -z | grep -zvE '\.(png|jpg|jpeg|pfm|hdr|exr|gz|zip|pdf|ico|bin)$' |
  xargs -0 grep -lP '[\x00-\x08\x0b-\x1f]' 2>/dev/null || true)
tabs=$(git ls-files -z '*.md' '*.scene' | xargs -0 grep -lP '\t' 2>/dev/null || true)
if [ -n "$ctrl$tabs" ]; then
  for f in $(printf "%s\n" $ctrl $tabs | sort -u); do
    grep -nP '[\x00-\x08\x0b-\x1f]' "$f" | head -3 | cut -c1-100 | sed "s#^#$f:#" | cat -v
    case "$f" in *.md|*.scene) grep -nP '\t' "$f" | head -3 | cut -c1-100 | sed "s#^#$f:#" | cat -T ;; esac
  done
  echo "check-format: control characters (^L, ^H, ^I ...) in text files: an escaped LaTeX command? Write \\frac, \\beta, \\theta" >&2
  exit 1
fi
# Merge-conflict markers left in a tracked text file (a lesson README once shipped with them).
conflicts=$(git ls-files -z | grep -zvE '\.(png|jpg|jpeg|pfm|hdr|exr|gz|zip|pdf|ico|bin)$' |
  xargs -0 grep -lE '^(<<<<<<< |>>>>>>> )' 2>/dev/null || true)
if [ -n "$conflicts" ]; then
  printf '%s\n' $conflicts | sed 's/$/: merge-conflict markers (<<<<<<< ... >>>>>>>)/'
  echo "check-format: merge-conflict markers in tracked files" >&2
  exit 1
fi
cf="${CLANG_FORMAT:-clang-format}"
if ! command -v "$cf" >/dev/null 2>&1; then
  echo "check-format: $cf not found: format check skipped (Debian 12: apt-get install clang-format)" >&2
  exit 0
fi
major=$("$cf" --version | sed -n 's/.*version \([0-9]*\)\..*/\1/p')
if [ "$major" != 14 ]; then
  echo "check-format: $cf is version ${major:-unknown}, .clang-format is written for 14: format check skipped" >&2
  exit 0
fi
if [ $# -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(git ls-files '*.cpp' '*.h' | grep -v '^assignments/')
fi
# One clang-format per batch of files (a process per file costs more than the formatting); its
# "code should be clang-formatted" errors name the files that differ.
bad=$(printf '%s\0' "${files[@]}" | xargs -0 -n 40 -P "$(nproc)" "$cf" --style=file --dry-run -Werror 2>&1 |
  sed -n 's/^\(.*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' | sort -u || true)
if [ -n "$bad" ]; then
  while IFS= read -r f; do
    changed=$("$cf" --style=file "$f" | diff "$f" - | grep -c '^<' || true)
    echo "$f: $changed line(s) differ (clang-format -i $f)"
  done <<< "$bad"
  echo "check-format: $(printf '%s\n' "$bad" | wc -l) of ${#files[@]} file(s) are not formatted as .clang-format says" >&2
  exit 1
fi
echo "check-format: ${#files[@]} file(s) formatted as .clang-format says"
