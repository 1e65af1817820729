#!/usr/bin/env bash
# False failures measured, not assumed: runs the REFERENCE's graded tests over N independent seeds
# (PATHSPACE_TEST_SEED=1..N shifts every test's base seed, tests/support/seed.h) and prints how
# often each test failed and the total. With the suite's significance levels (README, "How strong
# are the tests"), a false failure of the whole graded suite should come in fewer than 1 run in 100.
#   bash scripts/seeds.sh [N=20] [NN ...]      (default: every lesson)
#   SEEDS_BUILD=DIR   the configured and built reference build (default build/)
#   SEEDS_JOBS=J      ctest parallelism (default 2)
# Builds the lessons' test programs first. Exit status 1 if any run failed.
set -uo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
bld="$(cd "${SEEDS_BUILD:-$src/build}" && pwd)"
jobs="${SEEDS_JOBS:-2}"
n="${1:-20}"
[ $# -gt 0 ] && shift
if [ $# -gt 0 ]; then lessons=("$@"); else
    lessons=()
    for d in "$src"/tests/[0-9][0-9]-*/; do lessons+=("$(basename "$d" | cut -c1-2)"); done
fi
label="^lesson-($(IFS='|'; echo "${lessons[*]}"))\$"
targets=()
for NN in "${lessons[@]}"; do targets+=("lesson_${NN}_tests"); done
cmake --build "$bld" -j"$jobs" --target "${targets[@]}" > "$bld/seeds-build.log" 2>&1 ||
    { echo "seeds: build failed, see $bld/seeds-build.log" >&2; exit 1; }
count=$(cd "$bld" && ctest -N -L "$label" | sed -n 's/^Total Tests: //p')
log="$bld/seeds"
mkdir -p "$log"
failures="$log/failures.txt"
: > "$failures"
: > "$log/timeouts.txt"
runs_failed=0
echo "seeds: $count graded tests (lessons ${lessons[*]}) x $n seeds"
for ((s = 1; s <= n; ++s)); do
    start=$(date +%s)
    (cd "$bld" && PATHSPACE_TEST_SEED=$s ctest -L "$label" -j"$jobs" --timeout 300 > "$log/seed-$s.log" 2>&1)
    # A test that ran out of time (CTest's 120 s, on a loaded machine) has not failed a hypothesis:
    # it is run again alone, with the same seed, and judged by that run.
    for t in $(sed -n '/tests FAILED:/,$ s/^[[:space:]]*\([0-9]*\) - .* (Timeout)$/\1/p' "$log/seed-$s.log"); do
        if (cd "$bld" && PATHSPACE_TEST_SEED=$s ctest -I "$t,$t" > "$log/seed-$s-rerun-$t.log" 2>&1); then
            sed -i "/tests FAILED:/,\$ {/^[[:space:]]*$t - .* (Timeout)$/d}" "$log/seed-$s.log"
            echo "seed $s: test $t timed out under load, passed when run again alone" >> "$log/timeouts.txt"
        fi
    done
    failed=$(sed -n '/tests FAILED:/,$ s/^[[:space:]]*[0-9]* - \(.*\) ([^()]*)$/\1/p' "$log/seed-$s.log")
    if [ -n "$failed" ]; then
        runs_failed=$((runs_failed + 1))
        printf '%s\n' "$failed" | sed "s/^/seed $s: /" >> "$failures"
        echo "seed $s: $(printf '%s\n' "$failed" | wc -l) failed ($(( $(date +%s) - start )) s): $(printf '%s' "$failed" | paste -sd ';' -)"
    else
        echo "seed $s: all passed ($(( $(date +%s) - start )) s)"
    fi
done
echo
echo "failures per test over $n seeds:"
if [ -s "$failures" ]; then sed 's/^seed [0-9]*: //' "$failures" | sort | uniq -c | sort -rn; else echo "  none"; fi
total=$(wc -l < "$failures")
[ -s "$log/timeouts.txt" ] && { echo "timeouts (judged by a second run alone):"; cat "$log/timeouts.txt"; }
echo "total: $total failed tests in $((count * n)) test runs; $runs_failed of $n suite runs had a failure"
[ "$total" -eq 0 ]
