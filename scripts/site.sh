#!/usr/bin/env bash
# The course web page: a static site from the lesson READMEs (math rendered to MathML when the site
# is built, offline), their diagrams and figures, the slides, a schedule with a time estimate per
# lesson, getting started (Debian/Ubuntu, macOS, Windows with WSL) and a FAQ; then checked in
# headless Chromium: no broken link, no math error, no missing image, nothing from the network.
#
#   bash scripts/site.sh [--out DIR] [--no-slides] [--check-only]
#
#   --out DIR      write the site to DIR (default: build/site); open DIR/index.html
#   --no-slides    leave the slides out (they need node and npm: scripts/slides.sh)
#   --check-only   only the browser check of the site already in DIR
#
# Lessons are the folders lessons/NN-name/ (title: the README's first heading; time estimate: its
# line "*Time: about N hours — R to read, W to write and test ...*"; points: the "[k pts]" of
# tests/NN-name/). Pages: tools/site/{start,faq}.md, the lesson READMEs, framework/ and
# scenes/README.md, the handout's README, and every Markdown file they link to.
# Tools: Debian's pandoc (Markdown and TeX math to HTML with MathML, which Chromium renders) and
# chromium (the check), installed with apt-get like scripts/deps.sh (as root, or through sudo);
# the slides as scripts/slides.sh builds them (Marp from npm, HTML only).
set -euo pipefail
cd "$(dirname "$0")/.."
src="$PWD"
out="build/site" slides=1 checkonly=0
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out="$2"; shift ;;
    --no-slides) slides=0 ;;
    --check-only) checkonly=1 ;;
    -h|--help) sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "site: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
case "$out" in /*) ;; *) out="$src/$out" ;; esac

# --- tools: Debian's pandoc and chromium --------------------------------------------------------------
need=(pandoc)
[ -n "${CHROME_PATH:-}" ] || need+=(chromium)
bash scripts/deps.sh "${need[@]}"
CHROME_PATH="${CHROME_PATH:-$(command -v chromium)}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
t0=$SECONDS

if [ "$checkonly" = 0 ]; then
# The student's README: tools/handout/README.md here, README.md in the handout (handout.sh).
handout_readme=tools/handout/README.md
[ -f "$handout_readme" ] || handout_readme=README.md
# --- the lessons: title, time estimate, points ------------------------------------------------------
rm -rf "$out" && mkdir -p "$out"
cp tools/site/site.css "$out/site.css"
lessons=()
for d in lessons/[0-9][0-9]-*/; do
  [ -f "$d/README.md" ] && lessons+=("$(basename "$d")")
