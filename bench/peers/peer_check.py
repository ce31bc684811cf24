#!/usr/bin/env python3
"""Process wall time of `derivcheck check derivations/handout9/` against the SymPy script
(bench/peers/sympy_handout.py), median of N runs each (min and max too), and what each checks.

derivcheck's counts come from `derivcheck check --json`: every object with a "verdict" field
(proved / holds_numerically / refuted / undecided) is one checked claim; objects with a
"dimension" or "dimensions" field count as dimension checks, "side_conditions" entries as side
conditions.  If derivcheck is missing or fails for another reason than a verdict exit code
(0, 1, 3), its side reads "not available yet".

Usage: peer_check.py --cli PATH --python PY [--repeats N] DIR
Prints one JSON object on stdout.
"""
import argparse
import glob
import json
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def timed_runs(cmd, n, ok_codes):
    ts, last = [], None
    for _ in range(n):
        t0 = time.perf_counter()
        last = subprocess.run(cmd, capture_output=True, text=True, timeout=900)
        ts.append(time.perf_counter() - t0)
        if last.returncode not in ok_codes:
            raise RuntimeError(f"{' '.join(cmd[:2])}: exit {last.returncode}: "
                               + (last.stderr.strip().splitlines() or [''])[-1][:200])
    return {"median": statistics.median(ts), "min": min(ts), "max": max(ts), "runs": n}, last


def walk(o, acc):
    if isinstance(o, dict):
        v = o.get("verdict")
        if isinstance(v, dict):
            v = v.get("kind", v.get("verdict"))
        if v in ("proved", "holds_numerically", "refuted", "undecided"):
            acc[v] = acc.get(v, 0) + 1
        for key in ("dimension", "dimensions", "dimension_check"):
            if key in o:
                acc["dimension_checks"] = acc.get("dimension_checks", 0) + 1
                break
        sc = o.get("side_conditions")
        if isinstance(sc, list):
            acc["side_conditions"] = acc.get("side_conditions", 0) + len(sc)
        for x in o.values():
            walk(x, acc)
    elif isinstance(o, list):
        for x in o:
            walk(x, acc)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", required=True)
    ap.add_argument("--python", default=sys.executable)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("dir")
    a = ap.parse_args()
    files = sorted(glob.glob(os.path.join(a.dir, "*.dc")))
    res = {"files": len(files), "repeats": a.repeats}

    sym_t, sym_last = timed_runs([a.python, os.path.join(HERE, "sympy_handout.py")], a.repeats, (0, 1))
    line = sym_last.stdout.strip().splitlines()[-1]
    counts = dict(kv.split("=", 1) for kv in line.split()[1:])
    res["sympy"] = {"seconds": sym_t, "claims": int(counts["claims"]), "checked": int(counts["checked"]),
                    "refuted": int(counts["refuted"]), "cannot": int(counts["cannot"]), "version": counts["sympy"]}
    try:
        dc_t, _ = timed_runs([a.cli, "check", a.dir], a.repeats, (0, 1, 3))
        j = subprocess.run([a.cli, "check", "--json", a.dir], capture_output=True, text=True, timeout=900)
        acc = {}
        try:
            walk(json.loads(j.stdout), acc)
        except json.JSONDecodeError:
            for ln in j.stdout.splitlines():  # JSON lines
                if ln.strip():
                    walk(json.loads(ln), acc)
        res["derivcheck"] = {"seconds": dc_t, "counts": acc,
                             "checked": acc.get("proved", 0) + acc.get("holds_numerically", 0),
                             "claims": sum(acc.get(k, 0) for k in ("proved", "holds_numerically", "refuted", "undecided"))}
        res["ratio"] = sym_t["median"] / dc_t["median"]
    except Exception as ex:
        ex = "derivcheck not built" if isinstance(ex, FileNotFoundError) else ex
        res["derivcheck"] = f"not available yet ({ex})"
    print(json.dumps(res))


if __name__ == "__main__":
    main()
