#!/usr/bin/env bash
# The grader against hostile submissions of lesson 0 (tests/course/data/hostile/README.md): each
# gets what it deserves, and the reference, through the same path, full marks.
#   bash tests/course/hostile.sh GRADE TREE SOURCE WORK
# Exit 77 (CTest: skipped) when there is no working sandbox (bubblewrap), saying so.
set -uo pipefail
grade="$1" tree="$2" src="$3" work="$4"
data="$src/tests/course/data/hostile"
rm -rf "$work" && mkdir -p "$work"
failures=0
fail() { echo "hostile: FAIL: $*"; failures=$((failures + 1)); }

# submission NAME [STORED]: $work/NAME/00-rays with the reference rays.cpp, the files of the
# stored submission STORED (default NAME) and paths.h saying where everything is.
submission() {
  local name="$1" stored="${2:-$1}" dir="$work/$1/00-rays"
  mkdir -p "$dir"
  cp "$src/solutions/00-rays/rays.cpp" "$dir/"
  [ -d "$data/$stored/00-rays" ] && cp "$data/$stored/00-rays/"* "$dir/"
  cat >"$dir/paths.h" <<PATHS
#define HOSTILE_SOURCE "$src"
#define HOSTILE_TREE "$tree"
#define HOSTILE_OUT "$work/out-$name"
#define HOSTILE_OTHER_SUBMISSION "$work/honest/00-rays/rays.cpp"
PATHS
}
# run NAME [OPTIONS...]: grades submission NAME into $work/out-NAME (lesson 0, short limits).
run() {
  local name="$1"
  shift
  "$grade" --tree "$tree" --submission "$work/$name" --lessons 0 --out "$work/out-$name" \
    --timeout 10 --build-timeout 120 --jobs 2 "$@" >"$work/$name.txt" 2>&1
}
score() { sed -n 's/^  "score": \([0-9]*\),$/\1/p' "$work/out-$1/results.json"; }
max() { sed -n 's/^  "extra_data": {"max_score": \([0-9]*\)},$/\1/p' "$work/out-$1/results.json"; }
expect_score() {
  local got
  got="$(score "$1")"
  [ "$got" = "$2" ] && echo "hostile: $1: $got / $(max "$1"), as it deserves" || fail "$1: score '$got', expected $2"
}
expect_in() { grep -qF -- "$2" "$work/out-$1/results.json" || fail "$1: results.json does not say '$2'"; }

# The reference, through the same path: full marks. Also tells whether there is a sandbox.
submission honest
run honest
status=$?
if [ $status -eq 3 ]; then
  echo "hostile: SKIP: the grader has no working sandbox here:"
  sed 's/^/  /' "$work/honest.txt"
  exit 77
fi
[ $status -eq 0 ] || fail "honest: grade exited $status: $(tail -3 "$work/honest.txt")"
full="$(max honest)"
expect_score honest "$full"

# (a) Solution source by relative path, absolute path, symbolic link: nothing to compile with.
mkdir -p "$work/include-relative/00-rays" "$work/include-absolute/00-rays" "$work/symlink/00-rays"
cp "$data/include-relative/00-rays/rays.cpp" "$work/include-relative/00-rays/"
printf '#include "%s/solutions/00-rays/rays.cpp"\n' "$src" >"$work/include-absolute/00-rays/rays.cpp"
ln -s "$src/solutions/00-rays/rays.cpp" "$work/symlink/00-rays/rays.cpp"
# (b, c) Reads and writes where it must not; (d) a detached process rewriting results.json.
submission snoop
submission daemon
submission daemon-nosandbox daemon
# (e) A build that never ends; (f, g) a test that hangs, one that crashes, one that exits early.
mkdir -p "$work/build-hang/00-rays" && cp "$data/build-hang/00-rays/rays.cpp" "$work/build-hang/00-rays/"
submission misbehave
# Two gradings at a time (each --jobs 2: the tests are short).
names=(include-relative include-absolute symlink snoop daemon build-hang misbehave)
for n in "${names[@]}"; do
  if [ "$n" = build-hang ]; then run "$n" --build-timeout 5 & else run "$n" & fi
  [ "$(jobs -r | wc -l)" -ge 2 ] && wait -n
done
run daemon-nosandbox --no-sandbox &
wait
sleep 2  # a daemon that outlived its step would rewrite results.json every 0.1 s

for n in include-relative include-absolute symlink; do
  expect_score "$n" 0
done
expect_in include-relative "the lesson did not build"
expect_in include-absolute "the lesson did not build"
expect_in symlink "left out rays.cpp: a symbolic link"

expect_score snoop "$full"
logs="$work/out-snoop/logs"
while read -r l; do fail "snoop: $l"; done < <(grep -h "snoop: \(READ\|WROTE\|CONNECTED\)" "$logs"/*.log | sort -u)
[ "$(grep -h "snoop: refused" "$logs/00-test-0.log" | sort -u | wc -l)" -eq 11 ] || fail "snoop: its probes did not all run"
[ ! -e "$src/HOSTILE-WAS-HERE" ] || fail "snoop: wrote into the source tree"
[ ! -e "$work/out-snoop/HOSTILE-WAS-HERE" ] || fail "snoop: wrote into OUT"
grep -q hostile "$tree/include/framework/camera.h" "$tree/data/scenes/cornell-box.scene" && fail "snoop: wrote into the tree"

for n in daemon daemon-nosandbox; do
  expect_score "$n" "$full"
  grep -q '"score": 999' "$work/out-$n/results.json" && fail "$n: a detached process rewrote results.json"
done

expect_score build-hang 0
expect_in build-hang "the build timed out after 5 s"

misbehave_full=$((full - 4))  # the fan (2 pts), behind the origin (1), the open segment (1)
expect_score misbehave "$misbehave_full"
expect_in misbehave "timed out after 10 s"
expect_in misbehave "crashed: killed by signal 11 (Segmentation fault)"
expect_in misbehave "exited 0 without doctest's summary"

if [ $failures -gt 0 ]; then
  echo "hostile: $failures checks failed (grader output: $work/*.txt, results: $work/out-*/)"
  exit 1
fi
echo "hostile: every hostile submission got what it deserves"
