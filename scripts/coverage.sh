#!/usr/bin/env bash
# Reach of the graded tests: which lines of the reference's solution regions (//! BEGIN ... //! END
# in solutions/NN-name/*.cpp, what a student writes) does each lesson's OWN graded tests never
# execute? A line that no graded test runs can be wrong for full marks.
#   bash scripts/coverage.sh [NN ...]     (default: every lesson with graded tests)
#   COVERAGE_DIR=DIR   the coverage build (default build-coverage/, kept: the next run is incremental)
#   COVERAGE_JOBS=N    build and ctest parallelism (default: nproc)
# Builds the lessons' test programs in Release with the solution files alone at -O0 with gcov's
# counters (the launcher below), then per lesson: clears the counters, runs `ctest -L ^lesson-NN$`
# (that lesson's graded tests alone; other lessons' code runs too but is not counted for it), and
# reads the counters with gcovr (Debian's gcovr; scripts/deps.sh gcovr installs it). A line is
# reached when it was executed and every condition on it went both ways (gcov's branch outcomes,
# without the exception paths of calls). Prints one table row per lesson (lines executed,
# condition outcomes taken, lines excepted) and every line not reached, with its file and number;
# writes the same to DIR/coverage.md.
# tests/coverage-exceptions.txt lists the lines that may stay unreached, each with its reason (a
# guard that cannot trigger); format there. Exit status 1 if a region line is not reached and not
# excepted, if an exception is stale (its line is reached now, or not found exactly once), or if a
# graded test fails in the coverage build.
set -uo pipefail
# The compiler launcher of the coverage build (CMAKE_CXX_COMPILER_LAUNCHER, below): a solution file
# (solutions/NN-name/*.cpp) compiles at -O0 with gcov's counters, everything else as in Release
# (-O3): the counted lines stay the source's lines (no inlining or merging), the rest runs at speed;
# -fprofile-abs-path: the counters name the source by its absolute path whatever folder compiled it.
if [ "${1:-}" = "--compile" ]; then
    shift
    extra=()
    for a in "$@"; do
        case "$a" in */solutions/[0-9][0-9]-*/*.cpp) extra=(-O0 --coverage -fprofile-abs-path) ;; esac
    done
    # A solution file without ccache: its cache keys relative paths (CCACHE_BASEDIR), which gcov
    # cannot resolve from the folder that compiled lessons 0 and 1 (framework/).
    [ ${#extra[@]} -gt 0 ] && exec "$@" "${extra[@]}"
    if command -v ccache >/dev/null 2>&1; then exec ccache "$@"; else exec "$@"; fi
fi
src="$(cd "$(dirname "$0")/.." && pwd)"
bld="${COVERAGE_DIR:-$src/build-coverage}"
jobs="${COVERAGE_JOBS:-$(nproc)}"
t0=$SECONDS

# gcovr (Debian's package) reads gcov's counters; scripts/deps.sh installs it with the rest.
{ bash "$src/scripts/deps.sh" && bash "$src/scripts/deps.sh" gcovr; } || exit 1

if [ $# -gt 0 ]; then lessons=("$@"); else
    lessons=()
    for d in "$src"/tests/[0-9][0-9]-*/; do lessons+=("$(basename "$d" | cut -c1-2)"); done
fi

# The build: its own folder, Release, the solution files at -O0 with counters (the launcher above),
# linked with libgcov; every test's time limit raised (the solutions run slower unoptimised).
export CCACHE_BASEDIR="$src"
cmake -S "$src" -B "$bld" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_COMPILER_LAUNCHER="bash;$src/scripts/coverage.sh;--compile" \
    -DCMAKE_EXE_LINKER_FLAGS=--coverage -DCMAKE_SHARED_LINKER_FLAGS=--coverage \
    -DPATHSPACE_TEST_TIMEOUT=900 >/dev/null || exit 1
targets=()
for NN in "${lessons[@]}"; do targets+=(--target "lesson_${NN}_tests"); done
cmake --build "$bld" -j"$jobs" "${targets[@]}" >"$bld/build.log" 2>&1 || {
    tail -30 "$bld/build.log" >&2
    echo "coverage: the build failed ($bld/build.log)" >&2
    exit 1
}
tbuild=$((SECONDS - t0))

status=0
mkdir -p "$bld/coverage"
rm -f "$bld"/coverage/*.json
for NN in "${lessons[@]}"; do
    dir=$(cd "$src/solutions" && ls -d "$NN"-*/ 2>/dev/null | head -1)
    [ -n "$dir" ] || { echo "coverage: no solutions/$NN-*" >&2; status=1; continue; }
    dir="${dir%/}"
    find "$bld" -name '*.gcda' -delete
    t1=$SECONDS
    (cd "$bld" && ctest -L "^lesson-$NN\$" -j"$jobs" --output-on-failure >"$bld/coverage/ctest-$NN.log" 2>&1) || {
        echo "coverage: lesson $NN: a graded test failed in the coverage build ($bld/coverage/ctest-$NN.log)" >&2
        grep -E '^\s*[0-9]+ - ' "$bld/coverage/ctest-$NN.log" >&2
        status=1
    }
    gcovr -r "$src" --object-directory "$bld" --filter "$src/solutions/$dir/" --json \
        -o "$bld/coverage/$NN.json" "$bld" >"$bld/coverage/gcovr-$NN.log" 2>&1 || {
        echo "coverage: gcovr failed for lesson $NN ($bld/coverage/gcovr-$NN.log)" >&2
        status=1
    }
    echo "coverage: lesson $NN: tests and gcovr $((SECONDS - t1)) s" >&2
