#!/usr/bin/env bash
# How strong are the graded tests? Applies each classic mistake of the mutation catalogue
# (tests/mutants/NN.txt) in turn to a scratch copy of the reference and runs that lesson's graded
# tests: every mutant must make at least one graded test fail ("caught").
#   bash scripts/mutants.sh [NN ...]         (default: every tests/mutants/NN.txt)
#   MUTANTS_DIR=DIR   scratch folder (default build/mutants; the copy and its build live there)
#   MUTANTS_JOBS=N    ctest/cmake parallelism (default 2)
#   MUTANTS_ONLY="ID ..."  run only these mutants (e.g. "02-h 02-k")
#   MUTANTS_FULL=1    run all of the lesson's graded tests for each mutant and list every one that
#                     fails (default: stop at the first failure, which is enough to catch it)
#   bash scripts/mutants.sh --check [NN ...]   only checks that every catalogue entry still
#                     applies (its original text found exactly once): no build, a second; the
#                     README test command runs it, so a change to solutions/ cannot leave a stale
#                     catalogue behind
# The repository is never modified: the mutants are applied to DIR/submission, a copy of
# solutions/, built as a submission (-DPATHSPACE_STUDENT=all -DPATHSPACE_ASSIGNMENTS_DIR=...),
# incrementally (one object file and the lesson's test program per mutant).
# Prints, per mutant: id, caught (yes/no), the graded tests that failed, the description; then a
# summary per lesson. Exit status 1 if a mutant survives, does not build, or its original text is
# not found exactly once (a stale catalogue).
#
# Catalogue format (one mutant per block, blank lines and '#' comments between blocks ignored):
#   @ ID FILE              FILE relative to solutions/, e.g. 03-path-tracing/roulette.cpp
#   : description          one line: the mistake, as a TA would name it
#   - original text        an exact substring of ONE line of FILE, found exactly once
#   + replacement text     what the mistaken student wrote instead
set -uo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
scratch="${MUTANTS_DIR:-$src/build/mutants}"
jobs="${MUTANTS_JOBS:-2}"
mkdir -p "$scratch"
scratch="$(cd "$scratch" && pwd)"
sub="$scratch/submission"
bld="$scratch/build"

check_only=0
if [ "${1:-}" = "--check" ]; then check_only=1; shift; fi
if [ $# -gt 0 ]; then lessons=("$@"); else
    lessons=()
    for f in "$src"/tests/mutants/[0-9][0-9].txt; do lessons+=("$(basename "$f" .txt)"); done
fi

# The submission: a copy of solutions/; only files whose content changed are copied again, so the
# scratch build stays incremental across runs.
sync_submission() {
    mkdir -p "$sub"
    (cd "$src/solutions" && find . -type f) | while read -r f; do
        mkdir -p "$sub/$(dirname "$f")"
        cmp -s "$src/solutions/$f" "$sub/$f" || cp "$src/solutions/$f" "$sub/$f"
    done
    (cd "$sub" && find . -type f) | while read -r f; do
        [ -e "$src/solutions/$f" ] || rm -f "$sub/$f"
    done
}

# replace FILE: replaces the one occurrence of $ORIG by $REPL (exit 3: not found, 4: ambiguous).
replace() {
    ORIG="$1" REPL="$2" awk '{ buf = buf $0 "\n" }
        END { o = ENVIRON["ORIG"]; r = ENVIRON["REPL"]; i = index(buf, o)
              if (!i) exit 3
              rest = substr(buf, i + length(o)); if (index(rest, o)) exit 4
              printf "%s%s%s", substr(buf, 1, i - 1), r, rest }' "$3" > "$3.mutant" || { local rc=$?; rm -f "$3.mutant"; return $rc; }
    mv "$3.mutant" "$3"
}

if [ $check_only = 1 ]; then
    stale=0; entries=0
    tmp="$(mktemp)"
    for NN in "${lessons[@]}"; do
        id=""; file=""; orig=""
        while IFS= read -r line || [ -n "$line" ]; do
            case "$line" in
                "@ "*) read -r _ id file <<< "$line"; orig="" ;;
                "- "*) orig="${line#- }" ;;
                "+ "* | "+") repl="${line#+}"; repl="${repl# }"; entries=$((entries + 1))
                    if [ ! -f "$src/solutions/$file" ]; then
                        echo "mutants: $NN.txt $id: no file solutions/$file" >&2; stale=$((stale + 1)); continue
                    fi
                    cp "$src/solutions/$file" "$tmp"
                    rc=0; replace "$orig" "$repl" "$tmp" || rc=$?
                    if [ $rc -eq 3 ]; then echo "mutants: $NN.txt $id: original text not found in solutions/$file" >&2; stale=$((stale + 1))
                    elif [ $rc -eq 4 ]; then echo "mutants: $NN.txt $id: original text found more than once in solutions/$file" >&2; stale=$((stale + 1))
                    elif cmp -s "$src/solutions/$file" "$tmp"; then echo "mutants: $NN.txt $id: the replacement changes nothing" >&2; stale=$((stale + 1))
                    fi ;;
            esac
        done < "$src/tests/mutants/$NN.txt"
    done
    rm -f "$tmp" "$tmp.mutant"
    if [ $stale -gt 0 ]; then echo "mutants: $stale of $entries catalogue entries are stale (fix tests/mutants/NN.txt)" >&2; exit 1; fi
    echo "mutants: all $entries catalogue entries apply to solutions/ (run without --check to grade them)"
    exit 0
