#!/usr/bin/env bash
# Regenerates the approved LaTeX in tests/golden/ from derivations/handout9/*.dc (with the data
# files STEM-figN.dat of the figures the files draw).
# Usage: tools/update-golden.sh [path/to/derivcheck]     (default: build/derivcheck)
# Review the diff (git diff tests/golden) before committing: these files are what
# tests/latex/golden_test.cpp compares the writer's output with, byte for byte.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cli="${1:-$root/build/derivcheck}"
[ -x "$cli" ] || { echo "update-golden: no derivcheck binary at $cli (build it first)" >&2; exit 2; }
mkdir -p "$root/tests/golden"
for f in "$root"/derivations/handout9/*.dc; do
  stem="$(basename "$f" .dc)"
  "$cli" latex "$f" -o "$root/tests/golden/$stem.tex"
done
echo "update-golden: wrote $(ls "$root"/tests/golden/*.tex | wc -l) files to tests/golden/" >&2
