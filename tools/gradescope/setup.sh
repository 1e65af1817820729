#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image (the package is
# unzipped in /autograder/source; scripts/gradescope.sh made it). It installs the Debian packages
# the course needs, builds the grader and the prepared tree from the reference once (grade
# --prepare: grading then compiles only a submission's files), and leaves in the image only what
# grading needs: the grader and the tree, no solution source and no reference build.
# GRADESCOPE_ROOT (default /autograder) moves everything, for a test under a temporary root.
set -euo pipefail
root="${GRADESCOPE_ROOT:-/autograder}"
src="$root/source/pathspace"
tree="$root/pathspace/grader"
bash "$src/scripts/deps.sh"
# The grader itself, in the build folder that grade --prepare then uses for the reference.
cmake -S "$src" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release -DPATHSPACE_STUDENT= -DPATHSPACE_GRADER_TREE="$tree" >/dev/null
cmake --build "$tree/build" -j"$(nproc)" --target grade
"$tree/build/grade" --prepare "$tree" --source "$src" --jobs "$(nproc)"
mkdir -p "$root/pathspace/bin"
cp "$tree/build/grade" "$root/pathspace/bin/grade"
rm -rf "$tree/build" "$src"
echo "setup: the grader is $root/pathspace/bin/grade, its prepared tree $tree"
