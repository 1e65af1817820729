#!/usr/bin/env bash
# The points a lesson announces are the points its graded tests carry: the heading
# "## N. How it is graded (P points)" (or "How you are graded") of lessons/NN-name/README.md and
# every slide heading "## ... (P points)" of slides/NN-name.md, against the sum of the "[k pts]"
# of the TEST_CASEs in tests/NN-name/, counted as the student's score counts them (tools/score.cpp,
# run here on no test report: every test 0 of its points).
#   bash tests/course/readme_points.sh SCORE SRC WORK
set -uo pipefail
score="$1" src="$2" work="$3"
rm -rf "$work" && mkdir -p "$work"
"$score" --source "$src" --junit "$work/no-report.xml" --out "$work/report" >"$work/table.txt" ||
  { echo "readme_points: $score failed ($work/table.txt)"; exit 1; }
failures=0 lessons=0
fail() { echo "readme_points: FAIL: $*"; failures=$((failures + 1)); }
while read -r lesson max; do
  lessons=$((lessons + 1))
  readme="$src/lessons/$lesson/README.md"
  heading="$(grep -m1 -E '^## .*How (it is|you are) graded' "$readme" 2>/dev/null)"
  said="$(printf '%s' "$heading" | sed -n 's/.*(\([0-9]*\) points).*/\1/p')"
  if [ -z "$said" ]; then
    fail "lessons/$lesson/README.md has no heading '## N. How it is graded ($max points)'"
  elif [ "$said" != "$max" ]; then
    fail "lessons/$lesson/README.md says '$heading', its graded tests carry $max points"
  fi
  while IFS= read -r slide; do
    n="$(printf '%s' "$slide" | sed -n 's/.*(\([0-9]*\) points).*/\1/p')"
    [ "$n" = "$max" ] || fail "slides/$lesson.md says '$slide', the lesson's graded tests carry $max points"
  done < <(grep -E '^## .*\([0-9]+ points\)' "$src/slides/$lesson.md" 2>/dev/null)
done < <(sed -n 's/^\([0-9][0-9]-[^ ]*\) \{1,\}0 \/ \([0-9]\{1,\}\)$/\1 \2/p' "$work/table.txt")
[ "$lessons" -gt 0 ] || { echo "readme_points: no lesson in the score table ($work/table.txt)"; exit 1; }
if [ $failures -gt 0 ]; then
  echo "readme_points: $failures of the lessons' announced totals disagree with their tests"
  exit 1
fi
echo "readme_points: the README and slides of all $lessons lessons announce the points their tests carry"
