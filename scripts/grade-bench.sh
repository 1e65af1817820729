#!/usr/bin/env bash
# How long the autograder takes (README, "The autograder"): preparing the tree once, then grading
# all lessons of the reference (solutions/ as a submission: full marks) and of the untouched
# skeleton (assignments/: zero). Prints the figures; asserts nothing about time.
#   bash scripts/grade-bench.sh [BUILD_DIR] [--jobs N] [--no-sandbox]
# BUILD_DIR (default build) is a reference build: its grader/ tree is the one timed here
# ("prepare" = the incremental build of the tree target; a cold --prepare is a whole build).
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
build=build jobs=2 sandbox=()
while [ $# -gt 0 ]; do
  case "$1" in
    --jobs) jobs="$2"; shift 2 ;;
    --no-sandbox) sandbox=(--no-sandbox); shift ;;
    *) build="$1"; shift ;;
  esac
done
build="$(cd "$build" && pwd)"
out="$build/grade-bench"
rm -rf "$out"
# seconds LOG COMMAND...: runs COMMAND with its output to LOG, prints how many seconds it took.
seconds() {
  local log="$1" t0=$SECONDS
  shift
  "$@" >"$log" 2>&1 || true
  echo $((SECONDS - t0))
}

mkdir -p "$out"
t_prepare=$(seconds "$out/prepare.txt" cmake --build "$build" -j"$jobs" --target grader_tree grade)
score() { sed -n 's/^  "score": \([0-9]*\),$/\1/p;s/^  "extra_data": {"max_score": \([0-9]*\)},$/\1/p' "$1" | paste -sd/; }
t_ref=$(seconds "$out/reference.txt" "$build/grade" --tree "$build/grader" --submission "$src/solutions" \
  --jobs "$jobs" --out "$out/reference" "${sandbox[@]}")
t_skel=$(seconds "$out/skeleton.txt" "$build/grade" --tree "$build/grader" --submission "$src/assignments" \
  --jobs "$jobs" --out "$out/skeleton" "${sandbox[@]}")
echo "grade-bench: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg), --jobs $jobs${sandbox:+, --no-sandbox}"
echo "  prepare (incremental: grader_tree and grade targets)   ${t_prepare} s"
echo "  grade all lessons of the reference  (solutions/)       ${t_ref} s   score $(score "$out/reference/results.json")"
echo "  grade all lessons of the skeleton   (assignments/)     ${t_skel} s   score $(score "$out/skeleton/results.json")"
