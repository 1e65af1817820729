#!/usr/bin/env bash
# Builds the lecture decks slides/NN-*.md to self-contained HTML and to PDF, offline, with the Marp CLI
# (version pinned in slides/package-lock.json), then checks that no slide's content overflows its page.
#
#   bash scripts/slides.sh [--out DIR] [--no-pdf] [--check-only] [NN ...]
#
#   NN ...        only these decks (e.g. 04 07); default: every deck
#   --out DIR     write DIR/NN-name.html, DIR/NN-name.pdf and DIR/figures/ (default: build/slides)
#   --no-pdf      HTML only (faster)
#   --check-only  only the overflow check: nothing is written to --out
#
# Needs node >= 18 with npm (installs @marp-team/marp-cli into slides/node_modules with `npm ci`) and
# Debian's chromium (installed with apt-get if missing, like scripts/deps.sh; set CHROME_PATH to use
# another Chrome/Chromium). No browser is ever downloaded through npm. Math is rendered by MathJax to
# SVG, so the HTML needs no network. The images a deck shows are copied to DIR/figures/.
set -euo pipefail
cd "$(dirname "$0")/.."
src="$PWD"
out="build/slides" pdf=1 checkonly=0 only=()
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out="$2"; shift ;;
    --no-pdf) pdf=0 ;;
    --check-only) checkonly=1 ;;
    -h|--help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    [0-9][0-9]) only+=("$1") ;;
    *) echo "slides: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
