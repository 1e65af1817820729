#!/usr/bin/env bash
# Writes the student handout into DIR: every tracked file except solutions/ and CI files, with the
# student's README and the GitHub Classroom / Actions workflow (tools/handout/).
# The handout builds every lesson from assignments/, except the lessons released with --release.
#   bash scripts/handout.sh DIR                    # a new handout (DIR new or empty)
#   bash scripts/handout.sh --release 0-7 DIR      # ... with the reference of lessons 0 to 7
#   bash scripts/handout.sh --release 0-7,9 DIR    # lists and ranges
# --release LESSONS puts the reference pieces of those lessons (the lecturer's solutions/NN-name/,
# after their deadline) into DIR/released/NN-name/: the handout's build takes a released lesson
# from there unless the student asks for their own (-DPATHSPACE_STUDENT), so a later lesson builds,
# runs and scores with the same earlier lessons as the grader's (README, "Releases").
# DIR may also be an earlier handout under git (the course's handout repository, which students
# pull from as their "upstream" remote): its files are replaced by the new handout's and its .git
# is kept, so that `git -C DIR add -A && git -C DIR commit` records exactly what changed.
set -euo pipefail
usage() { echo "usage: bash scripts/handout.sh [--release LESSONS] DIR   (LESSONS: e.g. 0-7 or 0,1,3-5)" >&2; exit 2; }
release=""
while [ $# -gt 1 ]; do
  case "$1" in
    --release) release="$2"; shift 2 ;;
    *) usage ;;
  esac
done
[ $# -eq 1 ] && [ "${1:0:1}" != "-" ] || usage
src="$(cd "$(dirname "$0")/.." && pwd)"
dest="$1"
# The released lessons: "0-7,9" -> the lesson folders 00-rays ... 07-bidirectional 09-metropolis.
released=()
if [ -n "$release" ]; then
  IFS=',' read -r -a parts <<<"$release"
  for part in "${parts[@]}"; do
    case "$part" in
      [0-9]|[0-9][0-9]) lo=$((10#$part)) hi=$((10#$part)) ;;
      [0-9]-[0-9]|[0-9]-[0-9][0-9]|[0-9][0-9]-[0-9][0-9]) lo=$((10#${part%-*})) hi=$((10#${part#*-})) ;;
      *) echo "handout: --release '$release': '$part' is not a lesson number or a range like 0-7" >&2; exit 2 ;;
    esac
    [ "$lo" -le "$hi" ] || { echo "handout: --release '$release': the range '$part' is empty" >&2; exit 2; }
    for ((n = lo; n <= hi; n++)); do
      dir=$(cd "$src/solutions" && ls -d "$(printf '%02d' "$n")"-*/ 2>/dev/null | head -1)
      [ -n "$dir" ] || { echo "handout: --release '$release': there is no lesson $n (solutions/$(printf '%02d' "$n")-*)" >&2; exit 2; }
      released+=("${dir%/}")
    done
  done
fi
if [ -e "$dest" ] && [ -n "$(ls -A "$dest" 2>/dev/null)" ]; then
  # An earlier handout under git: replace its files, keep its history.
  if [ -d "$dest/.git" ] && [ -d "$dest/assignments" ] && [ -f "$dest/scripts/score.sh" ] && [ ! -e "$dest/solutions" ]; then
    echo "handout: $dest is an earlier handout under git: replacing its files (its .git stays)"
    find "$dest" -mindepth 1 -maxdepth 1 ! -name .git -exec rm -rf {} +
  else
    echo "handout: $dest exists and is not empty (nor an earlier handout under git); give a new directory" >&2
    exit 1
  fi
fi
mkdir -p "$dest"
cd "$src"
git ls-files -z --cached --others --exclude-standard |
  grep -zv -E '^(solutions/|\.ci/|tests/course/|scripts/handout\.sh|scripts/check-skeleton\.sh|scripts/grade-bench\.sh|scripts/gradescope\.sh|scripts/classroom\.sh|tools/gradescope/|tools/grade/(main|lesson|process|sandbox)|tools/photon_figures\.cpp|cmake/grader)' |
  xargs -0 -I{} cp --parents {} "$dest"/
# (tools/photon_figures.cpp draws lesson 8's figures with the reference's gather: lecturer only,
# like every tool whose target the handout's tools/CMakeLists.txt leaves out below.)
# The grader needs the reference; the handout has none.
sed -i '/^# grade: the autograder/,$d' "$dest/tools/CMakeLists.txt"
# The student's README (tools/handout/README.md) instead of the lecturer's, with the lessons
# table of the lecturer's README (one source for both).
lessons=$(sed -n '/^## Lessons$/,/^## [^L]/p' README.md | sed -n '/^| [0-9]/p')
awk -v table="$lessons" '$0 == "@LESSONS@" { print table; next } { print }' tools/handout/README.md > "$dest/README.md"
# The workflow GitHub Classroom / Actions runs in every student repository made from the handout.
mkdir -p "$dest/.github/workflows"
cp tools/handout/.github/workflows/classroom.yml "$dest/.github/workflows/"
rm -rf "$dest/tools/handout"
# The released lessons' reference pieces (solutions/NN-name/, regions marked as in the lecturer's
# tree): the handout's build uses them for those lessons (cmake/lessons.cmake).
if [ ${#released[@]} -gt 0 ]; then
  mkdir -p "$dest/released"
  for l in "${released[@]}"; do
    mkdir -p "$dest/released/$l"
    (cd "solutions/$l" && git ls-files -z . | xargs -0 -I{} cp --parents {} "$dest/released/$l/")
  done
  {
    cat <<'EOF_README'
# Released reference

The lecturer's reference pieces of the lessons below, released after their deadline. The build
uses them for these lessons instead of your `assignments/` (cmake/lessons.cmake), so that every
later lesson builds, runs and scores with the same earlier lessons as the course's grader. To build
one of them from your own files again: `cmake -S . -B build -DPATHSPACE_STUDENT=N` (README,
"Releases and fixes").

EOF_README
    for l in "${released[@]}"; do echo "- \`$l/\`"; done
  } >"$dest/released/README.md"
fi
echo "handout: wrote $(find "$dest" -path "$dest/.git" -prune -o -type f -print | wc -l) files to $dest (no solutions/$([ ${#released[@]} -gt 0 ] && echo "; released: ${released[*]}"))"
