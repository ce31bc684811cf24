#!/usr/bin/env python3
"""The scenes in SciPy's solve_ivp (RK45, DOP853, LSODA) against derivcheck's integrators at
equal accuracy.

Each scene below is the same model as numeric/scenes/<scene>.cpp (same defaults, same initial
state, same compared quantity and closed form), written the way a SciPy user would write it.
For every method a tolerance sweep (rtol = atol = 1e-3 ... 1e-13) gives (relative error of the
compared quantity, wall time: median of R calls, min, max).  The derivcheck side comes from
`derivcheck chart scenes --csv FILE` (its own sweep over step sizes / tolerances, timed
in-process the same way), or "not available yet" if the command fails.

At each accuracy target (relative error <= 1e-6 and <= 1e-9) the fastest run of each tool that
reaches it is picked; the ratio is SciPy's best time over derivcheck's best time.

Usage: peer_scenes.py --cli PATH [--repeats R] [--csv OUT] [--dc-csv IN]
Prints JSON lines (one per scene and target) on stdout; with --csv writes every SciPy run.
"""
import argparse
import csv
import io
import json
import math
import os
import subprocess
import sys
import time

import numpy as np
from scipy.integrate import solve_ivp

TOLS = [10.0**-k for k in range(3, 14)]
TARGETS = [1e-6, 1e-9]


# --- the scenes (defaults from numeric/scenes/spec.cpp) ------------------------------------------
def spring():
    m1, m2, k, L0, v0, t_end = 1.0, 2.0, 5.0, 1.0, 2.0, 10.0
    M = m1 + m2

    def f(t, x):
        F = k * (x[1] - x[0] - L0)
        return [x[2], x[3], F / m1, -F / m2]

    om = math.sqrt(k * M / (m1 * m2))
    vG = m2 * v0 / M
    x2_exact = vG * t_end + m2 * L0 / M + m1 / M * (L0 + v0 / om * math.sin(om * t_end))

    def run(method, tol):
        s = solve_ivp(f, (0, t_end), [0, L0, 0, v0], method=method, rtol=tol, atol=tol)
        return s.y[1, -1]
    return "spring", "x2(t_end)", run, x2_exact


def rocket():
    m0, m_r, mu, u_e, g = 1000.0, 300.0, 10.0, 2500.0, 9.81
    t_b = (m0 - m_r) / mu

    def f(t, x):
        return [x[1], u_e * mu / (m0 - mu * t) - g]

    v_cf = -u_e * math.log1p(-mu * t_b / m0) - g * t_b

    def run(method, tol):
        s = solve_ivp(f, (0, t_b), [0.0, 0.0], method=method, rtol=tol, atol=tol)
        return s.y[1, -1]
    return "rocket", "v_burnout", run, v_cf


def pendulum():
    m, M, v0, L, g = 0.01, 2.0, 300.0, 1.0, 9.81
    v1 = m * v0 / (M + m)

    def f(t, x):
        return [x[1], -(g / L) * math.sin(x[0])]

    def turn(t, x):
        return x[1]
    turn.terminal, turn.direction = True, -1
    th_cf = 2 * math.asin(m * v0 / ((M + m) * 2 * math.sqrt(g * L)))

    def run(method, tol):
        s = solve_ivp(f, (0, 1000 * math.sqrt(L / g)), [0.0, v1 / L], method=method, rtol=tol, atol=tol,
                      events=turn)
        return s.y_events[0][0][0]
    return "pendulum", "theta_max", run, th_cf


def ladder():
    m, l, g, th0 = 10.0, 4.0, 9.81, math.radians(60)

    def thdd(th):
        return -1.5 * g / l * math.cos(th)

    def wall(th, om):
        return -m * 0.5 * l * (math.cos(th) * om * om + math.sin(th) * thdd(th))

    def f(t, x):
        return [x[1], thdd(x[0]), wall(x[0], x[1])]

    def sep(t, x):
        return wall(x[0], x[1])
    sep.terminal, sep.direction = True, -1

    def run(method, tol):
        s = solve_ivp(f, (0, 1000 * math.sqrt(l / g)), [th0, 0.0, 0.0], method=method, rtol=tol, atol=tol,
                      events=sep)
        return math.sin(s.y_events[0][0][0])
    return "ladder", "sin_theta_sep", run, 2.0 / 3.0 * math.sin(th0)


SCENES = [spring, rocket, pendulum, ladder]


def timed(fn, repeats):
    ts, val = [], None
    for _ in range(repeats):
        t0 = time.perf_counter()
        val = fn()
        ts.append(time.perf_counter() - t0)
    return val, float(np.median(ts)), min(ts), max(ts)


def best(rows, target):
    ok = [r for r in rows if r["rel_error"] <= target]
    return min(ok, key=lambda r: r["seconds"]) if ok else None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", required=True)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--csv")
    ap.add_argument("--dc-csv", default="/tmp/peer_dc_scenes.csv")
    a = ap.parse_args()

    # derivcheck's sweep (one call for all scenes)
    dc_rows, dc_status = {}, ""
    try:
        r = subprocess.run([a.cli, "chart", "scenes", "--scenes", ",".join(s()[0] for s in SCENES),
                            "--repeats", str(a.repeats), "--csv", a.dc_csv], capture_output=True, text=True,
                           timeout=1800)
        if r.returncode != 0:
            raise RuntimeError(r.stderr.strip().splitlines()[-1] if r.stderr.strip() else f"exit {r.returncode}")
        with open(a.dc_csv) as fh:
            for row in csv.DictReader(fh):
                dc_rows.setdefault(row["scene"], []).append(
                    {"method": row["method"], "param": row["param"], "rel_error": float(row["rel_error"]),
                     "seconds": float(row["seconds_median"])})
    except Exception as ex:
        ex = "derivcheck not built" if isinstance(ex, FileNotFoundError) else ex
        dc_status = f"not available yet ({ex})"

    out = io.StringIO()
    w = csv.writer(out)
    w.writerow(["scene", "tool", "method", "tol", "rel_error", "seconds_median", "seconds_min", "seconds_max"])
    for make in SCENES:
        name, quantity, run, cf = make()
        rows = []
        for method in ("RK45", "DOP853", "LSODA"):
            for tol in TOLS:
                try:
                    val, med, lo, hi = timed(lambda: run(method, tol), a.repeats)
                    err = abs(val - cf) / abs(cf)
                except Exception:
                    continue
                rows.append({"method": method, "param": f"tol={tol:.0e}", "rel_error": err, "seconds": med})
                w.writerow([name, "scipy", method, f"{tol:.0e}", f"{err:.6e}", f"{med:.6e}", f"{lo:.6e}", f"{hi:.6e}"])
        for target in TARGETS:
            sb = best(rows, target)
            res = {"scene": name, "quantity": quantity, "target_rel_error": target,
                   "scipy_best": sb}
            if dc_status:
                res["derivcheck_best"] = dc_status
            else:
                db = best(dc_rows.get(name, []), target)
                res["derivcheck_best"] = db if db else "no derivcheck run reached the target"
                if sb and db:
                    res["ratio"] = sb["seconds"] / db["seconds"]
            print(json.dumps(res), flush=True)
    if a.csv:
        tmp = a.csv + ".tmp"
        with open(tmp, "w") as fh:
            fh.write(out.getvalue())
        os.replace(tmp, a.csv)


if __name__ == "__main__":
    sys.exit(main())
