#!/usr/bin/env bash
# Writes the student handout into DIR: every tracked file except solutions/ and CI files, with the
# student's README and the GitHub Classroom / Actions workflow (tools/handout/).
# The handout builds with every lesson from assignments/ (there is no solutions/ in it).
#   bash scripts/handout.sh DIR
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: bash scripts/handout.sh DIR" >&2; exit 2; }
src="$(cd "$(dirname "$0")/.." && pwd)"
dest="$1"
if [ -e "$dest" ] && [ -n "$(ls -A "$dest" 2>/dev/null)" ]; then
  echo "handout: $dest exists and is not empty; give a new directory" >&2
  exit 1
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
echo "handout: wrote $(find "$dest" -type f | wc -l) files to $dest (no solutions/)"
