#!/usr/bin/env bash
# The Gradescope package (scripts/gradescope.sh) run the way Gradescope runs it, under a temporary
# root instead of /autograder: the zip unzipped in ROOT/source, run_autograder copied to ROOT and
# run from there with an upload in ROOT/submission. setup.sh's build is not repeated: the package
# grades with this build's grader and prepared tree (PATHSPACE_GRADE, PATHSPACE_TREE).
# Every results.json and junit.xml it writes must pass report_check (Gradescope's published
# format, JUnit XML as CI reads it, the same tests in both) and show none of the grader's paths.
#   bash tests/course/gradescope.sh GRADE TREE SOURCE WORK REPORT_CHECK
# Exit 77 (CTest: skipped) when there is no working sandbox (bubblewrap), saying so.
set -uo pipefail
grade="$1" tree="$2" src="$3" work="$4" check="$5"
rm -rf "$work" && mkdir -p "$work"
failures=0
fail() { echo "gradescope: FAIL: $*"; failures=$((failures + 1)); }

# package NAME [OPTIONS...]: builds the zip and unzips it as Gradescope does, in $work/NAME/source.
package() {
  local name="$1" root="$work/$1"
  shift
  bash "$src/scripts/gradescope.sh" --out "$work/$name.zip" "$@" >/dev/null || { fail "$name: scripts/gradescope.sh failed"; return; }
  mkdir -p "$root/source"
  if command -v unzip >/dev/null 2>&1; then (cd "$root/source" && unzip -q "$work/$name.zip")
  else (cd "$root/source" && cmake -E tar xf "$work/$name.zip"); fi
  for f in setup.sh run_autograder; do
    [ -x "$root/source/$f" ] || fail "$name: no executable $f at the root of the zip"
  done
  cp "$root/source/run_autograder" "$root/run_autograder"
}

