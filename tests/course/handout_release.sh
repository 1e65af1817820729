#!/usr/bin/env bash
# The lecturer's release step (scripts/handout.sh --release) and what the handout's build makes of
# it (cmake/lessons.cmake): the released lessons' reference pieces are in released/NN-name/, byte
# for byte those of solutions/, and no other lesson's; the handout's configure builds the released
# lessons from them and every other lesson from assignments/, and -DPATHSPACE_STUDENT=N takes a
# released lesson back from the student's files; an earlier handout under git is refreshed in
# place (its .git kept), and a bad --release is refused before anything is written.
#   bash tests/course/handout_release.sh SRC WORK
set -uo pipefail
src="$1" work="$2"
rm -rf "$work" && mkdir -p "$work"
failures=0
fail() { echo "handout_release: FAIL: $*"; failures=$((failures + 1)); }
h="$work/handout"
bash "$src/scripts/handout.sh" --release 0-1,3 "$h" >"$work/handout.log" 2>&1 || { cat "$work/handout.log"; exit 1; }
[ -e "$h/solutions" ] && fail "the handout has solutions/"
for l in "$src"/solutions/*/; do
  name=$(basename "$l")
  case "$name" in
    00-*|01-*|03-*)
      diff -r "$l" "$h/released/$name" >/dev/null || fail "released/$name differs from solutions/$name" ;;
    *) [ -e "$h/released/$name" ] && fail "released/$name is there, but lesson $name was not released" ;;
  esac
done
grep -q '03-path-tracing' "$h/released/README.md" || fail "released/README.md does not list 03-path-tracing"
# What the handout's build takes from where (configure only).
cmake -S "$h" -B "$work/build" >"$work/configure.log" 2>&1 || { fail "the handout does not configure"; tail "$work/configure.log"; }
grep -q "lesson 03-path-tracing: released reference" "$work/configure.log" || fail "lesson 3 is not built from released/"
grep -q "lesson 02-direct-mis: student, no reference here" "$work/configure.log" || fail "lesson 2 is not the student's"
cmake -S "$h" -B "$work/build" -DPATHSPACE_STUDENT=3 >"$work/configure-3.log" 2>&1
grep -q "lesson 03-path-tracing: student (" "$work/configure-3.log" || fail "-DPATHSPACE_STUDENT=3 does not build lesson 3 from assignments/"
grep -q "lesson 01-monte-carlo: released reference" "$work/configure-3.log" || fail "-DPATHSPACE_STUDENT=3 does not keep lesson 1 released"
# An earlier handout under git is refreshed in place; anything else non-empty is refused.
(cd "$h" && git init -q && git add -A && git -c user.email=ci@example.org -c user.name=ci commit -qm v1) ||
  fail "git init of the handout"
bash "$src/scripts/handout.sh" --release 0-4 "$h" >"$work/refresh.log" 2>&1 || fail "refreshing the handout: $(tail -1 "$work/refresh.log")"
[ -d "$h/.git" ] && [ -d "$h/released/04-measurement" ] || fail "the refreshed handout lost .git or lacks released/04-measurement"
[ -n "$(git -C "$h" status --porcelain)" ] || fail "the refresh changed nothing git sees"
mkdir -p "$work/other" && touch "$work/other/file"
bash "$src/scripts/handout.sh" "$work/other" >/dev/null 2>&1 && fail "a non-empty folder that is no handout was not refused"
bash "$src/scripts/handout.sh" --release 5-2 "$work/bad" >/dev/null 2>&1
[ $? -eq 2 ] || fail "--release 5-2 is not a usage error"
bash "$src/scripts/handout.sh" --release 99 "$work/bad" >/dev/null 2>&1
[ $? -eq 2 ] || fail "--release 99 is not a usage error"
[ -e "$work/bad" ] && fail "a refused --release wrote $work/bad"
[ "$failures" -eq 0 ] && echo "handout_release: released lessons in place, built from released/, refresh and refusals as documented"
exit $((failures > 0))
