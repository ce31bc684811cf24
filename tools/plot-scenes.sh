#!/bin/sh
# Regenerates the scene figures in docs/charts/ from `derivcheck simulate`:
#   scene_NAME.csv (data), scene_NAME.tex (pgfplots tikzpicture to \input), scene_NAME.gp
#   (gnuplot script) and scene_NAME.png. Every file is written atomically (temporary + rename).
# Usage: tools/plot-scenes.sh [path/to/derivcheck]   (run from the repository root)
set -eu
BIN=${1:-build/derivcheck}
OUT=docs/charts
mkdir -p "$OUT"
plot() {  # plot NAME [simulate options...]
  name=$1; shift
  "$BIN" simulate "$name" "$@" --csv "$OUT/scene_$name.csv" --pgfplots "$OUT/scene_$name.tex" \
    --gnuplot "$OUT/scene_$name.gp" > /dev/null
  gnuplot "$OUT/scene_$name.gp" > "$OUT/scene_$name.png.tmp.$$"
  mv "$OUT/scene_$name.png.tmp.$$" "$OUT/scene_$name.png"
  echo "$OUT/scene_$name.png"
}
plot spring --method rk4 --step 0.01      # Example 9.3: x1, x2 erratic, x_G a straight line
plot chain --method rk4 --step 0.001      # Example 9.7: N against 3xmg/L
plot rocket --method rk4 --step 0.1       # §9.4: v(t) against the closed form
plot ladder --method rk4 --step 0.001     # Example 9.2: wall and floor reactions
plot pendulum --method rk4 --step 0.001   # Example 9.5: the swing to theta_max
plot bounce                               # Example 9.6: heights of the two balls (events)
