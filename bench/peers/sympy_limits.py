#!/usr/bin/env python3
"""SymPy's `limit` on the limit corpus (tests/data/limits.jsonl), the peer of bench_limits.

Each line is a limit claim (lhs, var, point, optional dir, rhs, assumptions, expected). The
script computes sympy.limit(lhs, var, point, dir) and judges the claim the way a user would:

  rhs a value        proved if simplify(limit - rhs) == 0, refuted otherwise (as a user reads
                     it); a limit with oo, zoo, nan or sign(...) in it: "cannot"
  rhs oo / -oo       proved / refuted by the value SymPy returns
  rhs undefined      proved if SymPy says the one-sided limits differ (ValueError for dir="+-"),
                     returns zoo (unsigned infinity) or AccumBounds (oscillation), refuted if it
                     returns a value

An exception, an unevaluated Limit, or the timeout counts as "cannot". Timing is the
sympy.limit call only (median of --repeats runs, SymPy's cache cleared before each), so it
does not include parsing or the comparison.

Assumptions map to SymPy symbol assumptions: positive, negative, nonnegative, real; an
interval "in (a, b)" becomes positive when a >= 0 and real otherwise (SymPy has no interval
assumptions, so e in (0, 1) is only known to be positive). Undeclared symbols are real, as in
derivcheck.

Usage: sympy_limits.py [--corpus FILE] [--repeats N] [--timeout S] [--json FILE] [--verbose]
"""
import argparse
import json
import keyword
import re
import signal
import statistics
import sys
import time

import sympy as sp
from sympy.core.cache import clear_cache
from sympy.parsing.sympy_parser import parse_expr, standard_transformations


class Timeout(Exception):
    pass


def on_alarm(signum, frame):
    raise Timeout()


def symbols_for(texts, assumptions):
    names = set()
    for t in texts:
        names.update(re.findall(r"[A-Za-z_][A-Za-z_0-9]*", t))
    builtins = {"sqrt", "exp", "log", "ln", "sin", "cos", "tan", "asin", "acos", "atan", "abs", "pi", "oo"}
    table = {}
    for n in names - builtins:
        dom = assumptions.get(n, "real")
        if dom == "positive":
            kw = {"positive": True}
        elif dom == "negative":
            kw = {"negative": True}
        elif dom == "nonnegative":
            kw = {"nonnegative": True}
        elif dom.startswith("in"):
            lo = dom[2:].strip()[1:].split(",")[0].strip()
            kw = {"positive": True} if float(sp.sympify(lo)) >= 0 else {"real": True}
        else:
            kw = {"real": True}
        table[safe(n)] = sp.Symbol(n, **kw)
    table.update({"ln": sp.log, "abs": sp.Abs, "pi": sp.pi, "oo": sp.oo, "exp": sp.exp})
    return table


def safe(name):
    """Python keywords (lambda) cannot be names in parse_expr: lambda -> lambda_."""
    return name + "_" if keyword.iskeyword(name) else name


def parse(text, table):
    text = re.sub(r"[A-Za-z_][A-Za-z_0-9]*", lambda m: safe(m.group(0)), text)
    return parse_expr(text.replace("^", "**"), local_dict=table, transformations=standard_transformations)


