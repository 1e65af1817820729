#!/usr/bin/env bash
# pathspace against SmallVCM (github.com/SmallVCM/SmallVCM, built by you; never part of the
# course) on SmallVCM's scenes 1 (a mirror sphere) and 2 (a point light, mirror and glass) at
# equal wall-clock time: pixel samples per second and relMSE against one reference for pt, lt
# and bpt. bench/README.md, "Renders against SmallVCM", says how to build SmallVCM with the
# scenes' floor as ours (one sed line) and lists the figures.
#
#   bench/smallvcm_compare.sh SMALLVCM [SECONDS] [THREADS] [SCENE]
#
# SECONDS (default 20) of wall-clock time per render, THREADS (default 2) for both renderers,
# SCENE 1 (default: SmallVCM's -s 1, scenes/smallvcm-mirror.scene) or 2 (smallvcm-point.scene).
# ALGOS (environment, default "pt lt bpt"): ours to compare, each with SmallVCM's of the same
# name (vcm and vcm-balance with SmallVCM's vcm, vcm-bpm with its bpm, vcm-ppm with its ppm).
# REF_ALGO (default bpt): the reference's algorithm (vcm where the scene has paths no connection
# samples, such as scene 2's caustics of a point light seen through glass). Each render's process
# CPU time (user + system, bash's `time`) is measured too: on a shared machine the efficiency per
# CPU second, 1 / (relMSE x CPU seconds), is the comparable figure.
# The reference is pathspace's bpt for 8 x SECONDS on THREADS threads, in CPU time (kept in
# $OUT/reference.pfm and reused when present). SmallVCM's -t counts process CPU time (clock()), which with 2 threads is twice the
# wall time, so SmallVCM is given a number of iterations instead: its rate is measured on a short
# run first, and the iterations are chosen to fill SECONDS; both wall times are measured here
# and printed, and the efficiency 1 / (relMSE x seconds) evens out what is left.
set -euo pipefail
if [[ $# -lt 1 || $1 == --help || $1 == -h ]]; then
  sed -n '2,22p' "$0" | sed 's/^# \{0,1\}//'
  [[ $# -ge 1 ]] && exit 0 || exit 2
fi
SVCM=$(realpath "$1"); SECONDS_EACH=${2:-20}; THREADS=${3:-2}; SID=${4:-1}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${BUILD:-$ROOT/build}
case $SID in
  1) SCENE=$ROOT/scenes/smallvcm-mirror.scene ;;
  2) SCENE=$ROOT/scenes/smallvcm-point.scene ;;
  *) echo "smallvcm_compare: SCENE is 1 or 2, not $SID" >&2; exit 2 ;;
esac
OUT=${OUT:-$ROOT/build/smallvcm-compare-$SID}
[[ -x $SVCM ]] || { echo "smallvcm_compare: $SVCM is not an executable" >&2; exit 2; }
for t in pathspace image_compare; do
  [[ -x $BUILD/$t ]] || { echo "smallvcm_compare: $BUILD/$t missing: cmake --build build --target $t" >&2; exit 2; }
done
mkdir -p "$OUT"; cd "$OUT"
now() { date +%s.%N; }
calc() { awk "BEGIN { print $1 }"; }  # floating-point arithmetic (awk is in every Debian)
REF_ALGO=${REF_ALGO:-bpt}
if [[ ! -f reference.pfm ]]; then
  # 8 x SECONDS on THREADS threads' worth of CPU time (the same on an idle machine, fair on a busy one)
  echo "reference: pathspace $REF_ALGO for $((8 * SECONDS_EACH * THREADS)) CPU seconds ..."
  "$BUILD/pathspace" render "$SCENE" --algo "$REF_ALGO" --time $((8 * SECONDS_EACH * THREADS)) --cpu-time \
    --threads "$THREADS" --seed 1000 --out reference.pfm --no-progress 2>&1 | grep ' spp in '
fi
TIMEFORMAT='%U %S'                     # bash's `time`: the process's user and system CPU seconds
cpu() { awk '{ print $1 + $2 }' "$1"; }
echo "scene $SID: $SCENE; $THREADS thread(s), $SECONDS_EACH s per render"
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-5s %-10s %6s %8s %8s %12s %10s %10s %10s %10s\n' algo renderer spp wall_s cpu_s samples/s relMSE trimmed \
  efficiency eff_cpu
svcm_algo() { case $1 in vcm | vcm-balance) echo vcm ;; vcm-bpm) echo bpm ;; vcm-ppm) echo ppm ;; *) echo "$1" ;; esac; }
for a in ${ALGOS:-pt lt bpt}; do
  sa=$(svcm_algo "$a")
  # pathspace: --time stops the render loop after SECONDS_EACH.
  s=$(now)
  { time "$BUILD/pathspace" render "$SCENE" --algo $a --time "$SECONDS_EACH" --threads "$THREADS" \
      --out ours-$a.pfm --no-progress >ours-$a.log 2>&1; } 2>ours-$a.time
  e=$(now)
  line=$(grep ' spp in ' ours-$a.log)
  spp=$(sed -E 's/.*: ([0-9]+) spp in.*/\1/' <<<"$line")
  wall=$(calc "$e - $s")
  # SmallVCM: 2 x THREADS iterations to measure its rate, then enough to fill SECONDS_EACH.
  n0=$((2 * THREADS)); s=$(now)
  OMP_NUM_THREADS=$THREADS "$SVCM" -s $SID -a "$sa" -i $n0 -o svcm-probe.hdr >/dev/null
  e=$(now)
  n=$(calc "int($SECONDS_EACH * $n0 / ($e - $s) / $THREADS + 0.5) * $THREADS")
  [[ $n -ge $THREADS ]] || n=$THREADS
  s=$(now)
  { time OMP_NUM_THREADS=$THREADS "$SVCM" -s $SID -a "$sa" -i $n -o svcm-$a.hdr >/dev/null; } 2>svcm-$a.time
  e=$(now)
  swall=$(calc "$e - $s")
  for r in ours svcm; do
    if [[ $r == ours ]]; then img=ours-$a.pfm; k=$spp; w=$wall; name=pathspace; else img=svcm-$a.hdr; k=$n; w=$swall; name=SmallVCM; fi
    c=$(cpu $r-$a.time)
    m=$("$BUILD/image_compare" "$img" reference.pfm --scene "$SCENE")
    rel=$(awk '$1 == "MSE" {print $4}' <<<"$m"); trim=$(awk '$1 == "MSE" {print $7}' <<<"$m")
    ratio=$(sed -nE 's/^mean ratio (.*)/\1/p' <<<"$m")
    printf '%-5s %-10s %6d %8.2f %8.2f %12.0f %10.4g %10.4g %10.4g %10.4g   (mean / reference: %s)\n' $a $name \
      $k $w $c "$(calc "$k * 512 * 512 / $w")" "$rel" "$trim" "$(calc "1 / ($rel * $w)")" \
      "$(calc "1 / ($rel * $c)")" "$ratio"
  done
done
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "samples/s: pixel samples (iterations x 512 x 512) per wall-clock second; efficiency: 1 / (relMSE x wall seconds);" \
  "eff_cpu: 1 / (relMSE x CPU seconds of the whole process)"
