#!/usr/bin/env bash
# Writes every user-visible output of the CLI for every .dc and .jsonl file in the repository
# into OUTDIR, so that a refactoring can be checked byte for byte:
#   tools/snapshot-outputs.sh build/derivcheck /tmp/before    (on the old tree)
#   tools/snapshot-outputs.sh build/derivcheck /tmp/after     (on the new tree)
#   diff -r /tmp/before /tmp/after
# Per .dc: `check` (text), `check --json`, `latex`, `latex --annotate`; per .jsonl: `claims`
# (JSON lines). Exit codes are recorded beside each output. Run from the repository root.
set -uo pipefail
cli=$(realpath "$1"); out=$2
mkdir -p "$out"
root=$(pwd)
n=0
while IFS= read -r f; do
  key=$(echo "$f" | sed 's|^\./||; s|/|__|g')
  case "$f" in
    *.dc)
      "$cli" check "$f" --jobs 1 > "$out/$key.check.txt" 2>&1; echo "exit $?" >> "$out/$key.check.txt"
      "$cli" check "$f" --json --jobs 1 > "$out/$key.check.json" 2>&1; echo "exit $?" >> "$out/$key.check.json"
      "$cli" latex "$f" -o "$out/$key.tex" > "$out/$key.latex.log" 2>&1; echo "exit $?" >> "$out/$key.latex.log"
      "$cli" latex "$f" --annotate -o "$out/$key.annotated.tex" > /dev/null 2>&1
      n=$((n + 4));;
    *.jsonl)
      "$cli" claims "$f" --jobs 1 --no-timings > "$out/$key.claims.jsonl" 2>&1; echo "exit $?" >> "$out/$key.claims.jsonl"
      n=$((n + 1));;
  esac
done < <(cd "$root" && find . \( -name '*.dc' -o -name '*.jsonl' \) -not -path './build*' -not -path './.git/*' | sort)
"$cli" check derivations/handout9/ --jobs 2 > "$out/handout9-dir.check.txt" 2>&1; echo "exit $?" >> "$out/handout9-dir.check.txt"
"$cli" latex derivations/handout9/ -o "$out/handout9-dir.tex" > /dev/null 2>&1
echo "snapshot: $((n + 2)) outputs in $out" >&2