def judge(claim, repeats, timeout):
    table = symbols_for([claim["lhs"], claim["rhs"], claim["point"], claim["var"]], claim.get("assumptions", {}))
    f = parse(claim["lhs"], table)
    x = table[safe(claim["var"])]
    point = {"oo": sp.oo, "+oo": sp.oo, "-oo": -sp.oo}.get(claim["point"]) or parse(claim["point"], table)
    direction = claim.get("dir", "+-")
    if point in (sp.oo, -sp.oo):
        direction = "-" if point == sp.oo else "+"
    times, result, error = [], None, None
    for _ in range(repeats):
        clear_cache()
        signal.alarm(timeout)
        t0 = time.perf_counter()
        try:
            result, error = sp.limit(f, x, point, dir=direction), None
        except Timeout:
            result, error = None, "timeout"
        except ValueError as e:
            result, error = None, "differ" if "differ" in str(e) or "not exist" in str(e) else "error: " + str(e)
        except Exception as e:  # noqa: BLE001 - any failure counts as "cannot"
            result, error = None, "error: " + type(e).__name__
        finally:
            signal.alarm(0)
        times.append(time.perf_counter() - t0)
        if error == "timeout":
            break
    rhs_text = claim["rhs"]
    if error is not None:
        if error == "differ":
            return ("proved" if rhs_text == "undefined" else "refuted"), times, "one-sided limits differ"
        return "cannot", times, error
    if result.has(sp.Limit):
        return "cannot", times, "unevaluated Limit"
    if result == sp.zoo:   # unsigned infinity: for a real two-sided limit, the sides differ
        return ("proved" if rhs_text == "undefined" else "refuted"), times, "zoo"
    if isinstance(result, sp.AccumBounds) or result.has(sp.AccumBounds):
        return ("proved" if rhs_text == "undefined" else "refuted"), times, str(result)
    if rhs_text == "undefined":
        return "refuted", times, str(result)
    if rhs_text in ("oo", "+oo", "-oo"):
        want = sp.oo if rhs_text != "-oo" else -sp.oo
        if result in (sp.oo, -sp.oo):
            return ("proved" if result == want else "refuted"), times, str(result)
        if result.is_number and result.is_finite:
            return "refuted", times, str(result)
        return "cannot", times, str(result)
    rhs = parse(rhs_text, table)
    if result in (sp.oo, -sp.oo):
        return "refuted", times, str(result)
    if result.has(sp.oo, sp.zoo, sp.nan, sp.sign):
        return "cannot", times, str(result)
    try:
        diff = sp.simplify(result - rhs)
    except Exception:  # noqa: BLE001
        return "cannot", times, str(result)
    # as a user reads it: a difference that simplifies to 0 proves the claim, any other
    # difference refutes it
    return ("proved" if diff == 0 else "refuted"), times, str(result)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--corpus", default="tests/data/limits.jsonl")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--timeout", type=int, default=30)
    ap.add_argument("--json")
    ap.add_argument("--verbose", action="store_true")
    a = ap.parse_args()
    signal.signal(signal.SIGALRM, on_alarm)
    rows = [json.loads(line) for line in open(a.corpus) if line.strip()]
    medians, out = [], []
    counts = {"as labelled": 0, "wrong": 0, "cannot": 0}
    for claim in rows:
        verdict, times, what = judge(claim, a.repeats, a.timeout)
        med = statistics.median(times)
        medians.append(med)
        tag = "as labelled" if verdict == claim["expected"] else ("cannot" if verdict == "cannot" else "wrong")
        counts[tag] += 1
        out.append({"id": claim["id"], "verdict": verdict, "expected": claim["expected"], "seconds": med, "sympy": what})
        if a.verbose or tag == "wrong":
            print(f"{tag:12} {claim['id']:28} {verdict:8} {med * 1e3:9.1f} ms  {what[:100]}", file=sys.stderr)
    s = sorted(medians)
    print(f"sympy {sp.__version__}: lines {len(rows)}  repeats {a.repeats}  timeout {a.timeout} s")
    print(f"median per limit  {1e3 * s[len(s) // 2]:.2f} ms")
    print(f"mean per limit    {1e3 * sum(s) / len(s):.2f} ms")
    print(f"90th percentile   {1e3 * s[len(s) * 9 // 10]:.2f} ms")
    print(f"slowest           {1e3 * s[-1]:.2f} ms ({max(out, key=lambda r: r['seconds'])['id']})")
    print(f"total             {sum(s):.2f} s")
    print(f"verdicts: {counts['as labelled']} as labelled, {counts['cannot']} cannot, {counts['wrong']} wrong")
    if a.json:
        with open(a.json, "w") as fh:
            json.dump(out, fh, indent=1)


if __name__ == "__main__":
    main()
