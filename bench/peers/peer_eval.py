#!/usr/bin/env python3
"""Closed-form evaluation: SymPy lambdify + NumPy against derivcheck's fast evaluator.

For each formula (FILE:LABEL, loaded from the derivation file by label):
  1. draw N seeded random points from the symbols' declared domains (points where the formula
     is not real are redrawn), written as raw little-endian float64, row-major N x k;
  2. NumPy: f = lambdify(inputs, expr, "numpy"); time f(*columns) over all N points (median
     of R repeats, min and max); 
  3. derivcheck: `derivcheck chart evalpoints FILE LABEL --points-file P --out-file O --repeats R`
     (the same points; the batch API of numeric/evaluator.hpp; also the hand-written C++
     function where the chart command has one) -- "not available yet" if the command fails;
  4. errors of both against a 50-digit mpmath reference on the first M points (ulps of double
     at the reference value; max and median).
Prints one JSON object per formula on stdout.

Usage: peer_eval.py --cli PATH [--n N] [--repeats R] [--ref-points M] [--tmp DIR] FILE:LABEL...
"""
import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np
import sympy as sp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dcfile  # noqa: E402


def sample(doms, inputs, n, rng):
    cols = []
    for s in inputs:
        kind, lo, hi = doms[str(s)]
        if kind == "positive" or kind == "nonnegative":
            c = np.exp(rng.uniform(np.log(0.1), np.log(10.0), n))
        elif kind == "negative":
            c = -np.exp(rng.uniform(np.log(0.1), np.log(10.0), n))
        elif kind == "real":
            c = rng.uniform(-10.0, 10.0, n)
        else:
            c = rng.uniform(lo, hi, n)
        cols.append(c)
    return np.column_stack(cols) if cols else np.zeros((n, 0))


def real_points(f, doms, inputs, n, rng):
    """n points where the double result is finite (e.g. acos arguments inside [-1, 1])."""
    out = np.zeros((0, len(inputs)))
    while out.shape[0] < n:
        pts = sample(doms, inputs, 2 * n, rng)
        with np.errstate(all="ignore"):
            y = f(*pts.T)
        y = np.broadcast_to(y, (pts.shape[0],))
        out = np.vstack([out, pts[np.isfinite(y)]])
    return out[:n]


def ulps(computed, ref):
    sp_ = np.spacing(np.abs(ref.astype(np.float64)))
    sp_[sp_ == 0] = np.spacing(0.0)
    with np.errstate(all="ignore"):
        e = np.abs(computed - ref) / sp_
    e[~np.isfinite(computed)] = np.inf
    return e


def time_numpy(f, pts, repeats):
    cols = [np.ascontiguousarray(pts[:, j]) for j in range(pts.shape[1])]
    ts = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        y = f(*cols)
        ts.append(time.perf_counter() - t0)
    return np.median(ts), min(ts), max(ts), np.broadcast_to(y, (pts.shape[0],))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", required=True)
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--ref-points", type=int, default=2000)
    ap.add_argument("--seed", type=int, default=20261121)
    ap.add_argument("--tmp", default="/tmp")
    ap.add_argument("formulas", nargs="+")
    a = ap.parse_args()
    rng = np.random.default_rng(a.seed)
    for spec in a.formulas:
        path, label = spec.rsplit(":", 1)
        target, expr, inputs = dcfile.formula(path, label)
        doms = dcfile.symbol_domains(path)
        f = sp.lambdify(inputs, expr, "numpy")
        pts = real_points(f, doms, inputs, a.n, rng)
        med, lo, hi, y_np = time_numpy(f, pts, a.repeats)
        row = {"formula": f"{os.path.basename(path)}:{label}", "inputs": [str(s) for s in inputs],
               "n": a.n, "seed": a.seed, "numpy_evals_per_s": a.n / med,
               "numpy_ns_per_eval": {"median": med / a.n * 1e9, "min": lo / a.n * 1e9, "max": hi / a.n * 1e9}}
        # 50-digit reference on the first M points (mpmath, exact double inputs)
        m = min(a.ref_points, a.n)
        fm = sp.lambdify(inputs, expr, "mpmath")
        import mpmath
        mpmath.mp.dps = 50
        ref = np.array([float(fm(*[mpmath.mpf(float(x)) for x in pts[i]])) for i in range(m)])
        e_np = ulps(y_np[:m], ref)
        row["numpy_ulps"] = {"max": float(np.max(e_np)), "median": float(np.median(e_np))}
        # derivcheck on the same points
        pfile = os.path.join(a.tmp, f"peer_pts_{label}.bin")
        ofile = os.path.join(a.tmp, f"peer_out_{label}.bin")
        pts.astype("<f8").tofile(pfile)
        cmd = [a.cli, "chart", "evalpoints", path, label, "--inputs", ",".join(row["inputs"]),
               "--points-file", pfile, "--out-file", ofile, "--repeats", str(a.repeats)]
        try:
            r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
            if r.returncode != 0:
                raise RuntimeError(r.stderr.strip().splitlines()[-1] if r.stderr.strip() else f"exit {r.returncode}")
            dc = json.loads(r.stdout.strip().splitlines()[-1])
            y_dc = np.fromfile(ofile, dtype="<f8")
            e_dc = ulps(y_dc[:m], ref)
            row["derivcheck"] = dc
            row["derivcheck_ulps"] = {"max": float(np.max(e_dc)), "median": float(np.median(e_dc))}
            row["ratio_vs_numpy"] = dc["evals_per_s"] / row["numpy_evals_per_s"]
            if dc.get("handwritten_evals_per_s"):
                row["fraction_of_handwritten"] = dc["evals_per_s"] / dc["handwritten_evals_per_s"]
        except Exception as ex:  # the derivcheck side has not landed (or failed): say so
            ex = "derivcheck not built" if isinstance(ex, FileNotFoundError) else ex
            row["derivcheck"] = f"not available yet ({ex})"
        for fn in (pfile, ofile):
            if os.path.exists(fn):
                os.remove(fn)
        print(json.dumps(row), flush=True)


if __name__ == "__main__":
    main()
