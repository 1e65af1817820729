#!/usr/bin/env bash
# Runs the student repositories' GitHub Actions workflow (tools/handout/.github/workflows/
# classroom.yml, which scripts/handout.sh puts in the handout as .github/workflows/classroom.yml)
# on this machine, the way the service runs its job: each step's `run:` script in order, in the
# checkout (here: a handout folder), with `bash --noprofile --norc -eo pipefail` as `shell: bash`
# does, CI, GITHUB_ACTIONS, GITHUB_WORKSPACE, RUNNER_TEMP and GITHUB_STEP_SUMMARY set; the first
# step that fails ends the job with its status. `uses:` steps are the service's own and are
# skipped with a note (actions/checkout: the folder is the checkout; actions/upload-artifact: the
# files stay where they are). It runs here, not in the workflow's debian:12 container: on
# Debian 12 with the packages installed, scripts/deps.sh has nothing to do and needs no network.
#   bash scripts/classroom.sh [--dry-run] [--workflow FILE] DIR
# DIR: a handout (bash scripts/handout.sh DIR), whose files the steps may change: give a copy.
# --dry-run prints the steps without running them. --workflow FILE: another workflow file
# (default DIR/.github/workflows/classroom.yml).
# The workflow may use only what this runner does the same as the service: `run:` as one line
# or a `|` block, `name:`, `uses:` with `with:`, and `shell: bash` under `defaults: run:`; any
# other step key (if, env, working-directory, continue-on-error, shell, ...) is refused.
set -euo pipefail
dry=0 workflow="" dir=""
while [ $# -gt 0 ]; do
  case "$1" in
    --dry-run) dry=1; shift ;;
    --workflow) workflow="$2"; shift 2 ;;
    -*) echo "classroom: unknown option $1" >&2; exit 2 ;;
    *) dir="$1"; shift ;;
  esac
done
[ -n "$dir" ] && [ -d "$dir" ] || { echo "usage: bash scripts/classroom.sh [--dry-run] [--workflow FILE] DIR" >&2; exit 2; }
dir="$(cd "$dir" && pwd)"
workflow="${workflow:-$dir/.github/workflows/classroom.yml}"
[ -f "$workflow" ] || { echo "classroom: no workflow $workflow" >&2; exit 2; }
grep -qE '^    shell: bash$' "$workflow" && grep -qE '^defaults:$' "$workflow" ||
  { echo "classroom: $workflow: the runner needs 'defaults: run: shell: bash' (the service's default shell differs)" >&2; exit 2; }

temp="$(mktemp -d "${TMPDIR:-/tmp}/pathspace-classroom-XXXXXX")"
trap 'rm -rf "$temp"' EXIT
# The steps, one file each: $temp/N.kind (run or uses), N.name, N.sh (the script or the action).
awk -v out="$temp" '
  function indent(s) { match(s, /^ */); return RLENGTH }
  function fail(msg) { printf "classroom: %s:%d: %s\n", FILENAME, NR, msg > "/dev/stderr"; bad = 1; exit 2 }
  function key(s) { sub(/^ *(- )?/, "", s); return substr(s, 1, index(s, ":") - 1) }
  function value(s) { sub(/^[^:]*: */, "", s); return s }
  function step_key(line,   k, v) {
    k = key(line); v = value(line)
    if (k == "name") { print v > (out "/" n ".name"); return }
    if (k == "uses") { print "uses" > (out "/" n ".kind"); print v > (out "/" n ".sh"); return }
    if (k == "with") { inwith = 1; return }
    if (k == "run") {
      print "run" > (out "/" n ".kind")
      if (v == "|") { block = 1; blockind = -1; return }
      if (v ~ /^[|>]/) fail("run: " v " (only a one-line run: or a | block)")
      print v > (out "/" n ".sh"); return
    }
    fail("the step key \"" k "\" (the local runner runs only name, run, uses and with)")
  }
  /^ *steps:$/ { steps = 1; stepind = -1; next }
  !steps { next }
  {
    ind = indent($0)
    if (block) {
      if ($0 ~ /^ *$/) { print "" > (out "/" n ".sh"); next }
      if (blockind < 0) blockind = ind
      if (ind >= blockind) { print substr($0, blockind + 1) > (out "/" n ".sh"); next }
      block = 0
    }
    if ($0 ~ /^ *(#.*)?$/) next
    if (stepind < 0) stepind = ind
    if (ind < stepind) { steps = 0; next }
    if (ind == stepind && $0 ~ /^ *- /) { n++; inwith = 0; step_key($0); next }
    if (ind == stepind + 2) { inwith = 0; step_key($0); next }
    if (inwith && ind > stepind + 2) next
    fail("a line the local runner does not understand")
  }
  END { if (!bad && n == 0) { printf "classroom: %s: no steps\n", FILENAME > "/dev/stderr"; exit 2 } }
' "$workflow"

summary="$temp/summary.md"
: >"$summary"
n=0
while [ -f "$temp/$((n + 1)).kind" ]; do
  n=$((n + 1))
  name="$(cat "$temp/$n.name" 2>/dev/null || echo "step $n")"
  kind="$(cat "$temp/$n.kind")"
  if [ "$kind" = uses ]; then
    echo "classroom: step $n, $name: skipped (uses $(cat "$temp/$n.sh"): the service's own action)"
    continue
  fi
  echo "classroom: step $n, $name"
  if [ $dry -eq 1 ]; then
    sed 's/^/    /' "$temp/$n.sh"
    continue
  fi
  status=0
  (cd "$dir" && CI=true GITHUB_ACTIONS=true GITHUB_WORKSPACE="$dir" RUNNER_TEMP="$temp" GITHUB_STEP_SUMMARY="$summary" \
    bash --noprofile --norc -eo pipefail "$temp/$n.sh") || status=$?
  if [ $status -ne 0 ]; then
    echo "classroom: step $n, $name, failed with exit status $status: the job ends here, as on the service" >&2
    exit $status
  fi
done
if [ $dry -eq 0 ]; then
  echo "classroom: all $n steps done; the job summary:"
  cat "$summary"
fi
