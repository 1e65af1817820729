#!/usr/bin/env bash
# The include graph the course's layering promises (README, "How the lessons fit together"):
#   - a lesson may use every earlier lesson, never a later one: lessons/NN-*, solutions/NN-*,
#     assignments/NN-* and tests/NN-* include "MM-name/..." only for MM <= NN;
#   - framework/ includes no lesson header, nothing of app/ or report/, and names no lesson but
#     the ones whose student pieces it declares (0, 1, 4: "lesson 0's piece", ...);
#   - app/ and report/ include no lesson header (the program reaches the lessons through the
#     framework's registries); tests/framework/ neither;
#   - tools/ and bench/ include nothing of app/ (the report is report/, shared).
#   bash scripts/check-includes.sh [ROOT]     exit status 1 on a forbidden edge, each one named
set -uo pipefail
root="${1:-$(cd "$(dirname "$0")/.." && pwd)}"
cd "$root" || exit 2
bad=0
fail() { echo "check-includes: $*"; bad=$((bad + 1)); }

# The quoted includes of a file: one "LINE<TAB>PATH" per include "PATH".
includes() { grep -n '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "$1" | sed 's/^\([0-9]*\):[^"]*"\([^"]*\)".*/\1\t\2/'; }

# The lesson a path names ("07-bidirectional/bpt.h" -> 07), or "" for none.
lessonOf() { printf '%s' "$1" | sed -n 's#^\(\.\./\)*\(lessons/\)\{0,1\}\([0-9][0-9]\)-[^/]*/.*#\3#p'; }

sources() { find "$@" -type f \( -name '*.h' -o -name '*.cpp' \) 2>/dev/null | sort; }

# Lessons, their references, skeletons and graded tests: no later lesson.
for dir in lessons solutions assignments tests; do
  for d in "$dir"/[0-9][0-9]-*; do
    [ -d "$d" ] || continue
    own="$(basename "$d" | cut -c1-2)"
    while read -r f; do
      while IFS=$'\t' read -r line path; do
        [ -n "$path" ] || continue
        other="$(lessonOf "$path")"
        [ -n "$other" ] || continue
        if [ "$((10#$other))" -gt "$((10#$own))" ]; then
          fail "$f:$line: lesson $own includes \"$path\" of the later lesson $other"
        fi
      done < <(includes "$f")
    done < <(sources "$d")
  done
done

# framework/, app/, report/, tests/framework/: no lesson header.
for dir in framework app report tests/framework; do
  while read -r f; do
    while IFS=$'\t' read -r line path; do
      [ -n "$path" ] || continue
      [ -n "$(lessonOf "$path")" ] && fail "$f:$line: $dir/ includes the lesson header \"$path\""
      case "$path" in
        app/* | */app/* | ../app/*) fail "$f:$line: $dir/ includes \"$path\" of app/" ;;
      esac
      if [ "$dir" = framework ]; then
        case "$path" in report/* | */report/*) fail "$f:$line: framework/ includes \"$path\" of report/" ;; esac
      fi
    done < <(includes "$f")
  done < <(sources "$dir")
done

# framework/ names no lesson but those whose student pieces it declares (0, 1, 4).
while IFS=: read -r f line text; do
  for n in $(printf '%s' "$text" | grep -io 'lesson [0-9][0-9]*' | grep -o '[0-9][0-9]*'); do
    case "$((10#$n))" in
      0 | 1 | 4) ;;
      *) fail "$f:$line: framework/ names lesson $n: $(printf '%s' "$text" | sed 's/^[[:space:]]*//')" ;;
    esac
  done
done < <(grep -rnio 'lesson [0-9][0-9]*.*' framework --include='*.h' --include='*.cpp')

# tools/ and bench/: nothing of app/.
for dir in tools bench; do
  while read -r f; do
    while IFS=$'\t' read -r line path; do
      case "$path" in
        app/* | */app/* | ../app/* | ../../app/*) fail "$f:$line: $dir/ includes \"$path\" of app/" ;;
      esac
    done < <(includes "$f")
  done < <(sources "$dir")
done

if [ "$bad" -gt 0 ]; then
  echo "check-includes: $bad forbidden edge(s) (scripts/check-includes.sh says which are allowed)"
  exit 1
fi
echo "check-includes: the include graph keeps the course's layering ($(sources framework lessons solutions assignments app report tests tools bench | wc -l) files)"
