#!/usr/bin/env bash
# The student's score: builds (Release, in build/), runs the graded tests of the lessons asked for
# and prints the grader's table (tools/score.cpp): every graded test with its points, pass or FAIL,
# a total per lesson. The course's grader runs the same tests on the same seeds.
#   bash scripts/score.sh           # every lesson
#   bash scripts/score.sh 3 5       # lessons 3 and 5
set -euo pipefail
cd "$(dirname "$0")/.."
lessons=() ctest_labels=()
for a in "$@"; do
  case "$a" in
    -h|--help) sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *[!0-9]*|'') echo "score: '$a' is not a lesson number (see --help)" >&2; exit 2 ;;
    *) nn=$(printf '%02d' "$((10#$a))"); lessons+=("$((10#$a))"); ctest_labels+=("lesson-$nn") ;;
  esac
done
bash scripts/deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
# A lesson that does not compile is reported, and its tests score 0; the others still count.
cmake --build build -j"$(nproc)" -- -k >build/score-build.log 2>&1 ||
  echo "score: the build failed (build/score-build.log); the tests that did build are scored" >&2
labels="^lesson-"
[ ${#ctest_labels[@]} -gt 0 ] && labels="^($(IFS='|'; echo "${ctest_labels[*]}"))\$"
rm -f build/score.xml
(cd build && ctest -L "$labels" -j"$(nproc)" --timeout 300 --output-junit "$PWD/score.xml" >score-ctest.log 2>&1) || true
which=all
[ ${#lessons[@]} -gt 0 ] && which=$(IFS=','; echo "${lessons[*]}")
./build/score --source . --junit build/score.xml --lessons "$which" --out build/score-report
