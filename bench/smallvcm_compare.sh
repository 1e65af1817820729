#!/usr/bin/env bash
# pathspace against SmallVCM (github.com/SmallVCM/SmallVCM, built by you; never part of the
# course) on SmallVCM's scenes 1 (a mirror sphere) and 2 (a point light, mirror and glass) at
# equal time: pixel samples per second and relMSE against one reference for each algorithm.
# bench/README.md, "Renders against SmallVCM", says how to build SmallVCM with the scenes' floor
# as ours (one sed line) and lists the figures.
#
#   bench/smallvcm_compare.sh [--clock wall|cpu] [--algos LIST] [--ref-algo A] [--seeds K] SMALLVCM [SECONDS] [THREADS] [SCENE]
#
# SECONDS (default 20) per render, THREADS (default 2) for both renderers, SCENE 1 (default:
# SmallVCM's -s 1, scenes/smallvcm-mirror.scene) or 2 (smallvcm-point.scene); LIST of pt, lt,
# bpt, bpt-balance, ppm, vcm, vcm-balance, vcm-bpm, vcm-ppm (default pt,lt,bpt,ppm), each against
# SmallVCM's of the same name (bpt-balance against its bpt, whose MIS is the balance heuristic;
# vcm and vcm-balance against its vcm, vcm-bpm its bpm, vcm-ppm its ppm). The
# reference is pathspace's A (default bpt; vcm where no connection samples a scene's caustics)
# for 8 x SECONDS (kept in $OUT/reference.pfm and reused when present). --clock wall (default):
# wall-clock seconds of each whole process, measured here; --clock cpu: CPU seconds of the render loop, all threads added
# up, as each renderer reports them (pathspace render --clock cpu; SmallVCM's "done in", which is
# clock(), the process's CPU time): fair when other jobs share the machine. Either way SmallVCM
# is given a number of iterations (its -t counts CPU time: with 2 threads it would stop at half
# the wall time given), chosen from its rate on a short run to fill SECONDS; the efficiency
# 1 / (relMSE x seconds) evens out the difference left. --seeds K: K renders of each, seeds 1 .. K
# for both (pathspace --seed; SmallVCM's SVCM_SEED, which needs the seed line of bench/README.md:
# its own seed is fixed), then the medians of relMSE and seconds and the efficiency of those: one
# image of each compares two draws of a heavy-tailed error (bench/README.md, issue 30).
set -euo pipefail
CLOCK=wall; ALGOS=pt,lt,bpt,ppm; REF_ALGO=bpt; NSEEDS=0
while [[ $# -gt 0 && $1 == --* ]]; do
  case $1 in
    --clock) [[ ${2:-} == wall || ${2:-} == cpu ]] || { echo "smallvcm_compare: --clock wall|cpu" >&2; exit 2; }
             CLOCK=$2; shift 2 ;;
    --algos) ALGOS=${2:?--algos needs a list}; shift 2 ;;
    --ref-algo) REF_ALGO=${2:?--ref-algo needs an algorithm}; shift 2 ;;
    --seeds) [[ ${2:-} =~ ^[1-9][0-9]*$ ]] || { echo "smallvcm_compare: --seeds K, K >= 1" >&2; exit 2; }
             NSEEDS=$2; shift 2 ;;
    --help|-h) sed -n '2,25p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "smallvcm_compare: unknown option $1" >&2; exit 2 ;;
  esac
done
if [[ $# -lt 1 ]]; then sed -n '2,25p' "$0" | sed 's/^# \{0,1\}//'; exit 2; fi
SVCM=$(realpath "$1"); SECONDS_EACH=${2:-20}; THREADS=${3:-2}; SID=${4:-1}
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BUILD=${BUILD:-$ROOT/build}
case $SID in
  1) SCENE=$ROOT/scenes/smallvcm-mirror.scene ;;
  2) SCENE=$ROOT/scenes/smallvcm-point.scene ;;
  *) echo "smallvcm_compare: SCENE is 1 or 2, not $SID" >&2; exit 2 ;;
