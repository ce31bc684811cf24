#!/usr/bin/env bash
# Writes Handout 9 as its checked web page and takes a screenshot of it in headless Chromium:
#   docs/img/handout9-web.png     the top of the page at 1200 x 1600 (title, contents, §9.1)
# Usage: tools/render-html.sh [path/to/derivcheck]     (default: build/derivcheck)
# Needs chromium and libjs-katex (tools/install-deps.sh installs both).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cli="${1:-$root/build/derivcheck}"
[ -x "$cli" ] || { echo "render-html: no derivcheck binary at $cli (build it first)" >&2; exit 2; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
title="Handout 9 – Linear Momentum, Impact and Rockets"
sub="Every equation generated from derivations/handout9/*.dc and checked by derivcheck"
"$cli" html "$root/derivations/handout9" --title "$title" --subtitle "$sub" -o "$tmp/site"
mkdir -p "$root/docs/img"
chromium --headless --disable-gpu --no-sandbox --no-first-run --user-data-dir="$tmp/profile" \
  --hide-scrollbars --window-size=1200,1600 --virtual-time-budget=10000 \
  --screenshot="$root/docs/img/handout9-web.png" "file://$tmp/site/index.html" > "$tmp/chromium.log" 2>&1 ||
  { echo "render-html: chromium failed; its log:" >&2; tail -20 "$tmp/chromium.log" >&2; exit 1; }
echo "render-html: docs/img/handout9-web.png" >&2
