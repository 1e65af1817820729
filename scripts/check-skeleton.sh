#!/usr/bin/env bash
# CI's checks on the untouched skeleton, run by scripts/test.sh after the main tests:
#  1. the handout (no solutions/) holds no solution line, configures and builds;
#  2. in it, every graded test FAILS (a graded test that passes on the skeleton cannot tell a
#     finished assignment from an empty one: it is named and the check fails);
#  3. the student repositories' workflow (.github/workflows/classroom.yml) runs there as GitHub
#     runs it (scripts/classroom.sh) and its score command agrees with the grader: 0 of the maximum;
#  4. the grader's object check refuses none of the skeleton's files.
#   bash scripts/check-skeleton.sh BUILD_DIR
set -euo pipefail
build="$(cd "${1:-build}" && pwd)"
src="$(cd "$(dirname "$0")/.." && pwd)"
handout="$build/handout"
# The handout's build sits in it as build/ sits in the repository, so that each compile line is
# the same as the main build's relative to the tree: with the main build's ccache launcher (and
# CCACHE_BASEDIR at the repository) the framework and the tests come from the cache.
hbuild="$handout/build"
rm -rf "$handout" "$build/handout-build"
bash "$src/scripts/handout.sh" "$handout"
"$build/skeleton" leaks "$src/solutions" "$handout"

launcher=$(sed -n 's/^CMAKE_CXX_COMPILER_LAUNCHER:[A-Z]*=//p' "$build/CMakeCache.txt" 2>/dev/null || true)
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$src}"
cmake -S "$handout" -B "$hbuild" -DCMAKE_BUILD_TYPE=Release ${launcher:+-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher"} >/dev/null
# The student repositories' GitHub Classroom / Actions workflow, run as the service runs it
# (scripts/classroom.sh; the launcher above stays in the build's cache): packages, build, every
# graded test and the student's score command (scripts/score.sh, which leaves CTest's JUnit report
# in build/score.xml and its table in build/score.txt).
bash "$src/scripts/classroom.sh" "$handout" >"$build/classroom.txt" 2>&1 || {
  echo "check-skeleton: the handout's workflow failed ($build/classroom.txt):" >&2
  tail -20 "$build/classroom.txt" >&2
  exit 1
}
cd "$hbuild"
total=$(ctest -N -L '^lesson-' | sed -n 's/^Total Tests: //p')
[ "${total:-0}" -gt 0 ] || { echo "check-skeleton: no graded tests found" >&2; exit 1; }
# Scored by the autograder (the build's own, with the reference's test list): every graded test
# must fail; one that passes is named and fails CI.
"$build/grade" --source "$src" --junit "$PWD/score.xml" --expect zero --out "$build/grade-skeleton" > "$build/grade-skeleton.txt" || {
  echo "check-skeleton: a graded test that passes on the untouched skeleton cannot tell a finished assignment from an empty one" >&2
  exit 1
}
echo "check-skeleton: all $total graded tests fail on the untouched skeleton, as they must"
# The student's score command in the handout (tools/score.cpp, scripts/score.sh, run by the
# workflow) scored the same run: 0 of the same maximum as the grader's.
want=$(sed -n 's/^total *\([0-9]*\) \/ \([0-9]*\)$/0 \/ \2/p' "$build/grade-skeleton.txt")
got=$(sed -n 's/^total *\([0-9]*\) \/ \([0-9]*\)$/\1 \/ \2/p' "$hbuild/score.txt")
if [ -z "$want" ] || [ "$got" != "$want" ]; then
  echo "check-skeleton: the handout's score command says '$got', the grader '$want' ($hbuild/score.txt)" >&2
  exit 1
fi
echo "check-skeleton: the handout's workflow and score command agree: $got"
# The grader's object check (tools/grade/objcheck.h) refuses none of the skeleton's files, as the
# handout's build compiled them: an unfinished piece calls PS_TODO (which prints and calls
# std::call_once), and a student who leaves some pieces unfinished must still get the others' points.
: >"$build/objcheck-skeleton.txt"
for d in "$handout"/assignments/[0-9][0-9]-*/; do
  l="$(basename "$d")"
  mapfile -t objects < <(find "$hbuild" -path "*/assignments/$l/*.cpp.o" | sort)
  [ ${#objects[@]} -gt 0 ] || { echo "check-skeleton: no objects of $l in the handout's build" >&2; exit 1; }
  "$build/grade" --check-objects "$l" "${objects[@]}" --tree "$build/grader" >>"$build/objcheck-skeleton.txt" || {
    echo "check-skeleton: the grader's object check refuses the skeleton of $l:" >&2
    cat "$build/objcheck-skeleton.txt" >&2
    exit 1
  }
done
echo "check-skeleton: the grader's object check refuses none of the skeleton's files"
