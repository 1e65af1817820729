#!/usr/bin/env bash
# Renders every figure the lessons and slides show, with the reference solutions, from the
# commands their READMEs document (lecturers: after changing a solution or a scene).
#
#   bash scripts/figures.sh [--quick] [--out DIR] [--build DIR] [NN ...]
#
#   NN ...       only these lessons (e.g. 03 05); default: every lesson that has figures
#   --out DIR    write the figures under DIR/NN-name/ instead of into lessons/NN-name/
#   --quick      tiny budgets (seconds, not minutes) for a smoke run: checks that every command
#                works and every figure is written; the images are noisy. CI runs it.
#   --build DIR  the build to use (default: build; configured and built if missing)
#
# Full budgets take a little over an hour on 2 cores (most of it rendering references).
set -euo pipefail
cd "$(dirname "$0")/.."
src="$PWD"
quick=0 out="" build="build" only=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --out) out="$2"; shift ;;
    --build) build="$2"; shift ;;
    -h|--help) sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    [0-9][0-9]) only+=("$1") ;;
    *) echo "figures: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
if [ ! -x "$build/pathspace" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$build" -j"$(nproc)" >/dev/null
fi
case "$build" in /*) ;; *) build="$src/$build" ;; esac
ps="$build/pathspace"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
touch "$work/start"   # figures newer than this were made by this run

# t FULL QUICK: a budget (seconds or samples) in full or in quick mode.
t() { if [ "$quick" = 1 ]; then echo "$2"; else echo "$1"; fi; }
# dest NN-name: the folder the lesson's figures go to.
dest() { local d="${out:+$out/$1}"; d="${d:-$src/lessons/$1}"; mkdir -p "$d"; echo "$d"; }
wanted() { [ ${#only[@]} -eq 0 ] && return 0; local n; for n in "${only[@]}"; do [ "$n" = "$1" ] && return 0; done; return 1; }
# scene NAME RES: scenes/NAME.scene at RES x RES pixels, as the READMEs' `sed` lines make it.
scene() { sed "s/resolution 256 256/resolution $2 $2/" "scenes/$1.scene" > "$work/$1-$2.scene"; echo "$work/$1-$2.scene"; }
# reference ALGO SECONDS SCENE: a reference image of SCENE (seed 99), its path. Half a second in
# quick mode, whatever SECONDS says (CTest's course_figures_quick runs every figure this way).
reference() {
  local r="$work/ref-$RANDOM.pfm" secs="$2"; [ "$quick" = 1 ] && secs=0.5
  "$ps" render "$3" --algo "$1" --time "$secs" --seed 99 --out "$r" --no-progress >&2; echo "$r"
}
# converge SCENE REF OUTDIR ARGS...: pathspace converge quietly into OUTDIR.
converge() { local s="$1" r="$2" o="$3"; shift 3; "$ps" converge "$s" --reference "$r" --out "$o" --no-progress "$@" > "$o.log"; }
# The student handout has no reference: the figures come from the student's own pieces, and lesson
# 8's photon-map pictures (tools/photon_figures.cpp gathers with the reference's code) are left out.
handout=0
if [ ! -d solutions ]; then
  handout=1
  echo "figures: no solutions/ here (the student handout): the figures are made with your own pieces;" \
    "lesson 8's photon-map pictures (a lecturer's tool) are left out" >&2
fi
n=0
done_fig() { n=$((n + 1)); echo "figures: wrote $1"; }
cmake --build "$build" --target diagrams >/dev/null && "$build/diagrams" "${out:-$src/lessons}"  # blackboard SVGs, every lesson

# Lesson 2: Veach's plates, 16 spp of each estimator and the reference (lessons/02 README, section 5).
if wanted 02; then
  d="$(dest 02-direct-mis)"; s="$(scene veach-plates 128)"
  r="$(reference direct-power "$(t 60 2)" "$s")"
  converge "$s" "$r" "$work/02" --spp "$(t 16 2)" \
    --algos direct-light,direct-bsdf,direct-balance,direct-power,direct-max,direct-onesample
  cp "$work/02/equal-time.png" "$d/plates-16spp.png"; done_fig "$d/plates-16spp.png"
fi

# Lesson 3: pt-bsdf, pt-nee, pt on the Cornell box at equal time, 2 seeds (lessons/03 README, section 5).
if wanted 03; then
  d="$(dest 03-path-tracing)"; s="$(scene cornell-box 128)"
  r="$(reference pt "$(t 300 2)" "$s")"
  converge "$s" "$r" "$work/03" --algos pt-bsdf,pt-nee,pt --time "$(t 5 0.3)" --seeds 2
  cp "$work/03/equal-time.png" "$d/cornell-equal-time.png"
  cp "$work/03/convergence.svg" "$work/03/convergence.csv" "$work/03/efficiency.md" "$d/"
  done_fig "$d/cornell-equal-time.png, convergence.svg, convergence.csv, efficiency.md"
fi

# Lesson 4: pt and measure on the Cornell box (lessons/04 README).
if wanted 04; then
  d="$(dest 04-measurement)"; s="$(scene cornell-box 128)"
  r="$(reference pt "$(t 300 2)" "$s")"
  converge "$s" "$r" "$work/04" --algos pt,measure --time "$(t 8 0.3)" --seeds 2
  cp "$work/04/equal-time.png" "$d/converge-equal-time.png"; cp "$work/04/convergence.svg" "$d/converge.svg"
  done_fig "$d/converge-equal-time.png, converge.svg"
fi

# Lesson 5: pt and lt on the Cornell box, the glass lamp and the Cornell spheres (lessons/05 README).
if wanted 05; then
  d="$(dest 05-light-tracing)"
  for c in "cornell-box cornell pt 300" "glass-lamp glass-lamp lt 300" "cornell-spheres spheres pt 745"; do
    set -- $c
    s="$(scene "$1" 128)"; r="$(reference "$3" "$(t "$4" 2)" "$s")"
    converge "$s" "$r" "$work/05-$2" --algos pt,lt --time "$(t 8 0.3)" --seeds 2
    cp "$work/05-$2/equal-time.png" "$d/$2-equal-time.png"; cp "$work/05-$2/convergence.svg" "$d/$2-converge.svg"
    done_fig "$d/$2-equal-time.png, $2-converge.svg"
  done
fi

# Lesson 6: the four techniques of path length 3 on the gap box, 64 spp each (lessons/06 README, section 5).
if wanted 06; then
  d="$(dest 06-path-space)"; s="$work/gap96.scene"
  sed 's/resolution 16 16/resolution 96 96/' tests/06-path-space/data/gap-box.scene > "$s"
  r="$work/ref96.pfm"
  "$ps" render "$s" --algo path-s1 --maxdepth 2 --spp "$(t 4096 16)" --seed 1 --out "$r" --no-progress >&2
  converge "$s" "$r" "$work/06" --algos path-s0,path-s1,path-s2,path-s3 --spp "$(t 64 4)" --maxdepth 2
  cp "$work/06/equal-time.png" "$d/gap-box-k3-techniques.png"; done_fig "$d/gap-box-k3-techniques.png"
fi

# Lesson 7: pt, lt and bpt on the Cornell box at equal time; Veach's pyramid (lessons/07 README).
if wanted 07; then
  d="$(dest 07-bidirectional)"; s="$(scene cornell-box 128)"
  r="$(reference pt "$(t 240 2)" "$s")"
  converge "$s" "$r" "$work/07" --algos pt,lt,bpt --time "$(t 8 0.3)" --seeds 2
  cp "$work/07/equal-time.png" "$d/cornell-equal-time.png"; cp "$work/07/convergence.svg" "$d/cornell-converge.svg"
  cp "$work/07/convergence.csv" "$d/cornell-convergence.csv"; cp "$work/07/efficiency.md" "$d/cornell-efficiency.md"
  done_fig "$d/cornell-equal-time.png, cornell-converge.svg, cornell-convergence.csv, cornell-efficiency.md"
  "$ps" pyramid "$s" --max-length 4 --spp "$(t 128 2)" --seed 1 --exposure 1 --out "$work/07-pyramid" > "$work/07-pyramid.log"
  cp "$work/07-pyramid-unweighted.png" "$d/cornell-pyramid-unweighted.png"
  cp "$work/07-pyramid-weighted.png" "$d/cornell-pyramid-weighted.png"
  done_fig "$d/cornell-pyramid-unweighted.png, cornell-pyramid-weighted.png"
  # Specular vertices in the MIS (README 1.6): pt and bpt at equal samples on the caustics box,
  # relMSE per region (the pixels that see the glass, the mirror, the white walls).
  s="$(scene cornell-caustics 64)"
  r="$(reference pt "$(t 150 2)" "$s")"
  converge "$s" "$r" "$work/07-caustics" --algos pt,bpt --spp "$(t 64 2)" --seeds 2 --regions glass,chrome,white
  cp "$work/07-caustics/equal-time.png" "$d/caustics-equal-spp.png"; cp "$work/07-caustics/regions.md" "$d/caustics-regions.md"
  cp "$work/07-caustics/efficiency.md" "$d/caustics-efficiency.md"
  done_fig "$d/caustics-equal-spp.png, caustics-regions.md, caustics-efficiency.md"
fi

# Lesson 8: what a photon mapper holds (the maps as dots, the filters, the caustic map alone, final
# gathering off and on, the irradiance cache's records: tools/photon_figures.cpp), and pt, bpt, pm
# and ppm on the glass caustic at equal time, per region (lessons/08 README, section 5).
if wanted 08; then
  d="$(dest 08-photon-mapping)"
  if [ "$handout" = 0 ]; then
    cmake --build "$build" --target photon_figures >/dev/null
    if [ "$quick" = 1 ]; then "$build/photon_figures" "$d" --quick; else "$build/photon_figures" "$d"; fi > "$work/08-figures.log"
    done_fig "$d/pm-photons.png, pm-filters.png, pm-caustic-map.png, pm-final-gather.png, pm-ic-records.png"
  fi
  s="$(scene glass-caustic 128)"
  r="$(reference bpt "$(t 900 2)" "$s")"
  converge "$s" "$r" "$work/08" --algos pt,bpt,pm,ppm --time "$(t 30 0.3)" --seeds 2 --regions white,mirror,glass
  cp "$work/08/equal-time.png" "$d/caustic-equal-time.png"; cp "$work/08/convergence.svg" "$d/caustic-converge.svg"
  cp "$work/08/convergence.csv" "$d/caustic-convergence.csv"; cp "$work/08/efficiency.md" "$d/caustic-efficiency.md"
  cp "$work/08/regions.md" "$d/caustic-regions.md"
  done_fig "$d/caustic-equal-time.png, caustic-converge.svg, caustic-convergence.csv, caustic-efficiency.md, caustic-regions.md"
fi

# Lesson 9: pt, bpt, pssmlt and mmlt at equal time, pathspace converge on Veach's door (where MLT
# should win: 128 x 128, 10 s each) and on the Cornell box (where it should not: 96 x 96, 5 s each),
# 2 seeds (lessons/09 README, "What MLT buys"); --quick: 32 x 32.
if wanted 09; then
  d="$(dest 09-metropolis)"
  for c in "door door 128 480 10" "cornell-box cornell 96 180 5"; do
    set -- $c
    s="$(scene "$1" "$(t "$3" 32)")"; r="$(reference pt "$(t "$4" 2)" "$s")"
    converge "$s" "$r" "$work/09-$2" --algos pt,bpt,pssmlt,mmlt --time "$(t "$5" 0.2)" --seeds "$(t 2 1)"
    cp "$work/09-$2/equal-time.png" "$d/$2-equal-time.png"; cp "$work/09-$2/convergence.svg" "$d/$2-converge.svg"
    cp "$work/09-$2/efficiency.md" "$d/$2-efficiency.md"
    done_fig "$d/$2-equal-time.png, $2-converge.svg, $2-efficiency.md"
  done
fi

# Lesson 10: the skylight, pt and pt-adrrs at equal time, the pre-pass included, and the converge
# report (lessons/10 README, section 5).
if wanted 10; then
  d="$(dest 10-adrrs)"; s="$(scene skylight 128)"
  r="$(reference pt "$(t 600 2)" "$s")"
  converge "$s" "$r" "$work/10" --algos pt,pt-adrrs --time "$(t 20 0.3)" --seeds 2
  cp "$work/10/equal-time.png" "$d/skylight-equal-time.png"; cp "$work/10/convergence.svg" "$d/skylight-convergence.svg"
  cp "$work/10/convergence.csv" "$d/skylight-convergence.csv"; cp "$work/10/efficiency.md" "$d/skylight-efficiency.md"
  done_fig "$d/skylight-equal-time.png, skylight-convergence.svg, skylight-convergence.csv, skylight-efficiency.md"
fi

# Lesson 12: the door and the skylight at equal time (pt, lesson 10's pt-adrrs, pt-guided,
# pt-guided-adrrs), the light in a side room (lt, lt-adrrs) and the field's memory under budgets
# (lessons/12-path-guiding README, section 5). The door and the skylight on the CPU clock: a
# comparison of four algorithms run one after the other stays fair on a shared machine.
if wanted 12; then
  d="$(dest 12-path-guiding)"
  for c in "door door" "skylight skylight"; do
    set -- $c
    s="$(scene "$1" 128)"; r="$(reference pt "$(t 600 2)" "$s")"
    converge "$s" "$r" "$work/12-$2" --algos pt,pt-adrrs,pt-guided,pt-guided-adrrs --time "$(t 20 0.3)" --clock cpu \
      --seeds "$(t 2 1)"
    cp "$work/12-$2/equal-time.png" "$d/$2-equal-time.png"; cp "$work/12-$2/convergence.svg" "$d/$2-converge.svg"
    cp "$work/12-$2/efficiency.md" "$d/$2-efficiency.md"
    done_fig "$d/$2-equal-time.png, $2-converge.svg, $2-efficiency.md"
  done
  s="$(scene side-room 128)"; r="$(reference pt "$(t 600 2)" "$s")"
  converge "$s" "$r" "$work/12-side" --algos lt,lt-adrrs --time "$(t 20 0.3)" --seeds "$(t 2 1)"
  cp "$work/12-side/equal-time.png" "$d/side-room-equal-time.png"; cp "$work/12-side/efficiency.md" "$d/side-room-efficiency.md"
  done_fig "$d/side-room-equal-time.png, side-room-efficiency.md"
  s="$(scene door 128)"
  { echo "| --guide-budget (MB) | cells | field (MB) |"; echo "|---:|---:|---:|"
    for b in 0.1 1 4 64; do
      "$ps" render "$s" --algo pt-guided --spp "$(t 63 7)" --guide-budget "$b" --seed 1 --out "$work/12-mem.pfm" \
        --no-progress 2>/dev/null | sed -n "s/.*field: \([0-9]*\) cells.* records, \([0-9.]*\) MB/| $b | \1 | \2 |/p"
    done; } > "$d/memory.md"
  done_fig "$d/memory.md"
fi

# lesson 11 (paths): pt split by Heckbert's path expressions on the Cornell spheres (LE, LDE, LD+DE
# and L.*S.*E add up to every path, L.*E; LS+DE, the caustics, is part of the last)
# (lessons/11-classics README, "Expected output"; tools/strip.cpp labels them).
if wanted 11; then
  d="$(dest 11-classics)"; s="$(scene cornell-spheres 128)"
  cmake --build "$build" --target strip >/dev/null
  cells=()
  for e in 'L.*E' LE LDE 'LD+DE' 'L.*S.*E' 'LS+DE'; do
    f="$work/11-split-${#cells[@]}.pfm"
    "$ps" render "$s" --algo pt --paths "$e" --spp "$(t 1024 4)" --seed 1 --out "$f" --no-progress >/dev/null 2>&1
    cells+=("pt $e=$f")
  done
  "$build/strip" "$d/pt-split.png" "${cells[@]}"
  done_fig "$d/pt-split.png"
fi

# lesson 11 (family tree): each classic beside the path tracer filtered to the paths it carries
# (lessons/11-classics README, section 1.17 and "Expected output"). No scene suits all three:
# radiosity takes only diffuse quads lit by quads, and Whitted lights surfaces only with point
# lights. So two scenes at 128 x 128: the Cornell box (radiosity, drt, and Whitted, which shows its
# lamp and nothing the lamp lights) and the Cornell box with point lights, a mirror, glass and
# Phong (Whitted, drt; pt and bpt with every path: pt cannot sample the point lights' caustics,
# bpt can). About 2 minutes on 2 cores.
if wanted 11; then
  d="$(dest 11-classics)"
  cmake --build "$build" --target strip >/dev/null
  # cell ALGO SPP LABEL [ARGS...]: render the current scene $s into the next cell of $cells.
  cell() {
    local f="$work/11-family-${#cells[@]}.pfm" algo="$1" spp="$2" label="$3"; shift 3
    "$ps" render "$s" --algo "$algo" --spp "$spp" --seed 1 --out "$f" --no-progress "$@" >/dev/null 2>&1
    cells+=("$label=$f")
  }
  s="$(scene cornell-box 128)"; cells=()
  cell radiosity 1 radiosity --shots 100000 --elements "$(t 8 4)"
  cell pt "$(t 1024 4)" 'pt LD*E' --paths 'LD*E'
  cell drt "$(t 1024 4)" drt
  cell pt "$(t 1024 4)" 'pt LD?[GS]*E' --paths 'LD?[GS]*E'
  cell whitted "$(t 64 2)" whitted
  cell pt "$(t 64 2)" 'pt LS*E' --paths 'LS*E'
  "$build/strip" "$d/family-cornell-box.png" "${cells[@]}"
  s="$(scene cornell-whitted 128)"; cells=()
  cell whitted "$(t 64 2)" whitted
  cell pt "$(t 1024 4)" 'pt L[DG]S*E|LS*E' --paths 'L[DG]S*E|LS*E'
  cell drt "$(t 1024 4)" drt
  cell pt "$(t 1024 4)" 'pt LD?[GS]*E' --paths 'LD?[GS]*E'
  cell pt "$(t 1024 4)" 'pt L.*E'
  cell bpt "$(t 256 2)" 'bpt L.*E'
  "$build/strip" "$d/family-cornell-whitted.png" "${cells[@]}"
  done_fig "$d/family-cornell-box.png, family-cornell-whitted.png"
fi

# lesson 11 (radiosity)
# The Cornell box by radiosity (8 x 8 elements a quad) after 1, 10, 100, 1000 shots and converged,
# next to pt; the same shots with the ambient term; converged with 2 x 2 to 16 x 16 elements; and
# the patch averages' error against pt's for each element size (tools/radiosity_figures.cpp,
# lessons/11-classics/README.md, "Expected output"). About 4 minutes on 2 cores, most of it the
# 16 x 16 elements' form factors.
if wanted 11; then
  d="$(dest 11-classics)"
  cmake --build "$build" --target radiosity_figures >/dev/null
  if [ "$quick" = 1 ]; then "$build/radiosity_figures" "$d" --quick; else "$build/radiosity_figures" "$d"; fi > "$work/11-radiosity.log"
  done_fig "$d/radiosity-shots.png, radiosity-ambient-shots.png, radiosity-elements.png, radiosity-elements.md, radiosity-elements.svg"
fi

# lesson 11 (lens): depth of field at two focal distances, distributed ray tracing next to the path
# tracer at equal samples, and bpt's per-technique images with the technique t = 0
# (lessons/11-classics/README.md, "Expected output").
if wanted 11; then
  d="$(dest 11-classics)"; s="$(scene cornell-lens 128)"
  sed 's/focus 900/focus 1280/' "$s" > "$work/11-back.scene"
  for f in "front $s" "back $work/11-back.scene"; do
    set -- $f
    "$ps" render "$2" --algo pt --spp "$(t 1024 4)" --seed 1 --out "$work/11-$1.png" --no-progress >&2
    cp "$work/11-$1.png" "$d/lens-dof-$1.png"
  done
  done_fig "$d/lens-dof-front.png, lens-dof-back.png"
  r="$(reference pt "$(t 180 2)" "$s")"
  converge "$s" "$r" "$work/11-drt" --algos drt,pt --spp "$(t 256 2)"
  cp "$work/11-drt/equal-time.png" "$d/lens-drt.png"; done_fig "$d/lens-drt.png"
  "$ps" pyramid "$s" --max-length 3 --spp "$(t 256 2)" --seed 1 --exposure 1 --out "$work/11-pyramid" > "$work/11-pyramid.log"
  cp "$work/11-pyramid-unweighted.png" "$d/lens-pyramid-unweighted.png"
  cp "$work/11-pyramid-weighted.png" "$d/lens-pyramid-weighted.png"
  done_fig "$d/lens-pyramid-unweighted.png, lens-pyramid-weighted.png"
fi

# Lesson 13: pt, bpt, ppm and vcm at equal time on the Cornell spheres (glass and mirror) and on
# the caustic seen through a window pane, 2 seeds, in seconds of CPU time (--clock cpu: the course
# machine is shared); the references: pt on the Cornell spheres, vcm itself on the pane (no unbiased
# technique samples its caustic well: lessons/13-vcm README, "Expected output").
if wanted 13; then
  d="$(dest 13-vcm)"
  for c in "cornell-spheres spheres pt 1800" "sds-caustic sds vcm 1800"; do
    set -- $c
    s="$(scene "$1" 128)"; r="$work/13-$2-ref.pfm"
    "$ps" render "$s" --algo "$3" --time "$(t "$4" 0.5)" --clock cpu --seed 99 --out "$r" --no-progress >&2
    converge "$s" "$r" "$work/13-$2" --algos pt,bpt,ppm,vcm --time "$(t 60 0.3)" --clock cpu --seeds 2
    cp "$work/13-$2/equal-time.png" "$d/$2-equal-time.png"; cp "$work/13-$2/convergence.svg" "$d/$2-converge.svg"
    cp "$work/13-$2/convergence.csv" "$d/$2-convergence.csv"; cp "$work/13-$2/efficiency.md" "$d/$2-efficiency.md"
    done_fig "$d/$2-equal-time.png, $2-converge.svg, $2-convergence.csv, $2-efficiency.md"
  done
fi

# Every image a slide deck shows from a lesson folder must be one this script makes (so one command
# remakes all of them); checked when every lesson was run, with the reference.
if [ ${#only[@]} -eq 0 ] && [ "$handout" = 0 ]; then
  missing=0
  for link in $(grep -ho '](\.\./lessons/[^)]*)' slides/*.md | sed 's/^](\.\.\/lessons\///; s/)$//' | sort -u); do
    if [ ! -f "$(dest "${link%%/*}")/${link#*/}" ] || [ -z "$(find "$(dest "${link%%/*}")/${link#*/}" -newer "$work/start" 2>/dev/null)" ]; then
      echo "figures: slides show lessons/$link, which this script does not make" >&2; missing=1
    fi
  done
  [ "$missing" = 0 ] || exit 1
fi
echo "figures: $n figure sets written$([ "$quick" = 1 ] && echo ' (quick budgets: noisy)')"