esac
# SmallVCM's name of the same algorithm.
svcm_algo() { case $1 in pt | lt | bpt | ppm) echo "$1" ;; bpt-balance) echo bpt ;; vcm | vcm-balance) echo vcm ;; vcm-bpm) echo bpm ;; vcm-ppm) echo ppm ;; esac; }
for a in ${ALGOS//,/ }; do
  [[ -n $(svcm_algo "$a") ]] || { echo "smallvcm_compare: algorithm $a: pt, lt, bpt, bpt-balance, ppm, vcm, vcm-balance, vcm-bpm or vcm-ppm" >&2; exit 2; }
done
OUT=${OUT:-$ROOT/build/smallvcm-compare-$SID}
[[ -x $SVCM ]] || { echo "smallvcm_compare: $SVCM is not an executable" >&2; exit 2; }
for t in pathspace image_compare; do
  [[ -x $BUILD/$t ]] || { echo "smallvcm_compare: $BUILD/$t missing: cmake --build build --target $t" >&2; exit 2; }
done
mkdir -p "$OUT"; cd "$OUT"
now() { date +%s.%N; }
calc() { awk "BEGIN { print $1 }"; }  # floating-point arithmetic (awk is in every Debian)
# Seconds from pathspace's summary line ("N spp in S s" or "N spp in S CPU s") and SmallVCM's
# last line ("done in S s", its clock(): CPU time).
ours_seconds() { sed -E 's/.* spp in ([0-9.]+) .*/\1/' <<<"$1"; }
svcm_seconds() { sed -nE 's/.*done in ([0-9.]+) s.*/\1/p' <<<"$1"; }
if [[ ! -f reference.pfm ]]; then
  echo "reference: pathspace $REF_ALGO for $((8 * SECONDS_EACH)) s ($CLOCK clock) ..."
  "$BUILD/pathspace" render "$SCENE" --algo "$REF_ALGO" --time $((8 * SECONDS_EACH)) --clock $CLOCK --threads "$THREADS" \
    --seed 1000 --out reference.pfm --no-progress 2>&1 | grep ' spp in '
fi
unit="wall-clock s of each process"; [[ $CLOCK == cpu ]] && unit="CPU s of the render loop, all threads"
echo "scene $SID: $SCENE; $THREADS thread(s), $SECONDS_EACH s per render; clock: $CLOCK ($unit)"
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-5s %-10s %6s %8s %12s %10s %10s %10s\n' algo renderer spp seconds samples/s relMSE trimmed efficiency
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
SEEDS=""; [[ $NSEEDS -gt 0 ]] && SEEDS=$(seq 1 "$NSEEDS")
for a in ${ALGOS//,/ }; do
  sa=$(svcm_algo "$a")
  # SmallVCM: 2 x THREADS iterations to measure its rate, then enough to fill SECONDS_EACH.
  n0=$((2 * THREADS)); s=$(now)
  probe=$(OMP_NUM_THREADS=$THREADS "$SVCM" -s $SID -a "$sa" -i $n0 -o svcm-probe.hdr)
  e=$(now)
  if [[ $CLOCK == cpu ]]; then per=$(calc "$(svcm_seconds "$probe") / $n0"); else per=$(calc "($e - $s) / $n0"); fi
  n=$(calc "int($SECONDS_EACH / $per / $THREADS + 0.5) * $THREADS")
  [[ $n -ge $THREADS ]] || n=$THREADS
  declare -A R=() W=() T=()
  for seed in ${SEEDS:-default}; do
    sfx=""; seedArg=(); [[ $seed != default ]] && { sfx=-s$seed; seedArg=(--seed "$seed"); }
    s=$(now)
    line=$("$BUILD/pathspace" render "$SCENE" --algo $a --time "$SECONDS_EACH" --clock $CLOCK --threads "$THREADS" \
             "${seedArg[@]}" --out ours-$a$sfx.pfm --no-progress 2>&1 | grep ' spp in ')
    e=$(now)
    spp=$(sed -E 's/.*: ([0-9]+) spp in.*/\1/' <<<"$line")
    if [[ $CLOCK == cpu ]]; then time_ours=$(ours_seconds "$line"); else time_ours=$(calc "$e - $s"); fi
    s=$(now)
    if [[ $seed == default ]]; then run=$(OMP_NUM_THREADS=$THREADS "$SVCM" -s $SID -a "$sa" -i $n -o svcm-$a.hdr)
    else run=$(SVCM_SEED=$seed OMP_NUM_THREADS=$THREADS "$SVCM" -s $SID -a "$sa" -i $n -o svcm-$a$sfx.hdr); fi
    e=$(now)
    if [[ $CLOCK == cpu ]]; then time_svcm=$(svcm_seconds "$run"); else time_svcm=$(calc "$e - $s"); fi
    if [[ $seed == 2 ]] && cmp -s svcm-$a-s1.hdr svcm-$a-s2.hdr; then
      echo "smallvcm_compare: SmallVCM gave the same image for seeds 1 and 2: build it with the SVCM_SEED line of bench/README.md" >&2
      exit 1
    fi
    for r in ours svcm; do
      if [[ $r == ours ]]; then img=ours-$a$sfx.pfm; k=$spp; w=$time_ours; name=pathspace; else img=svcm-$a$sfx.hdr; k=$n; w=$time_svcm; name=SmallVCM; fi
      m=$("$BUILD/image_compare" "$img" reference.pfm --scene "$SCENE")
      rel=$(awk '$1 == "MSE" {print $4}' <<<"$m"); trim=$(awk '$1 == "MSE" {print $7}' <<<"$m")
      ratio=$(sed -nE 's/^mean ratio (.*)/\1/p' <<<"$m")
      R[$r]+=" $rel"; T[$r]+=" $trim"; W[$r]+=" $w"
      printf '%-5s %-10s %6d %8.2f %12.0f %10.4g %10.4g %10.4g   (mean / reference: %s%s)\n' $a $name $k $w \
        "$(calc "$k * 512 * 512 / $w")" "$rel" "$trim" "$(calc "1 / ($rel * $w)")" "$ratio" "${sfx:+; seed ${seed}}"
    done
  done
  if [[ $NSEEDS -gt 1 ]]; then
    for r in ours svcm; do
      [[ $r == ours ]] && name=pathspace || name=SmallVCM
      mr=$(median ${R[$r]}); mt=$(median ${T[$r]}); mw=$(median ${W[$r]})
      printf '%-5s %-10s %6s %8.2f %12s %10.4g %10.4g %10.4g   (medians of %d seeds)\n' $a $name median $mw "" "$mr" "$mt" \
        "$(calc "1 / ($mr * $mw)")" "$NSEEDS"
      eval "eff_$r=$(calc "1 / ($mr * $mw)")"
    done
    echo "$a: efficiency ours / SmallVCM from the medians: $(calc "$eff_ours / $eff_svcm")"
  fi
done
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "seconds: $unit; samples/s: pixel samples (iterations x 512 x 512) per such second;"
echo "efficiency: 1 / (relMSE x seconds)"
