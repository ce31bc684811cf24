#!/usr/bin/env bash
# Checks a claim bank in SHARDS pieces with GNU parallel (on this machine, or on many with
# --sshlogin), then merges the pieces into one result file, byte-identical to an unsharded
# `derivcheck claims --no-timings` run. Documented in docs/scaling.md.
#
#   tools/cluster/claims-parallel.sh BANK.jsonl SHARDS OUT.jsonl [GNU parallel options...]
#
# Examples
#   tools/cluster/claims-parallel.sh bank.jsonl 8 results.jsonl                 # 8 shards here
#   tools/cluster/claims-parallel.sh bank.jsonl 64 results.jsonl \
#       --sshlogin 16/node1,16/node2 --transferfile bank.jsonl                  # 64 over two hosts
#
# Each shard runs `derivcheck claims BANK --shard K/SHARDS --jobs 1` (GNU parallel provides the
# parallelism, one job per core slot). DERIVCHECK names the binary (default: derivcheck on PATH;
# it must exist on every host). The exit code is that of `derivcheck claims` on the whole
# bank (0 all hold, 1 some refuted, 2 some malformed line, 3 some undecided); 4 when a shard
# itself failed (its exit code was not a verdict), with the shard named on stderr.
set -uo pipefail
if [ $# -lt 3 ]; then
  sed -n '2,20p' "$0" >&2
  exit 2
fi
bank=$1 shards=$2 out=$3
shift 3
dc=${DERIVCHECK:-derivcheck}
case $shards in '' | *[!0-9]*) echo "claims-parallel: SHARDS must be a positive integer, got '$shards'" >&2; exit 2 ;; esac
[ "$shards" -ge 1 ] || { echo "claims-parallel: SHARDS must be at least 1" >&2; exit 2; }
work=$(mktemp -d "$(dirname "$out")/.claims-parallel.XXXXXX") || exit 4
trap 'rm -rf "$work"' EXIT INT TERM

# One job per shard. --results stores each shard's standard output in a local file (also
# when the shard ran on another host over ssh); the job log records every exit code.
parallel --joblog "$work/joblog" --results "$work/shard-{}.jsonl" "$@" \
  "$dc" claims "$bank" --shard {}/"$shards" --jobs 1 --no-timings --no-progress \
  ::: $(seq 1 "$shards") > /dev/null

# Exit codes 0-3 are verdicts; anything else means a shard did not run to the end.
failed=$(awk 'NR > 1 && ($7 > 3 || $8 != 0) { print $NF }' FS='\t' "$work/joblog")
if [ -n "$failed" ]; then
  echo "claims-parallel: these shards failed (see $work/joblog):" >&2
  echo "$failed" >&2
  trap - EXIT
  exit 4
fi
"$dc" merge "$work"/shard-*.jsonl > "$work/merged.jsonl"
rc=$?
[ $rc -le 3 ] || exit 4
mv "$work/merged.jsonl" "$out"
exit $rc
