#!/usr/bin/env bash
# A case's HTML report opened in a real browser (headless Chromium): every plot of report.md must
# be in the page and render with a size. A control page with one plot taken out must be caught, so
# the check itself is known to fail when a plot is missing.
# usage: check_report_html.sh BLADEBENCH CASE.toml WORK_DIR
set -euo pipefail
bin=$1 case_file=$2 work=$3
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
  echo "FAIL: no chromium on PATH (Debian package chromium; ./run.sh installs it)" >&2
  exit 1
fi
rm -rf "$work" && mkdir -p "$work"
"$bin" run "$case_file" --out "$work/report" --no-cache >/dev/null
page=$work/report/report.html
[ -s "$page" ] || { echo "FAIL: no report.html in $work/report" >&2; exit 1; }
expected=$(grep -o '!\[' "$work/report/report.md" | wc -l)
[ "$expected" -gt 0 ] || { echo "FAIL: report.md has no plots to check" >&2; exit 1; }

# The verdict the page writes into itself once loaded: images, and how many failed to render.
probe_script='<script>
window.addEventListener("load", () => {
  const images = Array.from(document.images);
  const missing = images.filter(i => !(i.complete && i.naturalWidth > 0 && i.naturalHeight > 0));
  const out = document.createElement("pre");
  out.id = "verdict";
  out.textContent = "verdict images=" + images.length + " missing=" + missing.length;
  document.body.appendChild(out);
});
</script>'
probe() {  # $1: page to load; prints "images=N missing=M"
  local copy=$work/probe-$(basename "$1")
  { sed 's|</body>||; s|</html>||' "$1"; printf '%s\n</body>\n</html>\n' "$probe_script"; } > "$copy"
  "$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking \
    --disable-component-update --disable-sync --user-data-dir="$work/profile" --virtual-time-budget=10000 \
    --dump-dom "file://$copy" 2>"$work/chromium.log" | grep -o 'verdict images=[0-9]* missing=[0-9]*' | sed 's/verdict //'
}

got=$(probe "$page")
echo "report.html: $got (report.md has $expected plots)"
[ "$got" = "images=$expected missing=0" ] || { echo "FAIL: expected images=$expected missing=0" >&2; exit 1; }

# Control: the first plot replaced by a file that does not exist must be reported missing.
sed '0,/src="data:image\/svg+xml;base64,[^"]*"/s//src="plots\/no-such-plot.svg"/' "$page" > "$work/control.html"
got=$(probe "$work/control.html")
echo "control page with one plot removed: $got"
[ "$got" = "images=$expected missing=1" ] || { echo "FAIL: the check did not see the removed plot" >&2; exit 1; }

# And a picture of the page, as a user would see it (kept in the work folder).
"$browser" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking \
  --disable-component-update --disable-sync --user-data-dir="$work/profile" --window-size=1200,2400 \
  --screenshot="$work/report.png" "file://$page" 2>>"$work/chromium.log" >/dev/null
[ -s "$work/report.png" ] || { echo "FAIL: chromium wrote no screenshot" >&2; exit 1; }
echo "screenshot: $work/report.png ($(stat -c %s "$work/report.png") bytes)"
