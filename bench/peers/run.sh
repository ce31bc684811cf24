#!/usr/bin/env bash
# The peers, side by side in one run (issue 5, part 3):
#   1. `derivcheck check derivations/handout9/` vs the same claims in SymPy (process wall time);
#   2. closed-form evaluation: SymPy lambdify + NumPy vs derivcheck's default batch path (the
#      JIT) vs hand-written C++, repeats interleaved, medians (docs/charts/peer_eval.csv:
#      formula,tool,ns_per_eval_median);
#   3. the scenes in SciPy solve_ivp (RK45, DOP853, LSODA) vs derivcheck's integrators at
#      equal accuracy.
# Writes docs/charts/peer_*.csv and the "Peers" section of docs/performance.md (between the
# <!-- peers:begin --> / <!-- peers:end --> markers). Parts whose derivcheck side has not been
# built yet print "not available yet" instead of a number.
#
# Usage:  bench/peers/run.sh [--quick] [--repeats N] [--points N] [--build-dir DIR]
#   --quick      3 repeats (7 for the cheap evaluation part), 200000 evaluation points
#                (about a minute once derivcheck is built)
#   --repeats N  timing repeats per measurement (default 5)
#   --points N   evaluation points per formula (default 1000000)
# Needs: tools/install-peers.sh (python3-sympy, python3-numpy, python3-scipy from Debian).
# Builds the derivcheck CLI (Release) in --build-dir (default build-peers) if needed.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD="$ROOT/build-peers"
REPEATS=5
EVAL_REPEATS=""
POINTS=1000000
PY="${PYTHON:-/usr/bin/python3}"
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) REPEATS=3; EVAL_REPEATS=7; POINTS=200000 ;;
    --repeats) REPEATS="$2"; EVAL_REPEATS="$2"; shift ;;
    --points) POINTS="$2"; shift ;;
    --build-dir) BUILD="$(cd "$ROOT" && realpath -m "$2")"; shift ;;
    -h|--help) sed -n '2,19p' "$0"; exit 0 ;;
    *) echo "run.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
"$PY" -c "import sympy, numpy, scipy" 2>/dev/null || {
  echo "run.sh: $PY lacks sympy/numpy/scipy; run tools/install-peers.sh (or set PYTHON)" >&2; exit 2; }

say() { [ -t 2 ] && echo "peers: $*" >&2 || true; }
say "building derivcheck in $BUILD"
if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  cmake -S "$ROOT" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DDERIVCHECK_TESTS=OFF -DDERIVCHECK_BENCH=OFF >/dev/null
fi
CLI="$BUILD/derivcheck"
cmake --build "$BUILD" --target derivcheck -j2 >/dev/null 2>"$BUILD/peers-build.log" ||
  echo "run.sh: derivcheck did not build (see $BUILD/peers-build.log); its side reads 'not available yet'" >&2
BUILD_TYPE="$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$BUILD/CMakeCache.txt")"
CXX_ID="$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$BUILD/CMakeCache.txt")"
CXX_VER="$("$CXX_ID" -dumpfullversion 2>/dev/null || echo '?')"
MACHINE="$(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores, $(uname -sr)"

TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
HANDOUT="$ROOT/derivations/handout9"
say "1/3 handout check vs SymPy ($REPEATS runs each)"
"$PY" "$ROOT/bench/peers/peer_check.py" --cli "$CLI" --python "$PY" --repeats "$REPEATS" "$HANDOUT" > "$TMP/check.json"
say "2/3 evaluator vs NumPy ($POINTS points)"
# NumPy is timed inside peer_eval.py: OPENBLAS_CORETYPE / OPENBLAS_L2_SIZE (set on some CI
# machines) are unset for this command only.
env -u OPENBLAS_CORETYPE -u OPENBLAS_L2_SIZE \
"$PY" "$ROOT/bench/peers/peer_eval.py" --cli "$CLI" --n "$POINTS" --repeats "${EVAL_REPEATS:-$REPEATS}" --tmp "$TMP" \
  "$HANDOUT/05_direct_impact.dc:v1p_general" \
  "$HANDOUT/05_direct_impact.dc:energy_loss_general" \
  "$HANDOUT/06_ballistic_pendulum.dc:deflection" \
  "$HANDOUT/07_two_ball_bounce.dc:v1p_bounce" \
  "$HANDOUT/03_ladder.dc:wall_impulse" > "$TMP/eval.json"
say "3/3 scenes vs SciPy solve_ivp"
"$PY" "$ROOT/bench/peers/peer_scenes.py" --cli "$CLI" --repeats "$REPEATS" \
  --csv "$TMP/scipy_sweep.csv" --dc-csv "$TMP/dc_sweep.csv" > "$TMP/scenes.json"
# both sweeps in one CSV (docs/charts/peer_scenes_sweep.csv)
{
  cat "$TMP/scipy_sweep.csv"
  if [ -f "$TMP/dc_sweep.csv" ]; then
    "$PY" - "$TMP/dc_sweep.csv" <<'PYEOF'
import csv, sys
for r in csv.DictReader(open(sys.argv[1])):
    print(",".join([r["scene"], "derivcheck", r["method"], r["param"], r["rel_error"],
                    r["seconds_median"], r["seconds_min"], r["seconds_max"]]))
PYEOF
  fi
} > "$TMP/sweep.csv"
mkdir -p "$ROOT/docs/charts"
mv "$TMP/sweep.csv" "$ROOT/docs/charts/peer_scenes_sweep.csv.tmp"
mv "$ROOT/docs/charts/peer_scenes_sweep.csv.tmp" "$ROOT/docs/charts/peer_scenes_sweep.csv"
"$PY" "$ROOT/bench/peers/peer_report.py" --root "$ROOT" --check "$TMP/check.json" --eval "$TMP/eval.json" \
  --scenes "$TMP/scenes.json" --machine "$MACHINE" \
  --build "$BUILD_TYPE, g++ $CXX_VER, SymPy/NumPy/SciPy $("$PY" -c 'import sympy,numpy,scipy;print(sympy.__version__+"/"+numpy.__version__+"/"+scipy.__version__)')" \
  --command "bench/peers/run.sh --repeats $REPEATS --points $POINTS"
