#!/usr/bin/env bash
# Screenshots of the validation report (report.html) in headless Chromium, for a developer to
# look at before trusting it (issue 34): the page as a browser lays it out, not as its HTML
# reads. Shots: the top (summary, sources), the table, a narrow window, and the sections of
# the first entries with plots, of every failure and of the first findings.
#
#   bash scripts/report_screenshots.sh          # runs build/magfem validate --tier quick first
#   bash scripts/report_screenshots.sh DIR      # an existing report folder (DIR/report.html)
#
# Writes build/report_screenshots/*.png (the folder is emptied first) and prints the page
# height in pixels. Needs Debian's chromium (apt-get install chromium).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
out="$root/build/report_screenshots"

browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "report_screenshots: no chromium on the PATH (apt-get install chromium)" >&2
  exit 2
fi

if [ $# -ge 1 ]; then
  report_dir=$(cd "$1" && pwd)
else
  report_dir="$root/build/validate_quick"
  # Exit 4 means an entry failed: the report is written and is what there is to look at.
  rc=0
  "$root/build/magfem" validate --tier quick --out "$report_dir" || rc=$?
  if [ "$rc" -ne 0 ] && [ "$rc" -ne 4 ]; then
    echo "report_screenshots: magfem validate exited $rc" >&2
    exit "$rc"
  fi
fi
html="$report_dir/report.html"
[ -f "$html" ] || { echo "report_screenshots: no $html" >&2; exit 2; }

rm -rf "$out"
mkdir -p "$out"
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT

# Flags keep the run offline and quiet: no sandbox (root in containers), no first-run work.
chrome() {
  "$browser" --headless --no-sandbox --disable-gpu --disable-background-networking \
    --disable-component-update --disable-sync --no-first-run --hide-scrollbars \
    --user-data-dir="$profile" "$@" 2> /dev/null
}

# shot NAME ANCHOR [WIDTH,HEIGHT]: the page with the element #ANCHOR at the top ("" for the
# top of the page). Headless Chromium paints nothing below its first screen when a page is
# scrolled (by #fragment or script), so a copy of the page moves its body up instead: the
# same layout, the part asked for in view.
shot() {
  local page="$html"
  if [ -n "$2" ]; then
    page="$profile/$1.html"
    sed "s|</body>|<script>var t = document.getElementById('$2'); document.body.style.transform = 'translateY(-' + (t.getBoundingClientRect().top - 8) + 'px)';</script></body>|" \
      "$html" > "$page"
  fi
  chrome --screenshot="$out/$1.png" --window-size="${3:-1280,2000}" "file://$page" > /dev/null
  echo "  $out/$1.png"
}

# Entry ids: the first section with a figure from each source, every failure, the first two
# findings.
anchors=$(awk '
  /<section class=entry id="/ { match($0, /id="[^"]*"/); id = substr($0, RSTART + 4, RLENGTH - 5) }
  /<dt>Source<\/dt><dd><a href="#src-/ { match($0, /#src-[^"]*/); src = substr($0, RSTART, RLENGTH) }
  /<figure>/ && id != "" && !seen_fig[id]++ && !seen_src[src]++ { print "plot " id }
  /<h3><span class="badge fail">/ { print "fail " id }
  /<h3><span class="badge finding">/ && n_find < 2 { n_find++; print "finding " id }
' "$html")

echo "screenshots of $html:"
shot 01_top ""
shot 02_table table
shot 03_narrow "" 800,1400
k=4
while read -r kind id; do
  [ -n "$id" ] || continue
  shot "$(printf '%02d' "$k")_${kind}_${id}" "$id"
  k=$((k + 1))
done <<< "$anchors"

# The page height, measured by the browser: a copy that writes it into its title.
probe="$profile/height.html"
sed 's|</body>|<script>document.title = "height " + document.documentElement.scrollHeight</script></body>|' \
  "$html" > "$probe"
height=$(chrome --dump-dom --window-size=1280,2000 "file://$probe" | grep -o '<title>height [0-9]*' | grep -o '[0-9]*$' || true)
echo "page height at 1280 px: ${height:-unknown} px"
