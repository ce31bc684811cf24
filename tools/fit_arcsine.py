#!/usr/bin/env python3
"""Coefficients of the JIT's inline asin/acos (numeric/jit_module/jit_arcsine.cpp).

asin(s) = s + s*z*P(z) with z = s^2 in [0, 1/4]. P is fitted by Remez exchange (mpmath, 60
digits) minimising max |z*(P_true(z) - P(z))| on [0, 1/4], the error of asin(s)/s - 1 that the
polynomial leaves. Prints the degree-12 coefficients as doubles and the error after rounding
them to doubles (measured on 10 001 points): that figure enters the error bound in the .cpp.
Run: python3 tools/fit_arcsine.py   (about a minute)
"""
import mpmath as mp

mp.mp.dps = 60
A, B = mp.mpf(0), mp.mpf("0.25")


def p_true(z):
    if z == 0:
        return mp.mpf(1) / 6
    s = mp.sqrt(z)
    return (mp.asin(s) / s - 1) / z


def err(c, z):
    return z * (p_true(z) - sum(cj * z**j for j, cj in enumerate(c)))


def remez(n, iters=8):
    grid = [A + (B - A) * mp.mpf(i) / 4000 for i in range(4001)]
    ref = [(A + B) / 2 - (B - A) / 2 * mp.cos(mp.pi * k / (n + 1)) for k in range(n + 2)]
    c = None
    for _ in range(iters):
        M = mp.matrix(n + 2, n + 2)
        y = mp.matrix(n + 2, 1)
        for i, z in enumerate(ref):
            w = z if z != 0 else mp.mpf("1e-30")
            for j in range(n + 1):
                M[i, j] = w * z**j
            M[i, n + 1] = (-1) ** i
            y[i] = w * p_true(z)
        sol = mp.lu_solve(M, y)
        c = [sol[j] for j in range(n + 1)]
        ev = [err(c, z) for z in grid]
        ext = [i for i in range(len(grid))
               if (i == 0 or abs(ev[i]) >= abs(ev[i - 1])) and (i == len(grid) - 1 or abs(ev[i]) >= abs(ev[i + 1]))]
        alt = []
        for i in ext:
            if alt and mp.sign(ev[alt[-1]]) == mp.sign(ev[i]):
                if abs(ev[i]) > abs(ev[alt[-1]]):
                    alt[-1] = i
            else:
                alt.append(i)
        while len(alt) > n + 2:
            alt.pop(0 if abs(ev[alt[0]]) < abs(ev[alt[-1]]) else -1)
        if len(alt) == n + 2:
            ref = [grid[i] for i in alt]
    return c


def main():
    c = remez(12)
    cd = [float(x) for x in c]
    worst = max(abs(err([mp.mpf(x) for x in cd], mp.mpf(i) / 40000)) for i in range(10001))
    print("coefficients c0..c12 (P(z) = sum c_j z^j):")
    for x in cd:
        print("    %r," % x)
    print("max |z (P_true - P)| with double coefficients: 2^%.2f" % float(mp.log(worst, 2)))


if __name__ == "__main__":
    main()
