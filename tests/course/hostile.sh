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
# attack NAME [STORED]: $work/NAME/00-rays with the skeleton's rays.cpp hooked (every PS_TODO
# calls hostileAttack() first: data/hostile/attack.h) and the files of STORED (default NAME).
attack() {
  local name="$1" stored="${2:-$1}" dir="$work/$1/00-rays"
  mkdir -p "$dir"
  { echo '#include "attack.h"'; sed 's/PS_TODO(/HOSTILE_PIECE(/g' "$src/assignments/00-rays/rays.cpp"; } >"$dir/rays.cpp"
  grep -q 'HOSTILE_PIECE(' "$dir/rays.cpp" || fail "$name: the skeleton's rays.cpp has no PS_TODO to hook"
  cp "$data/attack.h" "$data/$stored/00-rays/"* "$dir/"
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
# expect_test NAME TEST MESSAGE: the entry of the test whose name holds TEST scores 0 and says MESSAGE.
expect_test() {
  local entry
  entry="$(grep -F -- "$2" "$work/out-$1/results.json" | head -1)"
  [ -n "$entry" ] || { fail "$1: no test '$2' in results.json"; return; }
  case "$entry" in *'"score": 0,'*) ;; *) fail "$1: '$2' scored points" ;; esac
  case "$entry" in *"$3"*) ;; *) fail "$1: '$2' does not say '$3': ${entry:0:400}" ;; esac
}

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
# (b, c) Reads and writes where it must not; (d) a detached process rewriting results.json. They
# call what graded code may not (open, fork...): graded with --no-object-check, the sandbox
# and the process control alone must hold; snoop once more with the check, which refuses it.
submission snoop
submission snoop-checked snoop
submission daemon
submission daemon-nosandbox daemon
# (e) A build that never ends; (f, g) a test that hangs, one that crashes, one that exits early.
mkdir -p "$work/build-hang/00-rays" && cp "$data/build-hang/00-rays/rays.cpp" "$work/build-hang/00-rays/"
submission misbehave
# (h) The verdict attacked from the skeleton's pieces: printed summaries, _exit, abort, raw
# system calls, forged records on every descriptor, doctest's counters, a static constructor
# that hunts for the channel's token. With the object check (refused, each file by name) and
# without it (the result channel alone: every test 0).
attack cheats
attack cheats-unchecked cheats
# (i) Attacks that use only what graded code may call: forged records through stderr's FILE,
# the old grader's regex bomb, 1 GiB of output (next to the reference: it keeps its points).
attack fd-write
attack regex-bomb
submission one-gib
# Two gradings at a time (each --jobs 2: the tests are short).
names=(include-relative include-absolute symlink snoop snoop-checked daemon build-hang misbehave cheats
  cheats-unchecked fd-write regex-bomb one-gib)
for n in "${names[@]}"; do
  case "$n" in
    build-hang) run "$n" --build-timeout 5 & ;;
    snoop | daemon | misbehave | cheats-unchecked) run "$n" --no-object-check & ;;
    *) run "$n" & ;;
  esac
  [ "$(jobs -r | wc -l)" -ge 2 ] && wait -n
done
run daemon-nosandbox --no-sandbox --no-object-check &
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
expect_score snoop-checked 0
expect_in snoop-checked "snoop.cpp: uses 'open' (system calls and file descriptors), which graded code may not use"
expect_in snoop-checked "snoop.cpp: and 4 more"

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
expect_in misbehave "the test program ended before the test started (exit status 0)"

# The cheats, checked: nothing is built, every attack is named in the lesson's notes.
expect_score cheats 0
expect_in cheats "refused by the object check"
expect_in cheats "fake_summary.cpp: uses '_exit' (process control)"
expect_in cheats "abort.cpp: uses 'abort' (process control)"
expect_in cheats "syscall.cpp: holds a system-call instruction"
expect_in cheats "fd_write.cpp: uses 'write' (system calls and file descriptors)"
expect_in cheats "counters.cpp: uses 'doctest::is_running_in_test', part of the test framework"
expect_in cheats "constructor.cpp: uses 'recv' (system calls and file descriptors)"
# ... and unchecked: each attack runs, in its own test, and the channel gives it 0; all but one:
# doctest told through its own names to stop counting (counters.cpp) gets the test's 1 point,
# as doctest and its listeners see nothing fail. That is what the object check is for.
expect_score cheats-unchecked 1
u=cheats-unchecked
grep -F "round to 0 in float" "$work/out-$u/results.json" | grep -qF '"score": 1,' ||
  fail "$u: doctest's counting was not switched off"

