#!/usr/bin/env bash
# TODOs are contracts, not the answer (README, "How strong are the tests"): a TODO says what the
# function returns, in which measure, which equation of the lesson it implements and the pitfalls
# a TA sees, never the code. A measure of drift toward dictating the code: per lesson, the lines
# of its TODO comments (the `//! TODO(NN)` line and the comment lines after it, up to the first
# `//! STUB` or `//! BEGIN`) against the non-blank lines of its solution regions (between
# `//! BEGIN` and `//! END`). Fails if a lesson's ratio is above 0.3, naming it.
#   bash scripts/check-todos.sh [--table] [SOLUTIONS_DIR]   (default: solutions/; --table: every lesson)
set -euo pipefail
shopt -s nullglob
table=0
if [ "${1:-}" = "--table" ]; then table=1; shift; fi
dir="${1:-$(cd "$(dirname "$0")/.." && pwd)/solutions}"
limit=0.30
status=0 lessons=0
for lesson in "$dir"/*/; do
  files=("$lesson"*.cpp "$lesson"*.h)
  counts=$(awk '
    FNR == 1 { intodo = 0; inblk = 0 }
    { s = $0; sub(/^[ \t]+/, "", s); sub(/[ \t]+$/, "", s) }
    index(s, "//! TODO") == 1 { intodo = 1; todo++; next }
    intodo { if (index(s, "//! STUB") == 1 || index(s, "//! BEGIN") == 1 || index(s, "//") != 1) intodo = 0
             else { todo++; next } }
    index(s, "//! BEGIN") == 1 { inblk = 1; next }
    index(s, "//! END") == 1 { inblk = 0; next }
    inblk && s != "" { sol++ }
    END { printf "%d %d\n", todo, sol }' "${files[@]}" 2>/dev/null || echo "0 0")
  read -r todo sol <<< "$counts"
  [ "$sol" -gt 0 ] || continue
  lessons=$((lessons + 1))
  name=$(basename "$lesson")
  over=$(awk -v t="$todo" -v s="$sol" -v l="$limit" 'BEGIN { print (t / s > l) ? 1 : 0 }')
  ratio=$(awk -v t="$todo" -v s="$sol" 'BEGIN { printf "%.2f", t / s }')
  if [ "$over" = 1 ]; then
    echo "check-todos: $name: $todo TODO comment lines for $sol solution lines ($ratio, at most $limit): a TODO states the contract, not the code" >&2
    status=1
  elif [ $table = 1 ]; then
    echo "  $name  $todo / $sol = $ratio"
  fi
done
[ $lessons -gt 0 ] || { echo "check-todos: no solution regions found in $dir" >&2; exit 1; }
[ $status = 0 ] && echo "check-todos: the TODOs of $lessons lessons are contracts (at most $limit TODO lines per solution line)"
exit $status
