#!/usr/bin/env bash
# Renders a demscale report in headless Chromium and writes a full-page PNG screenshot, to look at
# the report as a reader's browser shows it. Installs Debian's chromium if it is missing.
# Usage: tools/screenshot-report.sh [REPORT_HTML] [OUT_PNG]   (default: report/report.html → report/screenshot.png)
set -euo pipefail
html=$(realpath "${1:-report/report.html}")
out=${2:-$(dirname "$html")/screenshot.png}
[ -s "$html" ] || { echo "screenshot-report: no report at $html (run: build/demscale report --quick)" >&2; exit 2; }
if ! command -v chromium >/dev/null; then
  sudo_cmd=""; [ "$(id -u)" -eq 0 ] || sudo_cmd=sudo
  $sudo_cmd apt-get install -y -qq chromium >/dev/null
fi
# Tall enough for the whole report; Chromium cuts the page at the window height.
height=${SCREENSHOT_HEIGHT:-16000}
log=$(mktemp)
trap 'rm -f "$log"' EXIT
chromium --headless=new --no-sandbox --disable-gpu --hide-scrollbars --allow-file-access-from-files \
  --window-size=1280,"$height" --screenshot="$out.tmp.png" "file://$html" >"$log" 2>&1 || { cat "$log" >&2; exit 3; }
# Fail on page errors Chromium reports (a broken image, a script or CSS error); ignore its own chatter.
if grep -Ei 'ERR_FILE_NOT_FOUND|Uncaught|Failed to load' "$log" >&2; then rm -f "$out.tmp.png"; exit 3; fi
mv "$out.tmp.png" "$out"
echo "wrote $out"