case "$out" in /*) ;; *) out="$src/$out" ;; esac

# --- tools: node + npm, chromium (Debian package), the pinned Marp CLI -----------------------------
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  echo "slides: node (>= 18) and npm are needed; on Debian 12: apt-get install nodejs npm" >&2; exit 1
fi
if [ -z "${CHROME_PATH:-}" ]; then
  bash scripts/deps.sh chromium   # apt-get as root or through sudo, else the line to run
  CHROME_PATH="$(command -v chromium)"
fi
export CHROME_PATH
# Never let puppeteer fetch a browser of its own (marp-cli only uses puppeteer-core, this is a guard).
export PUPPETEER_SKIP_DOWNLOAD=1 PUPPETEER_SKIP_CHROMIUM_DOWNLOAD=1
marp() { "$src/slides/node_modules/.bin/marp" --config-file "$src/slides/.marprc.yml" "$@"; }
stamp="$src/slides/node_modules/.package-lock.json"
if [ ! -x "$src/slides/node_modules/.bin/marp" ] || [ "$src/slides/package-lock.json" -nt "$stamp" ]; then
  echo "slides: npm ci (slides/package-lock.json)" >&2
  (cd "$src/slides" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
fi

# --- stage the decks: image links ../lessons/NN-name/file become figures/NN-name/file ---------------
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/md" "$work/check" "$work/figures"
decks=()
for f in slides/[0-9][0-9]-*.md; do
  nn="$(basename "$f")"; nn="${nn%%-*}"
  if [ ${#only[@]} -gt 0 ]; then
    keep=0; for n in "${only[@]}"; do [ "$n" = "$nn" ] && keep=1; done
    [ "$keep" = 1 ] || continue
  fi
  decks+=("$(basename "$f" .md)")
  sed 's#](\.\./lessons/#](figures/#g' "$f" > "$work/md/$(basename "$f")"
  for link in $(grep -o '](\.\./lessons/[^)]*)' "$f" | sed 's/^](\.\.\/lessons\///; s/)$//' | sort -u); do
    if [ ! -f "lessons/$link" ]; then echo "slides: $f shows lessons/$link, which does not exist" >&2; exit 1; fi
    mkdir -p "$work/figures/$(dirname "$link")"; cp "lessons/$link" "$work/figures/$link"
  done
done
[ ${#decks[@]} -gt 0 ] || { echo "slides: no deck matches ${only[*]}" >&2; exit 2; }
ln -s ../figures "$work/md/figures"
ln -s ../figures "$work/check/figures"

# --- build ------------------------------------------------------------------------------------------
t0=$SECONDS
if [ "$checkonly" = 0 ]; then
  mkdir -p "$out/figures"
  cp -R "$work/figures/." "$out/figures/"
  marp --no-stdin --quiet --input-dir "$work/md" --output "$out" 2>/dev/null
  if [ "$pdf" = 1 ]; then
    marp --no-stdin --quiet --allow-local-files --pdf --input-dir "$work/md" --output "$out" 2>/dev/null
  fi
fi

# --- overflow check: every slide's content must fit its fixed-size section ------------------------
# Marp renders each slide as a fixed 1280x720 <section>; content that does not fit makes the
# section's scrollHeight (content + bottom padding) or scrollWidth larger than the section. The
# bare template shows every slide at once; one page loads every deck in an iframe, measures every
# section and writes the numbers into its DOM, which headless chromium prints (one browser start).
marp --no-stdin --quiet --template bare --input-dir "$work/md" --output "$work/check" 2>/dev/null
{
  for d in "${decks[@]}"; do echo "<iframe src=\"$d.html\" title=\"$d\" width=\"1280\" height=\"720\"></iframe>"; done
  cat <<'EOF'
<script>
window.addEventListener('load', function () {
  var lines = [];
  document.querySelectorAll('iframe').forEach(function (f) {
    var doc = f.contentDocument;
    if (!doc) { lines.push('deck ' + f.title + ' unreadable'); return; }
    lines.push('deck ' + f.title);
    doc.querySelectorAll('svg[data-marpit-svg] > foreignObject > section').forEach(function (s, i) {
      var dy = s.scrollHeight - s.clientHeight, dx = s.scrollWidth - s.clientWidth;
      s.querySelectorAll('pre, table').forEach(function (e) { dx = Math.max(dx, e.scrollWidth - e.clientWidth); });
      lines.push('slide ' + (i + 1) + ' ' + dy + ' ' + dx);
    });
  });
  var pre = document.createElement('pre');
  pre.textContent = 'BEGIN-REPORT ' + lines.join(' ') + ' END-REPORT';
  document.body.appendChild(pre);
});
</script>
EOF
} > "$work/check/measure.html"
report="$("$CHROME_PATH" --headless --no-sandbox --disable-gpu --allow-file-access-from-files \
  --user-data-dir="$work/profile" --dump-dom "file://$work/check/measure.html" 2>/dev/null |
  grep -o 'BEGIN-REPORT deck.* END-REPORT' || true)"
bad=0 deck="" nslides=0
[ -n "$report" ] || { echo "slides: the overflow check got no report from $CHROME_PATH" >&2; exit 1; }
set -- ${report#BEGIN-REPORT }
while [ "$1" != END-REPORT ]; do
  case "$1" in
    deck)
      deck="$2"; shift 2
      if [ "$1" = unreadable ]; then echo "slides: the overflow check could not read $deck" >&2; bad=1; shift; fi ;;
    slide)
      nslides=$((nslides + 1))
      if [ "$3" -gt 0 ] || [ "$4" -gt 0 ]; then
        msg=""; [ "$3" -gt 0 ] && msg="${3}px too tall"; [ "$4" -gt 0 ] && msg="${msg:+$msg, }${4}px too wide"
        echo "slides: OVERFLOW slides/$deck.md slide $2: $msg" >&2; bad=1
      fi
      shift 4 ;;
    *) echo "slides: unexpected overflow report near '$1'" >&2; exit 1 ;;
  esac
done
[ "$nslides" -gt 0 ] || { echo "slides: the overflow check measured no slide" >&2; exit 1; }
if [ "$bad" != 0 ]; then
  echo "slides: some slides overflow (split, shorten, or make the math smaller)" >&2; exit 1
fi
if [ "$checkonly" = 1 ]; then
  echo "slides: ${#decks[@]} deck(s), $nslides slides checked, no slide overflows ($((SECONDS - t0)) s)"
else
  echo "slides: ${#decks[@]} deck(s) in $out ($([ "$pdf" = 1 ] && echo 'HTML + PDF' || echo HTML)), no slide overflows ($((SECONDS - t0)) s)"
fi
