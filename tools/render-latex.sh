#!/usr/bin/env bash
# Emits Handout 9 as LaTeX, compiles it with pdflatex and renders to docs/img/:
#   handout9-page1.png            page 1 (title, prose, the first chains)
#   handout9-example.png          the page where the ballistic pendulum example starts
#   handout9-annotated-page1.png  page 1 of the --annotate version
#   handout9-plot.png             the page with the ballistic pendulum's plot (a figure drawn
#                                 from the file's formula, docs/latex.md "Figures")
# Usage: tools/render-latex.sh [path/to/derivcheck]     (default: build/derivcheck)
# Needs pdflatex and pdftoppm (tools/install-deps.sh installs both).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cli="${1:-$root/build/derivcheck}"
[ -x "$cli" ] || { echo "render-latex: no derivcheck binary at $cli (build it first)" >&2; exit 2; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
title="Handout 9 – Linear Momentum, Impact and Rockets"
sub="Every equation generated from derivations/handout9/*.dc and checked by derivcheck"
"$cli" latex "$root/derivations/handout9" --title "$title" --subtitle "$sub" -o "$tmp/handout9.tex"
"$cli" latex "$root/derivations/handout9" --title "$title" --subtitle "$sub" --annotate -o "$tmp/handout9-annotated.tex"
mkdir -p "$root/docs/img"
for name in handout9 handout9-annotated; do
  (cd "$tmp" && pdflatex -halt-on-error -interaction=nonstopmode "$name.tex" > "$name.build.log" 2>&1 &&
                pdflatex -halt-on-error -interaction=nonstopmode "$name.tex" > "$name.build.log" 2>&1) ||
    { echo "render-latex: pdflatex failed on $name.tex; see the log:" >&2; tail -20 "$tmp/$name.build.log" >&2; exit 1; }
  pdftoppm -r 100 -f 1 -l 1 -png -singlefile "$tmp/$name.pdf" "$root/docs/img/$name-page1"
  echo "render-latex: docs/img/$name-page1.png ($(pdfinfo "$tmp/$name.pdf" 2>/dev/null | awk '/^Pages/{print $2}') pages)" >&2
done
# the first page whose text has `needle`, rendered to docs/img/NAME.png
render_page_with() {
  local needle="$1" name="$2" pages p
  pages=$(pdfinfo "$tmp/handout9.pdf" | awk '/^Pages/{print $2}')
  for ((p = 1; p <= pages; ++p)); do
    if pdftotext -f "$p" -l "$p" "$tmp/handout9.pdf" - | grep -qi "$needle"; then
      pdftoppm -r 100 -f "$p" -l "$p" -png -singlefile "$tmp/handout9.pdf" "$root/docs/img/$name"
      echo "render-latex: docs/img/$name.png (page $p)" >&2
      return 0
    fi
  done
  echo "render-latex: no page with '$needle'" >&2
  return 1
}
render_page_with "Example 9.5" handout9-example            # the worked example (ballistic pendulum)
render_page_with "The largest swing angle" handout9-plot   # its figure drawn from the formula
