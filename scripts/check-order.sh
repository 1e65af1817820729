#!/usr/bin/env bash
# Finds random numbers drawn in an order C++ leaves open (README, "Platforms": GCC evaluates a
# call's arguments right to left, clang left to right, so `f(rng.uniform(), rng.uniform2())` or
# `Vec2(rng.uniform(), rng.uniform())` gives different images with each compiler). Draw into named
# variables, left to right in the callee's parameter order, or inside braces.
#   bash scripts/check-order.sh [FILE.cpp ...]   default: every .cpp file of build/compile_commands.json
#   CHECK_ORDER_BUILD=DIR                          another configured build (its compile_commands.json)
# Prints each place found, with its line (matches inside library headers are left out), and
# exits 1 if there is one. clang-query (Debian: clang-tools) parses each file as clang would: about
# 10 CPU-minutes for the whole repository, seconds per file. Known and meant (it cannot tell them
# apart): two different generators compared (`rng.uniform() == copy.uniform()`), a lambda argument
# whose body draws (lesson 10's adrrs_integrator.cpp), and the walk tests of lessons 3 and 5 that
# replay a student's numbers drawn inside the call in the compiler's own order (their "in the
# call" branches). tools/order/draw_order.query holds the matchers.
set -uo pipefail
cd "$(dirname "$0")/.."
bld="${CHECK_ORDER_BUILD:-build}"
command -v clang-query >/dev/null 2>&1 || { echo "check-order: clang-query not found (Debian: apt-get install clang-tools)" >&2; exit 2; }
[ -f "$bld/compile_commands.json" ] || { echo "check-order: $bld/compile_commands.json missing: configure $bld first" >&2; exit 2; }
files=("$@")
if [ ${#files[@]} -eq 0 ]; then
  mapfile -t files < <(sed -n 's/^ *"file": "\(.*\)",\?$/\1/p' "$bld/compile_commands.json" | sort -u)
fi
found=0
for f in "${files[@]}"; do
  out=$(clang-query -p "$bld" -f tools/order/draw_order.query "$f" 2>/dev/null | grep -A1 'note: "root" binds here' |
        grep -v '^--$' | paste - - | grep -v '^/usr/' || true)
  [ -n "$out" ] || continue
  printf '%s\n' "$out" | sed 's/: note: "root" binds here\t */: /'
  found=$((found + $(printf '%s\n' "$out" | wc -l)))
done
echo "check-order: $found place(s) in ${#files[@]} file(s)"
[ "$found" -eq 0 ]
