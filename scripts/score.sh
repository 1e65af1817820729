#!/usr/bin/env bash
# The student's score: builds (Release, in build/), runs the graded tests of the lessons asked for
# and prints the grader's table (tools/score.cpp): every graded test with its points, pass or FAIL,
# a total per lesson. The course's grader runs the same tests on the same seeds.
#   bash scripts/score.sh           # every lesson built from your files
#   bash scripts/score.sh 3 5       # lessons 3 and 5 from your files (even if released)
# The grader builds the lesson it grades from your files and every other lesson from the reference.
# The build here does the same wherever the reference is here (released/ after a release, README
# "Releases and fixes"); a lesson without one is built from your files. So a lesson scores here as
# the grader scores it when every earlier lesson is released (or when you score it alone and your
# earlier lessons are right); the script says which earlier lessons came from your files.
set -euo pipefail
cd "$(dirname "$0")/.."
asked=()
for a in "$@"; do
  case "$a" in
    -h|--help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *[!0-9]*|'') echo "score: '$a' is not a lesson number (see --help)" >&2; exit 2 ;;
    *) [ -d "$(ls -d tests/"$(printf '%02d' "$((10#$a))")"-*/ 2>/dev/null | head -1)" ] ||
         { echo "score: there is no lesson $a (tests/$(printf '%02d' "$((10#$a))")-*)" >&2; exit 2; }
       asked+=("$((10#$a))") ;;
  esac
done
# The lessons, and which have a reference in this tree (solutions/ or released/).
all=() with_ref=()
for d in tests/[0-9][0-9]-*/; do
  nn=$(basename "$d" | cut -c1-2)
  all+=("$((10#$nn))")
  if [ -n "$(ls -d solutions/"$nn"-*/ released/"$nn"-*/ 2>/dev/null)" ]; then with_ref+=("$((10#$nn))"); fi
done
has_ref() { local n; for n in "${with_ref[@]}"; do [ "$n" = "$1" ] && return 0; done; return 1; }
is_asked() { local n; for n in "${asked[@]}"; do [ "$n" = "$1" ] && return 0; done; return 1; }
# What is built from the student's files: the lessons asked for, and every lesson without a reference.
mine=() scored=()
for n in "${all[@]}"; do
  if is_asked "$n" || ! has_ref "$n"; then mine+=("$n"); fi
done
if [ ${#asked[@]} -gt 0 ]; then
  scored=("${asked[@]}")
elif [ ${#mine[@]} -gt 0 ]; then
  scored=("${mine[@]}")   # every lesson built from your files
else
  scored=("${all[@]}")    # the lecturer's tree: every lesson, from the reference
fi
student=$(IFS=';'; echo "${asked[*]}")
bash scripts/deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPATHSPACE_STUDENT="$student" >/dev/null
# A lesson that does not compile is reported, and its tests score 0; the others still count.
cmake --build build -j"$(nproc)" -- -k >build/score-build.log 2>&1 ||
  echo "score: the build failed (build/score-build.log); the tests that did build are scored" >&2
labels=$(for n in "${scored[@]}"; do printf 'lesson-%02d|' "$n"; done)
labels="^(${labels%|})\$"
rm -f build/score.xml
(cd build && ctest -L "$labels" -j"$(nproc)" --timeout 300 --output-junit "$PWD/score.xml" >score-ctest.log 2>&1) || true
which=$(IFS=','; echo "${scored[*]}")
./build/score --source . --junit build/score.xml --lessons "$which" --out build/score-report
# Which lessons the scored ones ran with: the grader uses the reference of every other lesson.
ranges() {  # 0 1 2 5 -> "0-2, 5"
  local out="" start="" prev="" n
  for n in "$@" ""; do
    if [ -n "$prev" ] && [ "$n" = "$((prev + 1))" ]; then prev=$n; continue; fi
    [ -n "$start" ] && out+="${out:+, }$start$([ "$prev" != "$start" ] && echo "-$prev")"
    start=$n prev=$n
  done
  echo "$out"
}
released=()
for n in "${with_ref[@]}"; do is_asked "$n" || released+=("$n"); done
[ ${#released[@]} -gt 0 ] && [ ${#released[@]} -lt ${#all[@]} ] &&
  echo "built from the reference (released/): lessons $(ranges "${released[@]}"); from your files: lessons $(ranges "${mine[@]}")"
with_own=() lines=()
for n in "${scored[@]}"; do
  own=()
  for m in "${mine[@]}"; do [ "$m" -lt "$n" ] && own+=("$m"); done
  if [ ${#own[@]} -gt 0 ]; then
    with_own+=("$n")
    lines+=("lesson $n ran with your own lessons $(ranges "${own[@]}"), not the reference")
  fi
done
if [ ${#with_own[@]} -gt 3 ]; then
  echo "lessons $(ranges "${with_own[@]}") ran with your own earlier lessons, not the reference"
elif [ ${#with_own[@]} -gt 0 ]; then
  printf '%s\n' "${lines[@]}"
fi
[ ${#with_own[@]} -gt 0 ] &&
  echo "(the grader builds every lesson but the graded one from the reference: README, \"Releases and fixes\")"
exit 0
