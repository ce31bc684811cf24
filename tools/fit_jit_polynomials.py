#!/usr/bin/env python3
"""Coefficients of the JIT's inline functions (numeric/jit_module/jit_arcsine.cpp).

Each polynomial P is fitted by Remez exchange (mpmath, 60 digits) to minimise the error it leaves
in the function, max |w(z) (P_true(z) - P(z))| on [0, b], where z is the squared argument:
  asin:  asin(s) = s + s z P(z),            z = s^2 in [0, 1/4],      w = z
(an inline sin and cos, fitted here too, were measured slower than SLEEF's and removed; the
table takes more targets of this form). Prints
the coefficients as doubles and the error after rounding them to doubles (measured on 10 001
points), which enters the error bounds in the .cpp files.
Run: python3 tools/fit_jit_polynomials.py [asin]   (about ten seconds)
"""
import sys

import mpmath as mp

mp.mp.dps = 60


def asin_p(z):
    if z == 0:
        return mp.mpf(1) / 6
    s = mp.sqrt(z)
    return (mp.asin(s) / s - 1) / z


TARGETS = {
    "asin": (asin_p, mp.mpf("0.25"), 12, lambda z: z),
}


def remez(f, b, n, w, iters=8):
    a = mp.mpf(0)
    grid = [a + (b - a) * mp.mpf(i) / 4000 for i in range(4001)]
    ref = [(a + b) / 2 - (b - a) / 2 * mp.cos(mp.pi * k / (n + 1)) for k in range(n + 2)]
    err = lambda c, z: w(z) * (f(z) - sum(cj * z**j for j, cj in enumerate(c)))
    c = None
    for _ in range(iters):
        M = mp.matrix(n + 2, n + 2)
        y = mp.matrix(n + 2, 1)
        for i, z in enumerate(ref):
            wz = w(z) if z != 0 else mp.mpf("1e-30")
            for j in range(n + 1):
                M[i, j] = wz * z**j
            M[i, n + 1] = (-1) ** i
            y[i] = wz * f(z)
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
    cd = [float(x) for x in c]
    worst = max(abs(err([mp.mpf(x) for x in cd], b * mp.mpf(i) / 10000)) for i in range(10001))
    return cd, worst


def main():
    for name in sys.argv[1:] or list(TARGETS):
        f, b, n, w = TARGETS[name]
        cd, worst = remez(f, b, n, w)
        print(f"{name}: coefficients c0..c{n} (P(z) = sum c_j z^j):")
        for x in cd:
            print("    %r," % x)
        print(f"{name}: max weighted error with double coefficients: 2^%.2f" % float(mp.log(worst, 2)))


if __name__ == "__main__":
    main()