done
[ ${#lessons[@]} -gt 0 ] || { echo "site: no lessons/NN-name/README.md" >&2; exit 1; }

# The navigation bar and the page around the converted Markdown; $1: the way up to the site's root.
nav() {
  local up="$1"
  printf '<nav><a href="%sindex.html">pathspace</a><a href="%sindex.html#schedule">schedule</a>' "$up" "$up"
  printf '<a href="%sstart.html">getting started</a><a href="%sfaq.html">FAQ</a>' "$up" "$up"
  printf '<a href="%shandout.html">the repository</a></nav>\n<main>\n' "$up"
}
: >"$work/links" >"$work/pandoc.log"
# convert SOURCE PAGE TITLE: the Markdown file SOURCE to the site's PAGE (a path ending in .html).
convert() {
  local source="$1" page="$2" title="$3" up
  up=""
  [ "$(dirname "$page")" = . ] || up=$(dirname "$page" | sed 's#[^/][^/]*#..#g; s#$#/#')
  mkdir -p "$out/$(dirname "$page")"
  nav "$up" >"$work/before.html"
  echo '</main>' >"$work/after.html"
  if ! SITE_PAGE="${page%.html}.md" SITE_LINKS="$work/links" pandoc "$source" -f gfm+tex_math_dollars -t html5 -s \
      --mathml --lua-filter tools/site/site.lua --css "${up}site.css" --metadata pagetitle="$title" \
      --include-before-body "$work/before.html" --include-after-body "$work/after.html" -o "$out/$page" 2>"$work/one.log"; then
    echo "site: pandoc failed on $source:" >&2; cat "$work/one.log" >&2; exit 1
  fi
  if [ -s "$work/one.log" ]; then { echo "== $source"; cat "$work/one.log"; } >>"$work/pandoc.log"; fi
}
title_of() { sed -n '1s/^# //p' "$1"; }
time_of() { sed -n 's/^\*Time: about \([0-9][0-9]*\) hours.*/\1/p' "$1" | head -1; }
detail_of() { sed -n 's/^\*Time: about [0-9][0-9]* hours — \([0-9][0-9]*\) to read, \([0-9][0-9]*\) to write.*/\1 + \2/p' "$1" | head -1; }
points_of() { cat tests/"$1"/*.cpp 2>/dev/null | grep -o '\[[0-9][0-9]* pts\{0,1\}\]' | grep -o '[0-9][0-9]*' | awk '{ s += $1 } END { print s + 0 }'; }

# --- the slides -----------------------------------------------------------------------------------
if [ "$slides" = 1 ]; then
  bash scripts/slides.sh --no-pdf --out "$out/slides" >&2
fi

# --- the front page: schedule, then links to the rest ---------------------------------------------
{
  echo "# pathspace — physically based light transport, one piece at a time"
  echo
  sed -n '/^pathspace teaches/,/^$/p' "$handout_readme"
  echo "Start here: [getting started](start.md) (Debian/Ubuntu, macOS, Windows with WSL), then"
  echo "[lesson 0](lessons/${lessons[0]}/README.md). Stuck? [The FAQ](faq.md) has the errors students"
  echo "hit most. [The repository](handout.md): what is where, how you are graded, how to pull the"
  echo "lecturer's fixes and releases."
  echo
  echo "## Schedule"
  echo
  echo "One lesson at a time, in order: each builds on the earlier ones. The time is an estimate for"
  echo "a student who has done the earlier lessons: reading the lesson (theory, task, tests), then"
  echo "writing and testing its pieces."
  echo
  if [ "$slides" = 1 ]; then
    echo "| # | lesson | slides | points | time (read + write) | total so far |"
    echo "|---|---|---|---|---|---|"
  else
    echo "| # | lesson | points | time (read + write) | total so far |"
    echo "|---|---|---|---|---|"
  fi
  total=0 points=0
  for l in "${lessons[@]}"; do
    readme="lessons/$l/README.md"
    t=$(time_of "$readme"); p=$(points_of "$l")
    if [ -z "$t" ]; then
      echo "site: $readme has no line '*Time: about N hours — R to read, W to write and test ...*'" \
        "under its title (the schedule gives every lesson's time estimate)" >&2
      exit 1
    fi
    total=$((total + t)); tcell="about $t h ($(detail_of "$readme"))"
    points=$((points + p))
    name=$(title_of "$readme" | sed 's/^Lesson [0-9]* — //')
    deck=""
    if [ "$slides" = 1 ]; then
      if [ -f "$out/slides/$l.html" ]; then deck="[slides](slides/$l.html) |"; else deck="— |"; fi
    fi
    echo "| $((10#${l:0:2})) | [$name](lessons/$l/README.md) | $deck $p | $tcell | $total h |"
  done
  echo
  echo "In all: ${#lessons[@]} lessons, $points points, about $total hours."
} >"$work/index.md"

# --- the pages --------------------------------------------------------------------------------------
convert "$work/index.md" index.html "pathspace"
convert tools/site/start.md start.html "Getting started — pathspace"
convert tools/site/faq.md faq.html "FAQ — pathspace"
# The handout's README as handout.sh writes it (with the lessons table of the lecturer's README);
# in the handout itself, its README.
if [ "$handout_readme" = README.md ]; then
  cp README.md "$work/handout.md"
else
  table=$(sed -n '/^## Lessons$/,/^## [^L]/p' README.md | sed -n '/^| [0-9]/p')
  awk -v table="$table" '$0 == "@LESSONS@" { print table; next } { print }' "$handout_readme" >"$work/handout.md"
fi
convert "$work/handout.md" handout.html "The repository — pathspace"
for l in "${lessons[@]}"; do
  convert "lessons/$l/README.md" "lessons/$l/README.html" "$(title_of "lessons/$l/README.md") — pathspace"
done
# What the pages link to: Markdown files become pages too (until none is new), images and other
# files are copied. A link from a generated page (index, handout) is relative to the site's root.
done_pages=" index.md start.md faq.md handout.md $(printf 'lessons/%s/README.md ' "${lessons[@]}")"
while :; do
  new=0
  while IFS=$'\t' read -r page target; do
    path="${target%%#*}"
    [ -n "$path" ] || continue
    rel=$(realpath -m --relative-to="$src" "$src/$(dirname "$page")/$path")
    case "$rel" in ../*) continue ;; esac   # outside the repository: the browser check reports it
    case "$done_pages" in *" $rel "*) continue ;; esac
    case "$rel" in
      slides/*.html) ;;   # made by scripts/slides.sh
      *.md)
        if [ -f "$rel" ]; then convert "$rel" "${rel%.md}.html" "$(title_of "$rel") — pathspace"; new=1; fi ;;
      *)
        if [ -f "$rel" ]; then mkdir -p "$out/$(dirname "$rel")"; cp "$rel" "$out/$rel"; fi ;;
    esac
    done_pages+="$rel "
  done <"$work/links"
  [ "$new" = 1 ] || break
done
if grep -q "Could not convert TeX math" "$work/pandoc.log"; then
  echo "site: math that pandoc could not convert:" >&2; cat "$work/pandoc.log" >&2; exit 1
fi
echo "site: $(find "$out" -name '*.html' | wc -l) pages in $out ($((SECONDS - t0)) s)" >&2
fi

# --- the browser check ------------------------------------------------------------------------------
[ -f "$out/index.html" ] || { echo "site: no site in $out (build it first)" >&2; exit 1; }
mkdir -p "$work/check"
{
  echo '<!DOCTYPE html><html><head><meta charset="utf-8"><title>site check</title></head><body>'
  (cd "$out" && find . -name '*.html' | sed 's#^\./##' | sort) | while read -r p; do
    echo "<iframe src=\"file://$out/$p\" title=\"$p\" width=\"1200\" height=\"800\"></iframe>"
  done
  echo "<script>"; cat tools/site/check.js; echo "</script></body></html>"
} >"$work/check/check.html"
# Offline: every host name resolves to nothing, so a page that needs the network shows it.
"$CHROME_PATH" --headless --no-sandbox --disable-gpu --disable-background-networking --no-first-run \
  --no-default-browser-check --disable-extensions --disable-sync --allow-file-access-from-files \
  --host-resolver-rules="MAP * ~NOTFOUND" --user-data-dir="$work/profile" --virtual-time-budget=120000 \
  --dump-dom "file://$work/check/check.html" 2>"$work/chromium.log" >"$work/dom.html" || true
report=$(sed 's/.*BEGIN-REPORT$/BEGIN-REPORT/; s/^END-REPORT.*/END-REPORT/' "$work/dom.html" |
  sed -n '/^BEGIN-REPORT$/,/^END-REPORT$/p' | sed '1d;$d' | sed 's/&amp;/\&/g; s/&lt;/</g; s/&gt;/>/g; s/&quot;/"/g')
[ -n "$report" ] || { echo "site: the browser check got no report from $CHROME_PATH ($work/chromium.log):" >&2; tail -5 "$work/chromium.log" >&2; exit 1; }
pages=$(grep -c '^PAGE ' <<<"$report" || true)
errors=$(grep '^ERROR ' <<<"$report" || true)
sum() { awk -v k="$1" '$1 == "PAGE" { for (i = 3; i < NF; i += 2) if ($i == k) s += $(i + 1) } END { print s + 0 }' <<<"$report"; }
if [ -n "$errors" ]; then
  echo "$errors" | sed 's/^/site: /' >&2
  echo "site: the browser check failed: $(grep -c . <<<"$errors") problem(s) on $pages pages" >&2
  exit 1
fi
echo "site: checked in $("$CHROME_PATH" --version 2>/dev/null | head -1): $pages pages, $(sum images) images, $(sum math) formulas," \
  "$(sum links) links, no broken link, no math error, no missing image, nothing from the network" \
  "($(sum external-links) links to other sites not followed; $((SECONDS - t0)) s)"
