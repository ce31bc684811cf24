#!/usr/bin/env bash
# Claims throughput and memory of `derivcheck claims` (figures in docs/performance.md,
# "Claim banks"): a generated bank (tools/gen-claim-bank.py) checked with --jobs 1 and
# --jobs N, reporting wall time, CPU time of all processes, claims per second and per
# core-second, the peak memory of the parent, and whether the outputs are byte-identical.
# Run it on an otherwise idle machine: wall-clock speedups mean nothing under load.
#
#   bench/scaling/claims-throughput.sh [CLAIMS=100000] [JOBS=all cores] [DERIVCHECK=build/derivcheck]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
n=${1:-100000}
jobs=${2:-$(nproc)}
dc=${3:-$root/build/derivcheck}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$root/tools/gen-claim-bank.py" "$n" > "$work/bank.jsonl"
echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; bank: $n claims"
for j in 1 "$jobs"; do
  /usr/bin/time -f "%e %U %S %M" -o "$work/time.$j" "$dc" claims "$work/bank.jsonl" --no-timings --no-progress \
    --jobs "$j" > "$work/out.$j.jsonl" || true
  read -r wall user sys rss < <(tail -1 "$work/time.$j")
  awk -v n="$n" -v j="$j" -v w="$wall" -v u="$user" -v s="$sys" -v r="$rss" 'BEGIN {
    printf "jobs=%-3d wall %8.1f s  cpu %8.1f s  %8.0f claims/s  %8.0f claims/core-s  parent peak %6.1f MiB\n",
           j, w, u + s, n / w, n / (u + s), r / 1024 }'
done
if [ "$jobs" != 1 ]; then
  cmp -s "$work/out.1.jsonl" "$work/out.$jobs.jsonl" && echo "outputs byte-identical" || echo "OUTPUTS DIFFER"
  w1=$(tail -1 "$work/time.1" | cut -d' ' -f1); wj=$(tail -1 "$work/time.$jobs" | cut -d' ' -f1)
  awk -v a="$w1" -v b="$wj" -v j="$jobs" 'BEGIN { printf "speedup at %d jobs: %.2fx\n", j, a / b }'
fi
echo "verdicts: $(grep -o '"verdict":"[a-z_]*"' "$work/out.1.jsonl" | sort | uniq -c | tr '\n' ' ')"
