#!/usr/bin/env bash
# One command: build the libFuzzer harnesses (bench/fuzz) and run them.
#   tools/fuzz.sh [TARGET|all] [RUNS] [extra libFuzzer flags...]
#     TARGET  reader | parse | dc_file | expr | assume | assume_sat | claims | all (default all)
#             (reader, parse: the .dc reader and the expression parser alone, thousands of inputs
#             per second; the others go on into GiNaC and the checker, 10-300 per second)
#     RUNS    executions per target (default 1000000; -1 = until stopped or a crash)
#   e.g. tools/fuzz.sh expr 2000000       tools/fuzz.sh claims 200000 -max_total_time=3600
#   SESSION=N: executions per fuzzer process (default 250000; see below), JOBS=N: build jobs
# Configures build-fuzz/ with clang-14 and -DDERIVCHECK_FUZZ=ON (libraries instrumented with
# -fsanitize=fuzzer-no-link,address,undefined), builds at nice 10, seeds each target from the
# repository's derivations and test data (build-fuzz/seeds/), keeps the grown corpus in
# build-fuzz/corpus/TARGET, writes crashing inputs to build-fuzz/crashes/TARGET/ and the log to
# build-fuzz/logs/TARGET.N.log (session N). Exit status is non-zero when any target found a crash.
# Reproduce a crash: build-fuzz/bench/fuzz/fuzz_TARGET build-fuzz/crashes/TARGET/crash-...
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build-fuzz}"
jobs="${JOBS:-2}"
target="${1:-all}"
runs="${2:-1000000}"
shift $(( $# > 2 ? 2 : $# ))
cd "$root"

all_targets=(reader parse dc_file expr assume assume_sat claims)
if [ "$target" = all ]; then targets=("${all_targets[@]}"); else targets=("$target"); fi
for t in "${targets[@]}"; do
  [ -f "bench/fuzz/fuzz_$t.cpp" ] || { echo "fuzz.sh: unknown target '$t' (one of ${all_targets[*]}, all)" >&2; exit 2; }
done

command -v clang++-14 >/dev/null || { echo "fuzz.sh: clang++-14 missing (sudo apt-get install -y clang-14 libclang-rt-14-dev)" >&2; exit 2; }
CC=clang-14 CXX=clang++-14 nice -n 10 cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DDERIVCHECK_FUZZ=ON -DDERIVCHECK_TESTS=OFF -DDERIVCHECK_BENCH=OFF >/dev/null
nice -n 10 cmake --build "$build" -j"$jobs" --target $(printf 'fuzz_%s ' "${targets[@]}")

# --- seeds from the repository (regenerated every run, in a directory of this run's own so
# that runs of different targets can go on side by side; the grown corpus is kept) --------
seeds="$build/seeds.$$"
trap 'rm -rf "$seeds"' EXIT
rm -rf "$seeds"
python3 - "$root" "$seeds" <<'PY'
import glob, hashlib, json, os, sys
root, out = sys.argv[1], sys.argv[2]
def put(target, text):
    d = os.path.join(out, target); os.makedirs(d, exist_ok=True)
    data = text.encode() if isinstance(text, str) else text
    with open(os.path.join(d, hashlib.sha1(data).hexdigest()[:16]), "wb") as f: f.write(data)
dc_files = sorted(glob.glob(f"{root}/derivations/handout9/*.dc") + glob.glob(f"{root}/tests/data/**/*.dc", recursive=True)
                  + glob.glob(f"{root}/docs/examples/*.dc"))
for p in dc_files:
    text = open(p, "rb").read()
    put("dc_file", text)
    for line in text.decode("utf-8", "replace").splitlines():   # claims of steps: "label: claim"
        s = line.strip()
        if s and not s.startswith(("#", "by ", "note ", "symbol ", "function ", "title ", "section ")) and ":" in s:
            put("expr", s.split(":", 1)[1].strip())
        if s.startswith("symbol ") and ":" in s:
            put("assume", s.split(":", 1)[1].split("[")[0].strip())
for p in sorted(glob.glob(f"{root}/tests/data/**/*.jsonl", recursive=True)):
    for line in open(p, encoding="utf-8", errors="replace"):
        line = line.rstrip("\n")
        if not line: continue
        put("claims", line)
        try: j = json.loads(line)
        except ValueError: continue
        if not isinstance(j, dict): continue
        for k in ("lhs", "rhs", "point", "solution"):
            if isinstance(j.get(k), str): put("expr", j[k])
        if isinstance(j.get("assume"), str): put("assume", j["assume"])
        if isinstance(j.get("assumptions"), dict):
            for v in j["assumptions"].values():
                if isinstance(v, str): put("assume", v)
for s in ["m1>0, v1 real, e in [0,1], v1 > v2", "x >= 0", "theta in (0, pi/2)", "a != b, a < 2*b", "x in [1/2, 3)"]:
    put("assume", s)
import shutil
shutil.copytree(os.path.join(out, "assume"), os.path.join(out, "assume_sat"))
shutil.copytree(os.path.join(out, "dc_file"), os.path.join(out, "reader"))
shutil.copytree(os.path.join(out, "expr"), os.path.join(out, "parse"))
PY

# --- per-target libFuzzer settings ----------------------------------------------------------
declare -A max_len=([reader]=8192 [parse]=512 [dc_file]=8192 [expr]=512 [assume]=256 [assume_sat]=256 [claims]=1024)
# A hang is an input slower than the timeout, 600 s: under ASan+UBSan with coverage, at nice 10 on
# a shared machine, GiNaC/CLN-heavy inputs run up to ~100x slower than in a Release build (inputs
# of 1-3 s there passed 120 s here). Inputs slower than 10 s are kept as slow-unit-* artifacts and
# listed, not failures; docs/hardening.md times them in a Release build.
declare -A timeout=([reader]=60 [parse]=60 [dc_file]=600 [expr]=600 [assume]=600 [assume_sat]=600 [claims]=600)
declare -A dict=([reader]=dc.dict [parse]=dc.dict [dc_file]=dc.dict [expr]=dc.dict [assume]=assume.dict [assume_sat]=assume.dict [claims]=claims.dict)
# Leak checks inside the loop are off: libFuzzer runs LeakSanitizer after every input whose
# mallocs and frees do not balance, and GiNaC's own leaks on exceptions (tools/lsan.supp)
# unbalance most inputs, so the whole process is scanned after each of them: 3-4x slower, and
# slower still as the process grows. Instead every target's whole corpus is replayed once with
# leak checks on at the end (and tools/sanitize.sh runs the test suite with leak checks).
declare -A leaks=([reader]=0 [parse]=1 [dc_file]=0 [expr]=0 [assume]=0 [assume_sat]=0 [claims]=0)

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:symbolize=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
export LSAN_OPTIONS="suppressions=$root/tools/lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"

# Sessions: RUNS is split into processes of at most SESSION executions (default 250000), each
# starting from the corpus the previous one grew. The process's memory grows with every input
# that makes GiNaC throw (GiNaC leaks ~100 bytes each time, tools/lsan.supp; under ASan the
# allocator adds more), so one process for 10^6 checker-heavy inputs would hit the RSS limit.
session="${SESSION:-250000}"
status=0
mkdir -p "$build/logs"
for t in "${targets[@]}"; do
  mkdir -p "$build/corpus/$t" "$build/crashes/$t"
  rm -f "$build/logs/$t".*.log
  echo "fuzz.sh: fuzz_$t, $runs runs in sessions of at most $session (logs $build/logs/$t.N.log)"
  total=0; total_secs=0; n_sess=0; rc=0; left="$runs"
  while :; do
    if [ "$runs" -lt 0 ]; then this=-1; else this=$(( left < session ? left : session )); fi
    n_sess=$((n_sess + 1))
    log="$build/logs/$t.$n_sess.log"
    set +e
    nice -n 10 "$build/bench/fuzz/fuzz_$t" -runs="$this" -max_len="${max_len[$t]}" -timeout="${timeout[$t]}" \
      -rss_limit_mb=4096 -detect_leaks="${leaks[$t]}" -dict="$root/bench/fuzz/${dict[$t]}" \
      -artifact_prefix="$build/crashes/$t/" -print_final_stats=1 "$@" "$build/corpus/$t" "$seeds/$t" >"$log" 2>&1
    rc=$?
    set -e
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    secs=$(grep -E '^Done [0-9]+ runs in' "$log" | grep -oE '[0-9]+ second' | grep -oE '[0-9]+' || true)
    [ -n "$secs" ] || secs=$(grep -E '^#[0-9]+' "$log" | tail -1 | awk '{for (i = 1; i < NF; i++) if ($i == "exec/s:") e = $(i + 1); n = substr($1, 2); if (e > 0) print int(n / e)}')
    total=$((total + ${execs:-0})); total_secs=$((total_secs + ${secs:-0}))
    last=$(grep -E '^#[0-9]+' "$log" | tail -1 | grep -oE 'cov: [0-9]+ ft: [0-9]+ corp: [0-9]+/[^ ]+' || true)
    peak=$(sed -n 's/^stat::peak_rss_mb: *//p' "$log" | tail -1)
    echo "fuzz.sh:   session $n_sess: exit $rc, ${execs:-?} execs in ${secs:-?} s, peak RSS ${peak:-?} MB, ${last:-?}"
    [ "$rc" -eq 0 ] || break
    left=$((left - ${execs:-0}))
    [ "$runs" -ge 0 ] && [ "$left" -gt 0 ] && [ "${execs:-0}" -gt 0 ] || break
  done
  eps=$(( total_secs > 0 ? total / total_secs : 0 ))
  crashes=$(find "$build/crashes/$t" -type f ! -name 'slow-unit-*' | wc -l)
  slow=$(find "$build/crashes/$t" -type f -name 'slow-unit-*' | wc -l)
  echo "fuzz.sh: fuzz_$t exit $rc, $total execs in $total_secs s ($eps exec/s) in $n_sess session(s), ${last:-?}," \
       "${crashes} crash/leak/timeout input(s) and ${slow} slow unit(s) (> 10 s, not failures) in crashes/$t"
  [ "$rc" -eq 0 ] || status=1
  # replay: every input of the corpus once, with leak checks
  set +e
  nice -n 10 "$build/bench/fuzz/fuzz_$t" -runs=0 -timeout="${timeout[$t]}" -rss_limit_mb=4096 -detect_leaks=1 \
    -artifact_prefix="$build/crashes/$t/" "$build/corpus/$t" >"$build/logs/$t.replay.log" 2>&1
  rc=$?
  set -e
  n=$(find "$build/corpus/$t" -type f | wc -l)
  echo "fuzz.sh: fuzz_$t replay of $n corpus inputs with leak checks: exit $rc"
  [ "$rc" -eq 0 ] || status=1
done
exit "$status"