expect_test $u "through the image centre" "the test program ended before the test finished (exit status 0)"
expect_test $u "corners of the image" "crashed: killed by signal 6 (Aborted)"
expect_test $u "midpoints of the image edges" "the test program ended before the test finished (exit status 42)"
expect_test $u "non-square images" "on the grader's result channel that the test harness did not send"
expect_test $u "are inverse" "the test program ended before the test started (exit status 0)"
grep -qF "Status: SUCCESS!" "$work/out-$u/logs/00-test-0.log" || fail "$u: the fake summary was not printed"

expect_score fd-write 0
expect_test fd-write "through the image centre" "on the grader's result channel that the test harness did not send"
expect_score regex-bomb 0
grep -qF "test cases:                    " "$work/out-regex-bomb/logs/00-test-0.log" || fail "regex-bomb: no bomb in the log"

# 1 GiB printed in one test: the test keeps its points, its log its cap (1 MiB and a line), all
# logs their budget (64 MiB).
expect_score one-gib "$full"
biggest=0 total=0
for f in "$work/out-one-gib/logs"/*.log; do
  s=$(stat -c %s "$f")
  total=$((total + s))
  [ "$s" -gt "$biggest" ] && biggest=$s
done
[ "$biggest" -le $((1048576 + 256)) ] || fail "one-gib: a log of $biggest bytes (cap: 1 MiB)"
[ "$total" -le $((64 * 1048576)) ] || fail "one-gib: $total bytes of logs (cap: 64 MiB)"
grep -qF "bytes of output left out here" "$work/out-one-gib/logs"/*.log || fail "one-gib: no log says what it left out"

# Every grading wrote reports a JSON reader takes, whatever was printed.
if command -v python3 >/dev/null 2>&1; then
  for n in "${names[@]}" honest daemon-nosandbox; do
    python3 -c 'import json, sys; json.load(open(sys.argv[1], encoding="utf-8"))' "$work/out-$n/results.json" ||
      fail "$n: results.json is not valid JSON"
  done
fi

# A signal to the grader: it stops, and its work folder and every process it started go with
# it. SIGTERM while a build runs, SIGINT while a test hangs.
# stop_with NAME SIGNAL WAIT_FOR OPTIONS...: grades NAME with its own TMPDIR, sends SIGNAL once
# the path WAIT_FOR (a glob; relative: in that TMPDIR) exists, and checks what is left.
stop_with() {
  local name="$1" sig="$2" ready="$3" tmp="$work/tmp-$1" pid i status left
  shift 3
  rm -rf "$tmp" && mkdir -p "$tmp"
  TMPDIR="$tmp" "$grade" --tree "$tree" --submission "$work/$name" --lessons 0 --out "$work/out-signal-$name" \
    --jobs 2 "$@" >"$work/signal-$name.txt" 2>&1 &
  pid=$!
  for ((i = 0; i < 600; ++i)); do
    [[ "$ready" == /* ]] || ready="$tmp/$ready"
    compgen -G "$ready" >/dev/null && break
    sleep 0.1
  done
  sleep 1
  kill -"$sig" $pid
  wait $pid
  status=$?
  [ $status -eq $((128 + $(kill -l "$sig"))) ] || fail "signal $sig: grade exited $status: $(tail -2 "$work/signal-$name.txt")"
  [ -z "$(ls -A "$tmp")" ] || fail "signal $sig: the work folder was left: $(ls "$tmp")"
  left=0
  for f in /proc/[0-9]*/cmdline; do
    { c="$(tr '\0' ' ' <"$f")"; } 2>/dev/null  # a process may end while it is read
    [[ "$c" == *"$tmp"* ]] && left=$((left + 1))
  done
  [ $left -eq 0 ] || fail "signal $sig: $left processes of the grading are still running"
  echo "hostile: signal $sig: grade stopped with status $status, work folder removed, no process left"
}
stop_with build-hang TERM "pathspace-grade-*/00/build" --build-timeout 120
stop_with misbehave INT "$work/out-signal-misbehave/logs/00-test-*.log" --timeout 120 --no-object-check

if [ $failures -gt 0 ]; then
  echo "hostile: $failures checks failed (grader output: $work/*.txt, results: $work/out-*/)"
  exit 1
fi
echo "hostile: every hostile submission got what it deserves"