fi

current=""   # the file of $sub currently mutated (restored on exit, even on Ctrl-C)
restore() { [ -n "$current" ] && cp "$src/solutions/$current" "$sub/$current"; current=""; }
trap 'restore; exit 130' INT TERM
trap 'restore' EXIT

sync_submission
if [ ! -f "$bld/CMakeCache.txt" ]; then
    echo "mutants: configuring the scratch build in $bld (once; the first build is a full build)"
    cmake -S "$src" -B "$bld" -DCMAKE_BUILD_TYPE=Release -DPATHSPACE_STUDENT=all \
        -DPATHSPACE_ASSIGNMENTS_DIR="$sub" > "$scratch/configure.log" 2>&1 ||
        { echo "mutants: configure failed, see $scratch/configure.log" >&2; exit 1; }
fi

stop="--stop-on-failure"
[ "${MUTANTS_FULL:-0}" = 1 ] && stop=""
status=0
summary=()
for NN in "${lessons[@]}"; do
    cat="$src/tests/mutants/$NN.txt"
    [ -f "$cat" ] || { echo "mutants: no catalogue $cat" >&2; status=1; continue; }
    target="lesson_${NN}_tests"
    # The unmutated reference must build and pass, or nothing below means anything.
    if ! cmake --build "$bld" -j"$jobs" --target "$target" > "$scratch/build-$NN.log" 2>&1; then
        echo "mutants: the reference lesson $NN does not build, see $scratch/build-$NN.log" >&2; status=1; continue
    fi
    if ! (cd "$bld" && ctest -L "lesson-$NN\$" -j"$jobs" --timeout 120 > "$scratch/reference-$NN.log" 2>&1); then
        echo "mutants: the reference fails lesson $NN's tests, see $scratch/reference-$NN.log" >&2; status=1; continue
    fi
    echo
    echo "lesson $NN ($(basename "$cat"))"
    printf '%-7s %-7s %-6s %s\n' "mutant" "caught" "tests" "mistake / the graded tests that failed"
    total=0; caught=0
    id=""; file=""; desc=""; orig=""
    run_one() {
        total=$((total + 1))
        local rc=0 result failed=""
        current="$file"
        replace "$orig" "$repl" "$sub/$file" || rc=$?
        if [ $rc -eq 3 ]; then result="STALE"; failed="original text not found in solutions/$file"
        elif [ $rc -eq 4 ]; then result="STALE"; failed="original text found more than once in solutions/$file"
        elif [ $rc -ne 0 ]; then result="ERROR"; failed="cannot edit $sub/$file"
        elif ! cmake --build "$bld" -j"$jobs" --target "$target" > "$scratch/mutant-$id.log" 2>&1; then
            result="NOBUILD"; failed="does not compile: $scratch/mutant-$id.log"
        else
            (cd "$bld" && ctest -L "lesson-$NN\$" -j"$jobs" --timeout 120 $stop > "$scratch/mutant-$id.log" 2>&1)
            failed=$(grep -v '(Not Run)$' "$scratch/mutant-$id.log" | sed -n '/tests FAILED:/,$ s/^[[:space:]]*[0-9]* - \(.*\) ([^()]*)$/\1/p' \
                | sed 's/ \[[0-9]* pts*\]$//' | paste -sd ';' -)
            if [ -n "$failed" ]; then result="yes"; caught=$((caught + 1)); else result="no"; fi
        fi
        restore
        [ "$result" = "yes" ] || status=1
        local nfailed=0
        [ "$result" = "yes" ] && nfailed=$(printf '%s\n' "$failed" | awk -F';' '{print NF}')
        printf '%-7s %-7s %-6s %s\n' "$id" "$result" "$nfailed" "$desc"
        printf '%23s%s\n' "" "$(printf '%s' "${failed:--}" | cut -c1-200)"
    }
    while IFS= read -r line || [ -n "$line" ]; do
        case "$line" in
            "@ "*) read -r _ id file <<< "$line"; desc=""; orig="" ;;
            ": "*) desc="${line#: }" ;;
            "- "*) orig="${line#- }" ;;
            "+ "* | "+") repl="${line#+}"; repl="${repl# }"
                         if [ -z "${MUTANTS_ONLY:-}" ] || [[ " $MUTANTS_ONLY " == *" $id "* ]]; then run_one; fi ;;
        esac
    done < "$cat"
    summary+=("$(printf 'lesson %s: %d mutants, %d caught' "$NN" "$total" "$caught")")
done
echo
printf '%s\n' "${summary[@]}"
[ $status -eq 0 ] && echo "mutants: every mutant caught" || echo "mutants: FAILED (a mutant survived, did not build or is stale)"
exit $status
