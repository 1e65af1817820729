#!/usr/bin/env bash
# scripts/classroom.sh, the local runner of the student repositories' workflow, on small workflows
# (tests/course/data/workflow/): the steps run in order in the folder, with the service's shell
# (-eo pipefail) and variables; a failing step ends the job with its status; a key it cannot run
# as the service does is refused. And the handout's own workflow reads as the four steps the
# README describes. (CI runs that workflow for real in the handout: scripts/check-skeleton.sh.)
#   bash tests/course/classroom.sh SOURCE WORK
set -uo pipefail
src="$1" work="$2"
data="$src/tests/course/data/workflow"
runner="$src/scripts/classroom.sh"
rm -rf "$work" && mkdir -p "$work"
failures=0
fail() { echo "classroom: FAIL: $*"; failures=$((failures + 1)); }

# run NAME: the runner on workflow NAME.yml in the empty folder $work/NAME; its status in $status.
run() {
  mkdir -p "$work/$1"
  bash "$runner" --workflow "$data/$1.yml" "$work/$1" >"$work/$1.txt" 2>&1
  status=$?
}

run ok
[ $status -eq 0 ] || fail "ok: exit status $status: $(tail -3 "$work/ok.txt")"
want=$'one true true\ntwo in the workspace\nthree'
[ "$(cat "$work/ok/order.txt" 2>/dev/null)" = "$want" ] || fail "ok: the steps wrote '$(cat "$work/ok/order.txt" 2>/dev/null)', not '$want'"
grep -q "^the summary$" "$work/ok.txt" || fail "ok: the job summary is not printed"
[ "$(grep -c "skipped (uses actions/" "$work/ok.txt")" -eq 2 ] || fail "ok: the two uses: steps are not skipped with a note"

run fail
[ $status -eq 1 ] || fail "fail: exit status $status, expected 1 (the failing pipeline's)"
[ "$(cat "$work/fail/order.txt" 2>/dev/null)" = first ] || fail "fail: the steps wrote '$(cat "$work/fail/order.txt" 2>/dev/null)', not 'first'"
grep -q "step 2, Pipeline, failed with exit status 1" "$work/fail.txt" || fail "fail: the failing step is not named"

run refused
[ $status -eq 2 ] || fail "refused: exit status $status, expected 2"
grep -q 'the step key "if"' "$work/refused.txt" || fail "refused: the message does not name the key"
[ ! -e "$work/refused/order.txt" ] || fail "refused: a step ran"

# The handout's workflow: checkout, packages, build, score, artifact.
bash "$runner" --dry-run --workflow "$src/tools/handout/.github/workflows/classroom.yml" "$work" >"$work/handout.txt" 2>&1 ||
  fail "handout: the runner cannot read the handout's workflow: $(tail -3 "$work/handout.txt")"
for want in "skipped (uses actions/checkout" "bash scripts/deps.sh" "cmake --build build" "bash scripts/score.sh" \
  "skipped (uses actions/upload-artifact"; do
  grep -qF -- "$want" "$work/handout.txt" || fail "handout: the workflow's steps do not hold '$want'"
done

if [ $failures -gt 0 ]; then
  echo "classroom: $failures checks failed (the runner's output: $work/*.txt)"
  exit 1
fi
echo "classroom: the local runner runs a workflow's steps as the service does"
