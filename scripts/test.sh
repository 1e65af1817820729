#!/usr/bin/env bash
# The second README command: install what is missing, build (Release), run every test.
set -euo pipefail
cd "$(dirname "$0")/.."
# Each phase's wall time, printed at the end: CI must stay under 10 minutes on 2 cores.
phases="" t0=$SECONDS
phase() { phases+="$(printf '  %-34s %4d s' "$1" $((SECONDS - t0)))"$'\n'; t0=$SECONDS; }
bash scripts/deps.sh
# Fast checks first (seconds): the mutation catalogues still apply to solutions/, the code is
# formatted as .clang-format says (clang-format 14, Debian 12's; skipped with a note without it),
# and the include graph keeps the layering: no lesson includes a later one, framework/, app/ and
# report/ include no lesson (scripts/check-includes.sh).
bash scripts/mutants.sh --check
bash scripts/check-format.sh
bash scripts/check-includes.sh
phase "packages, mutants --check, format, includes"
# ccache (scripts/deps.sh installs it) lets the handout build below reuse this build's objects:
# the framework and the tests compile the same in both trees. Without it, both compile in full.
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$PWD"  # paths relative to the tree: the handout's compile lines match
fi
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
cmake --build build -j"$(nproc)"
phase "build (Release)"
cd build
ctest -j"$(nproc)" --output-on-failure --timeout 300 --output-junit "$PWD/ctest.xml"
# The autograder's scoring, on this run: the reference must get full marks.
./grade --junit "$PWD/ctest.xml" --expect full --out grade-reference > grade-reference.txt
phase "ctest (every test), reference graded"
cd ..
# What CI must prove about the course: the handout holds no solution line and builds, and
# every graded test fails on the untouched skeleton.
bash scripts/check-skeleton.sh build
phase "handout: build, skeleton tests"
# Every reader of outside input under libFuzzer with ASan/UBSan: the corpus of past failures
# replayed, then a few seconds of new inputs per reader (skipped, with a note, without clang++).
bash scripts/fuzz.sh --seconds 2
phase "fuzzers: build, corpus, 2 s each"
echo "test.sh: wall time per phase (CI's limit: 600 s in all)"
printf '%s' "$phases"
echo "  total                              $SECONDS s"
