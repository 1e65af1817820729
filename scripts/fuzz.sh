#!/usr/bin/env bash
# Fuzzes every reader of outside input (scene files, OBJ/MTL, PFM, .hdr, and what the grader reads
# of a submission: the result channel, outputs, JUnit, objdump's text, objects) with libFuzzer
# under AddressSanitizer and UndefinedBehaviorSanitizer. Needs Clang (Debian: apt-get install clang).
#   bash scripts/fuzz.sh                 replay the corpus (fuzz/corpus/T: seeds and every crash
#                                        found so far), then fuzz each target for 10 s (CI does this)
#   bash scripts/fuzz.sh --seconds 600   fuzz each target for 10 minutes (a long run)
#   bash scripts/fuzz.sh --seconds 600 scene   one target
# New inputs that find new coverage are written to build-fuzz/corpus/T (not the repository);
# a crash is written as build-fuzz/crash-T-*: add it to fuzz/corpus/T once it is fixed, so it
# stays a regression test.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=10
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds="$2"; shift 2 ;;
    -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[ ${#targets[@]} -gt 0 ] || targets=(scene obj pfm hdr grade)
if ! command -v clang++ >/dev/null 2>&1; then
  echo "fuzz: clang++ not found: fuzzing skipped (Debian: apt-get install clang)" >&2
  exit 0
fi
build=build-fuzz
cmake -S . -B "$build" -DPATHSPACE_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j"$(nproc)" >/dev/null
for t in "${targets[@]}"; do
  corpus="fuzz/corpus/$t"
  work="$build/corpus/$t"
  mkdir -p "$work"
  # The checked-in corpus first, each input once: every crash found so far must stay fixed.
  "$build/fuzz/fuzz_$t" -runs=0 -timeout=10 -rss_limit_mb=2048 "$corpus" >"$build/replay-$t.log" 2>&1 || {
    echo "fuzz: $t: an input of $corpus fails again:" >&2; tail -30 "$build/replay-$t.log" >&2; exit 1; }
  # Then new inputs for a while.
  "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -artifact_prefix="$build/crash-$t-" "$work" "$corpus" >"$build/fuzz-$t.log" 2>&1 || {
    echo "fuzz: $t: found a failing input (see $build/crash-$t-*):" >&2; tail -40 "$build/fuzz-$t.log" >&2; exit 1; }
  runs=$(sed -n "s/^Done \([0-9]*\) runs.*/\1/p" "$build/fuzz-$t.log" | tail -1)
  echo "fuzz: $t: corpus of $(ls "$corpus" | wc -l) replayed, $seconds s of fuzzing (${runs} inputs): no failure"
done
