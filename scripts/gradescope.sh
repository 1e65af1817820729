#!/usr/bin/env bash
# The Gradescope autograder package (README, "Gradescope and GitHub Classroom"): one zip to upload
# as a programming assignment's autograder. At its root: setup.sh and run_autograder
# (tools/gradescope/), config.sh (the options below) and pathspace/ (this repository's files,
# solutions/ included: setup.sh builds the prepared tree from them, then deletes them).
#   bash scripts/gradescope.sh [--lessons all|3|3,5] [--timeout S] [--build-timeout S] [--sandbox auto|yes|no] [--out FILE]
# --lessons: what one Gradescope assignment grades (default all: every lesson in the upload).
# --timeout, --build-timeout: the grader's limits per test and per lesson build (120, 300 s).
# --sandbox: auto (the default) grades in bubblewrap where the container lets it make namespaces
# and otherwise without it, saying so in the output; yes refuses to grade without it; no never uses
# it (the README says what grading without it gives up). --no-sandbox is --sandbox no. --out: the zip (default build/gradescope-autograder.zip, or
# build/gradescope-lesson-NN.zip for one lesson). Zipped with zip, else python3's zipfile, else
# cmake -E tar.
set -euo pipefail
src="$(cd "$(dirname "$0")/.." && pwd)"
lessons=all timeout=120 build_timeout=300 sandbox=auto out=""
usage() { echo "gradescope: $1 (see the top of scripts/gradescope.sh)" >&2; exit 2; }
while [ $# -gt 0 ]; do
  [ $# -ge 2 ] || [ "$1" = --no-sandbox ] || usage "$1 needs a value"
  case "$1" in
    --lessons) lessons="$2"; shift 2 ;;
    --timeout) timeout="$2"; shift 2 ;;
    --build-timeout) build_timeout="$2"; shift 2 ;;
    --sandbox) sandbox="$2"; shift 2 ;;
    --no-sandbox) sandbox=no; shift ;;
    --out) out="$2"; shift 2 ;;
    *) usage "unknown option $1" ;;
  esac
done
[[ "$lessons" =~ ^(all|[0-9]{1,2}(,[0-9]{1,2})*)$ ]] || usage "--lessons takes all or lesson numbers such as 3,5, got '$lessons'"
[[ "$sandbox" =~ ^(auto|yes|no)$ ]] || usage "--sandbox takes auto, yes or no, got '$sandbox'"
[[ "$timeout" =~ ^[1-9][0-9]*$ ]] || usage "--timeout takes a whole number of seconds, got '$timeout'"
[[ "$build_timeout" =~ ^[1-9][0-9]*$ ]] || usage "--build-timeout takes a whole number of seconds, got '$build_timeout'"
# Lesson numbers without leading zeros (run_autograder compares them so).
[ "$lessons" = all ] || lessons="$(echo "$lessons" | tr ',' '\n' | while read -r n; do echo $((10#$n)); done | paste -sd,)"
if [ -z "$out" ]; then
  name=autograder
  [[ "$lessons" =~ ^[0-9]+$ ]] && name="lesson-$(printf '%02d' "$lessons")"
  mkdir -p "$src/build"
  out="$src/build/gradescope-$name.zip"
fi
mkdir -p "$(dirname "$out")"
out="$(cd "$(dirname "$out")" && pwd)/$(basename "$out")"

stage="$(mktemp -d "${TMPDIR:-/tmp}/pathspace-gradescope-XXXXXX")"
trap 'rm -rf "$stage"' EXIT
cp "$src/tools/gradescope/setup.sh" "$src/tools/gradescope/run_autograder" "$stage/"
chmod 755 "$stage/setup.sh" "$stage/run_autograder"
cat >"$stage/config.sh" <<CONFIG
# Written by scripts/gradescope.sh; read by run_autograder.
LESSONS=$lessons
TIMEOUT=$timeout
BUILD_TIMEOUT=$build_timeout
SANDBOX=$sandbox
CONFIG
mkdir "$stage/pathspace"
(cd "$src" && git ls-files -z --cached --others --exclude-standard | grep -zv '^\.ci/' |
  xargs -0 cp --parents -t "$stage/pathspace/")

rm -f "$out"
files=(setup.sh run_autograder config.sh pathspace)
# The first of zip, python3, cmake there is (PATHSPACE_ZIPPER names one, to test the others).
zipper="${PATHSPACE_ZIPPER:-}"
if [ -z "$zipper" ]; then
  for z in zip python3 cmake; do command -v "$z" >/dev/null 2>&1 && { zipper=$z; break; }; done
fi
case "$zipper" in
  zip) (cd "$stage" && zip -qrX "$out" "${files[@]}") ;;
  python3) (cd "$stage" && python3 -m zipfile -c "$out" "${files[@]}") ;;
  cmake) (cd "$stage" && cmake -E tar cf "$out" --format=zip "${files[@]}") ;;
  *) echo "gradescope: no way to make a zip (zip, python3 or cmake)" >&2; exit 1 ;;
esac
echo "gradescope: wrote $out ($(du -h "$out" | cut -f1), by $zipper; lessons: $lessons, sandbox: $sandbox)"