done

# The report: solution-region lines that gcov counts as executable, against the exceptions.
python3 - "$src" "$bld/coverage" "$src/tests/coverage-exceptions.txt" "${lessons[@]}" >"$bld/coverage.md" <<'EOF'
import json, os, re, sys
src, out, exfile, lessons = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
bad = 0
# Exceptions: "FILE | text | reason" (FILE relative to solutions/; text: the line, stripped).
exceptions = []
for n, line in enumerate(open(exfile, encoding="utf-8") if os.path.exists(exfile) else [], 1):
    if not line.strip() or line.lstrip().startswith("#"):
        continue
    parts = [p.strip() for p in line.rstrip("\n").split(" | ")]
    parts = [parts[0], " | ".join(parts[1:-1]), parts[-1]] if len(parts) >= 3 else parts
    if len(parts) != 3 or not all(parts):
        print(f"coverage: {exfile}:{n}: not 'FILE | line text | reason'", file=sys.stderr)
        bad = 1
        continue
    exceptions.append({"file": parts[0], "text": parts[1], "reason": parts[2], "where": n, "used": False})

def md(text):
    return text.replace("|", "\\|")

def regions(path):
    """Line numbers (1-based) inside //! BEGIN ... //! END, with their text."""
    inside, lines = False, {}
    for i, text in enumerate(open(path, encoding="utf-8"), 1):
        s = text.strip()
        if s.startswith("//! BEGIN"):
            inside = True
        elif s.startswith("//! END"):
            inside = False
        elif inside:
            lines[i] = s
    return lines

rows, details = [], []
for NN in lessons:
    d = [x for x in sorted(os.listdir(os.path.join(src, "solutions"))) if x.startswith(NN + "-")]
    if not d:
        continue
    d = d[0]
    counts = {}
    jpath = os.path.join(out, NN + ".json")
    if os.path.exists(jpath):
        for f in json.load(open(jpath))["files"]:
            rel = os.path.relpath(os.path.join(src, f["file"]), os.path.join(src, "solutions"))
            for l in f["lines"]:
                if l.get("gcovr/noncode"):
                    continue
                # A line's count and its branch outcomes (an exception's path through a call is
                # not a condition of the source: left out).
                c = counts.setdefault(rel, {})
                n, br = c.get(l["line_number"], (0, []))
                c[l["line_number"]] = (n + l["count"], br + [b["count"] for b in l.get("branches", [])
                                                               if not b.get("throw")])
    lines = executed = outcomes = taken = 0
    excepted = []
    for name in sorted(os.listdir(os.path.join(src, "solutions", d))):
        if not name.endswith(".cpp"):
            continue
        rel = d + "/" + name
        reg = regions(os.path.join(src, "solutions", rel))
        c = counts.get(rel)
        if reg and c is None:
            print(f"coverage: {rel}: no counters (not built into lesson {NN}'s tests?)", file=sys.stderr)
            bad = 1
            continue
        for ln, text in sorted(reg.items()):
            if ln not in c:
                continue  # gcov: not executable (a brace, a comment, a declaration)
            count, branches = c[ln]
            lines += 1
            executed += count > 0
            outcomes += len(branches)
            taken += sum(1 for b in branches if b > 0)
            what = []
            if count == 0:
                what.append("never executed")
            elif any(b == 0 for b in branches):
                what.append(f"a condition never went one way ({', '.join(str(b) for b in branches)} times)")
            if not what:
                continue
            ex = [e for e in exceptions if e["file"] == rel and e["text"] == text]
            if len(ex) == 1 and list(reg.values()).count(text) == 1:
                ex[0]["used"] = True
                excepted.append(ln)
                details.append(f"| {NN} | `{rel}:{ln}` | `{md(text)}` | {what[0]}; excepted: {ex[0]['reason']} |")
            else:
                bad = 1
                details.append(f"| {NN} | `{rel}:{ln}` | `{md(text)}` | **{what[0]}** |")
    rows.append(f"| {NN} | {executed} / {lines} | {taken} / {outcomes} | {len(excepted)} |")
for e in exceptions:
    if not e["used"] and any(e["file"].startswith(NN + "-") for NN in lessons):
        print(f"coverage: {exfile}:{e['where']}: stale exception (the line is executed, or not found "
              f"exactly once in a solution region): {e['file']} | {e['text']}", file=sys.stderr)
        bad = 1
print("| lesson | solution-region lines executed | condition outcomes taken | lines excepted |")
print("|---|---|---|---|")
print("\n".join(rows))
if details:
    print()
    print("| lesson | line | text | |")
    print("|---|---|---|---|")
    print("\n".join(details))
sys.exit(bad)
EOF
[ $? -eq 0 ] || status=1
cat "$bld/coverage.md"
echo "coverage: build $tbuild s, tests and report $((SECONDS - t0 - tbuild)) s, total $((SECONDS - t0)) s ($bld/coverage.md)"
exit $status