# upload PACKAGE NAME: runs the package on the upload in $work/uploads/NAME; its results (in
# $work/PACKAGE/results) are copied to $work/results-PACKAGE-NAME, which the checks below read.
last=""
broken_bwrap=()  # upload_without_sandbox sets it: PATHSPACE_GRADE_BWRAP=/bin/false, a bubblewrap that never works
upload() {
  local root="$work/$1" name="$2"
  last="$1-$2"
  rm -rf "$root/submission" "$root/results"
  cp -R "$work/uploads/$name" "$root/submission"
  (cd "$root" && env "${broken_bwrap[@]}" GRADESCOPE_ROOT="$root" PATHSPACE_GRADE="$grade" PATHSPACE_TREE="$tree" ./run_autograder) >"$work/$last.txt" 2>&1
  local status=$?
  if [ ${#broken_bwrap[@]} -eq 0 ] && grep -q "no working sandbox" "$work/$last.txt"; then
    echo "gradescope: SKIP: the grader has no working sandbox here:"
    sed 's/^/  /' "$work/$last.txt"
    exit 77
  fi
  [ $status -eq 0 ] || fail "$last: run_autograder exited $status: $(tail -3 "$work/$last.txt")"
  local r="$work/results-$last"
  rm -rf "$r" && cp -R "$root/results" "$r"
  # JUnit only when grade ran (an upload with no lesson has only results.json).
  local junit=()
  [ -e "$r/junit.xml" ] && junit=("$r/junit.xml")
  "$check" "$r/results.json" "${junit[@]}" --forbid "$root" --forbid "$tree" --forbid "$src" --forbid "$work" \
    --forbid "pathspace-grade-" --forbid "pathspace-upload-" >"$work/$last.check" 2>&1 || {
    fail "$last: the reports are not valid:"
    sed 's/^/  /' "$work/$last.check"
  }
  # An independent reader, where there is one.
  if command -v python3 >/dev/null 2>&1; then
    python3 -c 'import json, sys; json.load(open(sys.argv[1], encoding="utf-8"))' "$r/results.json" ||
      fail "$last: python3 cannot read results.json"
  fi
}
# expect_score full | expect_score SCORE MAX: the last upload's score.
expect_score() {
  local json="$work/results-$last/results.json" got max
  got="$(sed -n 's/^  "score": \([0-9]*\),$/\1/p' "$json")"
  max="$(sed -n 's/^  "extra_data": {"max_score": \([0-9]*\)},$/\1/p' "$json")"
  if [ "$1" = full ]; then
    [ -n "$got" ] && [ "$got" = "$max" ] && [ "$got" -gt 0 ] && echo "gradescope: $last: $got / $max, full marks" ||
      fail "$last: score '$got' of '$max', expected full marks"
  else
    [ "$got" = "$1" ] && [ "$max" = "$2" ] && echo "gradescope: $last: $got / $max" ||
      fail "$last: score '$got' of '$max', expected $1 of $2"
  fi
}
# expect_in TEXT: the last upload's results.json says TEXT.
expect_in() { grep -qF -- "$1" "$work/results-$last/results.json" || fail "$last: results.json does not say '$1'"; }

# The uploads.
u="$work/uploads"
mkdir -p "$u/folders" "$u/skeleton/00-rays" "$u/top-level" "$u/repository/pathspace-main/assignments" \
  "$u/repository/pathspace-main/lessons/00-rays" "$u/broken" "$u/nothing"
cp -R "$src/solutions/00-rays" "$src/solutions/04-measurement" "$u/folders/"       # lesson folders
cp "$src/assignments/00-rays/"* "$u/skeleton/00-rays/"                               # the untouched skeleton
cp "$src/solutions/00-rays/"* "$u/top-level/"                                        # files at the top level
cp -R "$src/solutions/00-rays" "$u/repository/pathspace-main/assignments/"          # a zipped repository
echo 'int decoy = "not the student folder";' >"$u/repository/pathspace-main/lessons/00-rays/rays.cpp"
printf '#include "camera.h"\nthis is not C++;\n' >"$u/broken/rays.cpp"                # does not build
echo "my answers" >"$u/nothing/README.txt"                                           # no lesson at all

# Lesson 0's points, from the tree's list of its graded tests ("... [N pts]", else 1).
max0=0
while IFS= read -r t; do
  p="$(echo "$t" | sed -n 's/.*\[\([0-9]*\) pts\{0,1\}\].*/\1/p')"
  max0=$((max0 + ${p:-1}))
done <"$tree/tests/00-rays.txt"

package all
upload all folders
expect_score full
expect_in "00-rays: $max0 / $max0"
expect_in "04-measurement: "
upload all skeleton
expect_score 0 "$max0"
upload all top-level
expect_score "$max0" "$max0"
expect_in "at the top level of the upload as lesson 00-rays"
upload all repository
expect_score "$max0" "$max0"
upload all broken
expect_score 0 "$max0"
expect_in "the lesson did not build"
expect_in "00-rays/rays.cpp:2"  # the compiler's message, with the file named by its lesson
upload all nothing
expect_score 0 0
expect_in "No lesson found in the upload"
expect_in "README.txt"

# A package for one lesson grades that lesson alone, and an upload without it scores 0 of that
# lesson's points.
package lesson0 --lessons 0
upload lesson0 folders
expect_score "$max0" "$max0"
expect_in "not graded: 04-measurement (this assignment grades lesson(s) 0)"
upload lesson0 nothing
expect_score 0 "$max0"
expect_in "no folder 00-rays in the submission"

# A container where bubblewrap cannot run (PATHSPACE_GRADE_BWRAP=/bin/false stands for it): the
# default package (--sandbox auto) grades without the sandbox and says so in what the student and
# the staff see; one made with --sandbox yes refuses to grade and says why.
broken_bwrap=(PATHSPACE_GRADE_BWRAP=/bin/false)
upload all folders
expect_score full
expect_in "graded without a sandbox"
grep -q "grading WITHOUT a sandbox" "$work/$last.txt" || fail "$last: the staff's log does not say the sandbox was off"
package strict --sandbox yes
root="$work/strict"
rm -rf "$root/submission" "$root/results" && cp -R "$work/uploads/folders" "$root/submission"
if (cd "$root" && env "${broken_bwrap[@]}" GRADESCOPE_ROOT="$root" PATHSPACE_GRADE="$grade" PATHSPACE_TREE="$tree" ./run_autograder) >"$work/strict.txt" 2>&1; then
  fail "strict: a package made with --sandbox yes graded without a working sandbox"
else
  grep -q "no working sandbox" "$work/strict.txt" || fail "strict: run_autograder failed without saying why: $(tail -2 "$work/strict.txt")"
  [ ! -e "$root/results/results.json" ] || fail "strict: results.json written although nothing was graded"
fi
broken_bwrap=()

if [ $failures -gt 0 ]; then
  echo "gradescope: $failures checks failed (run_autograder's output: $work/*.txt, results: $work/results-*/)"
  exit 1
fi
echo "gradescope: the package graded every upload as it should, with valid reports and no grader paths"
