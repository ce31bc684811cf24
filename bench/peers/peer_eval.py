#!/usr/bin/env python3
"""Closed-form evaluation: SymPy lambdify + NumPy against derivcheck's fast evaluator.

For each formula (FILE:LABEL, loaded from the derivation file by label):
  1. draw N seeded random points from the symbols' declared domains (points where the formula
     is not real are redrawn), written as raw little-endian float64, row-major N x k;
  2. derivcheck: `derivcheck chart evalpoints FILE LABEL --points-file P --out-file O --serve`
     loads the same points and compiles the formula (the batch API of numeric/evaluator.hpp:
     the JIT, numeric/jit.hpp, where available), then times one evaluation of all N points per
     request on stdin -- "derivcheck" (the default fast path) or "handwritten" (the hand-written
     C++ function where the chart command has one); "not available yet" if it fails;
  3. NumPy: f = lambdify(inputs, expr, "numpy"); f(*columns) over all N points, timed here;
     the repeats are interleaved: derivcheck, numpy, handwritten, derivcheck, numpy, ... and
     each tool's median (min, max) is reported. Only the evaluation is timed, never process
     start or loading;
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


def numpy_once(f, cols):
    t0 = time.perf_counter()
    y = f(*cols)
    return time.perf_counter() - t0, y


def stat(ts):
    return {"median": float(np.median(ts)), "min": float(min(ts)), "max": float(max(ts))}


class Server:
    """derivcheck chart evalpoints --serve: one timing per request line."""

    def __init__(self, cmd):
        self.p = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                  text=True, bufsize=1)
        line = self.p.stdout.readline()
        if not line:
            err = self.p.stderr.read().strip().splitlines()
            self.p.wait()
            raise RuntimeError(err[-1] if err else f"exit {self.p.returncode}")
        self.info = json.loads(line)

    def time(self, tool):
        self.p.stdin.write(tool + "\n")
        self.p.stdin.flush()
        r = json.loads(self.p.stdout.readline())
        if "error" in r:
            raise RuntimeError(f"{tool}: {r['error']}")
        return r["ns_per_eval"]

    def close(self):
        self.p.stdin.write("quit\n")
        self.p.stdin.close()
        rc = self.p.wait(timeout=600)
        if rc != 0:
            raise RuntimeError(self.p.stderr.read().strip() or f"exit {rc}")


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
        cols = [np.ascontiguousarray(pts[:, j]) for j in range(pts.shape[1])]
        row = {"formula": f"{os.path.basename(path)}:{label}", "inputs": [str(s) for s in inputs],
               "n": a.n, "seed": a.seed, "repeats": a.repeats}
        pfile = os.path.join(a.tmp, f"peer_pts_{label}.bin")
        ofile = os.path.join(a.tmp, f"peer_out_{label}.bin")
        pts.astype("<f8").tofile(pfile)
        cmd = [a.cli, "chart", "evalpoints", path, label, "--inputs", ",".join(row["inputs"]),
               "--points-file", pfile, "--out-file", ofile, "--serve"]
        try:
            srv = Server(cmd)
        except Exception as ex:  # the derivcheck side has not landed (or failed): say so
            srv = None
            row["derivcheck"] = f"not available yet ({'derivcheck not built' if isinstance(ex, FileNotFoundError) else ex})"
        ts = {"derivcheck": [], "numpy": [], "handwritten": []}
        y_np = None
        for _ in range(a.repeats):  # interleaved: derivcheck, numpy, handwritten, derivcheck, ...
            if srv:
                ts["derivcheck"].append(srv.time("derivcheck"))
            t, y_np = numpy_once(f, cols)
            ts["numpy"].append(t / a.n * 1e9)
            if srv and srv.info.get("handwritten"):
                ts["handwritten"].append(srv.time("handwritten"))
        y_np = np.broadcast_to(y_np, (pts.shape[0],))
        nn = stat(ts["numpy"])
        row["numpy_ns_per_eval"] = nn
        row["numpy_evals_per_s"] = 1e9 / nn["median"]
        # 50-digit reference on the first M points (mpmath, exact double inputs)
        m = min(a.ref_points, a.n)
        fm = sp.lambdify(inputs, expr, "mpmath")
        import mpmath
        mpmath.mp.dps = 50
        ref = np.array([float(fm(*[mpmath.mpf(float(x)) for x in pts[i]])) for i in range(m)])
        e_np = ulps(y_np[:m], ref)
        row["numpy_ulps"] = {"max": float(np.max(e_np)), "median": float(np.median(e_np))}
        if srv:
            try:
                srv.close()
                y_dc = np.fromfile(ofile, dtype="<f8")
                e_dc = ulps(y_dc[:m], ref)
                dn = stat(ts["derivcheck"])
                dc = dict(srv.info, ns_per_eval=dn, evals_per_s=1e9 / dn["median"])
                if ts["handwritten"]:
                    hw = stat(ts["handwritten"])
                    dc["handwritten_ns_per_eval"] = hw
                    dc["handwritten_evals_per_s"] = 1e9 / hw["median"]
                    row["fraction_of_handwritten"] = dc["evals_per_s"] / dc["handwritten_evals_per_s"]
                row["derivcheck"] = dc
                row["derivcheck_ulps"] = {"max": float(np.max(e_dc)), "median": float(np.median(e_dc))}
                row["ratio_vs_numpy"] = dc["evals_per_s"] / row["numpy_evals_per_s"]
            except Exception as ex:
                row["derivcheck"] = f"not available yet ({ex})"
        for fn in (pfile, ofile):
            if os.path.exists(fn):
                os.remove(fn)
        print(json.dumps(row), flush=True)


if __name__ == "__main__":
    main()
