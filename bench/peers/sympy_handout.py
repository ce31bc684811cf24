#!/usr/bin/env python3
"""Handout 9's claims checked in SymPy, the way a careful user would check them by hand.

This is the peer that `derivcheck check derivations/handout9/` is compared with (see
bench/peers/run.sh). Each check below reproduces one non-`given` step of a file in
derivations/handout9/*.dc, labelled FILE:LABEL, with the SymPy tool a user would reach for:
solve, subs, limit, series, integrate/dsolve, diff, and simplify(lhs - rhs) == 0.

A check returns True (SymPy confirms the claim), False (SymPy finds the claim wrong), or None
(SymPy gives no answer: simplify leaves a non-zero residual, solve finds no matching root, or
SymPy raises).  Exceptions count as "cannot".  Nothing here is hard-coded: each result is
what SymPy computes in this process.

What the script does not do (and derivcheck does): dimension checks of every step, side
conditions (divisors, log/sqrt/acos arguments), errata detection (the undefined v_e of
09_rocket.dc:minimise), positions in the source.  Those are counted separately by run.sh.

Usage: sympy_handout.py [--verbose] [--json FILE]
Exit code 0 if no claim was found false, 1 otherwise.
"""
import json
import sys
import time

T_START = time.perf_counter()
import sympy as sp  # noqa: E402  (import time is part of the measured process wall time)
from sympy import Rational as R, Eq, Function, diff, exp, limit, log, oo, simplify, solve, sqrt  # noqa: E402

CHECKS = []


def claim(file, label, how):
    def deco(fn):
        CHECKS.append((file, label, how, fn))
        return fn
    return deco


def zero(e):
    """simplify(e) == 0, SymPy's usual equality test."""
    return simplify(e) == 0


def chain_equal(*sides):
    """Every adjacent pair of a chain a = b = c is equal."""
    return all(zero(a - b) for a, b in zip(sides, sides[1:]))


def in_solutions(sols, expr):
    """Does one of solve()'s roots equal expr?  (None if solve returned nothing usable)"""
    if not sols:
        return None
    return any(zero(s - expr) for s in sols) or None


# ---------------------------------------------------------------------------------------------
# 01_momentum_particle.dc
F01 = "01_momentum_particle"
t, t1, t2 = sp.symbols("t t1 t2", real=True)
m = sp.Symbol("m", positive=True)
v, a, F, p = (Function(n) for n in ("v", "a", "F", "p"))


@claim(F01, "newton_v", "subs + diff + simplify")
def _():
    lhs = F(t)
    sides = [m * a(t), m * diff(v(t), t), diff(m * v(t), t)]
    newton = {F(t): m * a(t)}
    accel = {a(t): diff(v(t), t)}
    s = [lhs.subs(newton).subs(accel)] + [x.subs(accel) for x in sides]
    return chain_equal(*s)


@claim(F01, "momentum_rate", "diff of p = m v")
def _():
    return zero(diff(m * v(t), t) - diff(p(t), t).subs(p(t), m * v(t)).doit())


@claim(F01, "newton_p", "subs + simplify")
def _():
    return zero((m * diff(v(t), t)) - diff(p(t).subs(p(t), m * v(t)), t))


@claim(F01, "impulse", "integrate F = m dv/dt from t1 to t2")
def _():
    i = sp.integrate(m * diff(v(t), t), (t, t1, t2))
    return chain_equal(i, m * v(t2) - m * v(t1), (m * v(t)).subs(t, t2) - (m * v(t)).subs(t, t1))


# ---------------------------------------------------------------------------------------------
# 02_cannon.dc
F02 = "02_cannon"
m_p, m_c, v_p, v_c, p_p, p_c, T_p, T_c = sp.symbols("m_p m_c v_p v_c p_p p_c T_p T_c", positive=True)


@claim(F02, "speed_ratio", "solve momentum for v_p")
def _():
    vp = solve(Eq(m_p * v_p - m_c * v_c, 0), v_p)[0]
    return zero(vp / v_c - m_c / m_p)


@claim(F02, "T_c_def", "simplify chain")
def _():
    return chain_equal(R(1, 2) * m_c * v_c**2, R(1, 2) * v_c * (m_c * v_c), R(1, 2) * v_c * (m_c * v_c))


@claim(F02, "T_p_def", "simplify chain")
def _():
    return chain_equal(R(1, 2) * m_p * v_p**2, R(1, 2) * v_p * (m_p * v_p), R(1, 2) * v_p * (m_p * v_p))


@claim(F02, "same_momentum", "subs v_p from momentum")
def _():
    vp = solve(Eq(m_p * v_p - m_c * v_c, 0), v_p)[0]
    return zero((m_p * v_p - m_c * v_c).subs(v_p, vp))


@claim(F02, "energy_ratio", "subs + simplify chain")
def _():
    vp = solve(Eq(m_p * v_p - m_c * v_c, 0), v_p)[0]
    ratio = (R(1, 2) * v_p * m_p * v_p) / (R(1, 2) * v_c * m_c * v_c)
    return chain_equal(ratio.subs(v_p, vp), (v_p / v_c).subs(v_p, vp), m_c / m_p)


# ---------------------------------------------------------------------------------------------
# 03_ladder.dc
F03 = "03_ladder"
l, g = sp.symbols("l g", positive=True)
th, th0 = sp.symbols("theta theta0", positive=True)
om = sp.Symbol("omega", positive=True)
I_G = R(1, 12) * m * l**2
I_C = I_G + m * (l / 2)**2
omega_sq = 3 * g / l * (sp.sin(th0) - sp.sin(th))


@claim(F03, "inertia_C", "simplify")
def _():
    return zero(I_C - R(1, 3) * m * l**2)


@claim(F03, "omega_sq", "solve energy for omega")
def _():
    w2 = sp.Symbol("w2", positive=True)
    sol = solve(Eq(R(1, 2) * I_C * w2, m * g * l / 2 * (sp.sin(th0) - sp.sin(th))), w2)
    return in_solutions(sol, omega_sq)


@claim(F03, "velocity_G_sq", "subs + simplify")
def _():
    return zero((l / 2 * sp.sin(th))**2 * omega_sq - R(3, 4) * g * l * sp.sin(th)**2 * (sp.sin(th0) - sp.sin(th)))


@claim(F03, "slope", "diff + simplify")
def _():
    f = R(3, 4) * g * l * sp.sin(th)**2 * (sp.sin(th0) - sp.sin(th))
    return zero(diff(f, th) - R(3, 4) * g * l * sp.sin(th) * sp.cos(th) * (2 * sp.sin(th0) - 3 * sp.sin(th)))


@claim(F03, "leaves_wall", "solve for sin(theta) (stand-in symbol)")
def _():
    s, s0, c = sp.symbols("s s0 c")
    sol = solve(R(3, 4) * g * l * s * c * (2 * s0 - 3 * s), s)
    return in_solutions(sol, R(2, 3) * s0)


@claim(F03, "omega_leave", "subs + simplify")
def _():
    s0 = sp.Symbol("s0", positive=True)
    w2 = (3 * g / l * (s0 - sp.Symbol("s"))).subs(sp.Symbol("s"), R(2, 3) * s0)
    return zero(w2 - g / l * s0)


@claim(F03, "omega_at", "solve omega^2 = g/l sin(theta0) for omega > 0")
def _():
    sol = solve(Eq(om**2, g / l * sp.sin(th0)), om)
    return in_solutions(sol, sqrt(g / l * sp.sin(th0)))


@claim(F03, "wall_impulse", "subs chain + simplify")
def _():
    s0 = sp.Symbol("s0", positive=True)
    J = m * (l / 2 * R(2, 3) * s0 * sqrt(g / l * s0))
    return zero(J - R(1, 3) * m * s0 * sqrt(g * l * s0))


# ---------------------------------------------------------------------------------------------
# 04_system_of_particles.dc
F04 = "04_system_of_particles"
m1, m2, m3, m4 = sp.symbols("m1 m2 m3 m4", positive=True)
x1, x2, x3, xG = (Function(n) for n in ("x1", "x2", "x3", "xG"))
Mt = m1 + m2 + m3


@claim(F04, "centre_velocity", "diff of the centre of mass")
def _():
    lhs = diff(Mt * xG(t), t)
    rhs = diff(m1 * x1(t) + m2 * x2(t) + m3 * x3(t), t)
    xg = (m1 * x1(t) + m2 * x2(t) + m3 * x3(t)) / Mt
    return zero(lhs.subs(xG(t), xg).doit() - rhs)


@claim(F04, "total_momentum", "diff + subs chain")
def _():
    xg = (m1 * x1(t) + m2 * x2(t) + m3 * x3(t)) / Mt
    sides = [m1 * diff(x1(t), t) + m2 * diff(x2(t), t) + m3 * diff(x3(t), t),
             diff(m1 * x1(t) + m2 * x2(t) + m3 * x3(t), t),
             diff(Mt * xg, t), Mt * diff(xg, t)]
    return chain_equal(*[sp.expand(x.doit()) for x in sides])


Fs = sp.symbols("F1:5")
f = {(i, j): sp.Symbol(f"f{i}{j}") for i in range(1, 5) for j in range(1, 5) if i != j}


def external_only(n):
    third = {f[(j, i)]: -f[(i, j)] for i in range(1, n + 1) for j in range(i + 1, n + 1)}
    dps = [Fs[i - 1] + sum(f[(i, j)] for j in range(1, n + 1) if j != i) for i in range(1, n + 1)]
    return zero(sum(dps).subs(third) - sum(Fs[:n]))


@claim(F04, "external_only_3", "subs third law + simplify")
def _():
    return external_only(3)


@claim(F04, "external_only_4", "subs third law + simplify")
def _():
    return external_only(4)


@claim(F04, "vG_example", "subs numbers")
def _():
    v_10, v0 = sp.symbols("v_10 v0")
    vg = ((m1 * v_10 + m2 * v0) / (m1 + m2)).subs({m1: 1, m2: 2, v_10: 0, v0: 2})
    return zero(vg - R(4, 3))


vGf, pf, Ff, aG = (Function(n) for n in ("vG", "p", "F", "aG"))
Mb = sp.Symbol("M", positive=True)


@claim(F04, "rigid_rate", "diff")
def _():
    return zero(diff(Mb * vGf(t), t) - Mb * diff(vGf(t), t))


@claim(F04, "rigid_newton", "subs chain")
def _():
    dp = diff(Mb * vGf(t), t)
    return chain_equal(dp, Mb * diff(vGf(t), t), (Mb * aG(t)).subs(aG(t), diff(vGf(t), t)))


# ---------------------------------------------------------------------------------------------
# 05_direct_impact.dc
F05 = "05_direct_impact"
v1, v2, v1p, v2p, e = sp.symbols("v1 v2 v1p v2p e", real=True)
momentum = Eq(m1 * v1 + m2 * v2, m1 * v1p + m2 * v2p)
restitution = Eq(e, (v2p - v1p) / (v1 - v2))


def solve_impact(e_value=None):
    r = restitution if e_value is None else restitution.subs(e, e_value)
    return solve([momentum, r], [v1p, v2p], dict=True)[0]


v1p_el = ((m1 - m2) * v1 + 2 * m2 * v2) / (m1 + m2)
v2p_el = ((m2 - m1) * v2 + 2 * m1 * v1) / (m1 + m2)
v1p_gen = (m1 * v1 + m2 * v2 - e * m2 * (v1 - v2)) / (m1 + m2)
v2p_gen = (m1 * v1 + m2 * v2 - e * m1 * (v2 - v1)) / (m1 + m2)


@claim(F05, "restitution_elastic", "subs e = 1")
def _():
    return zero(restitution.rhs.subs(e, 1) - (v2p - v1p) / (v1 - v2)) and restitution.lhs.subs(e, 1) == 1


@claim(F05, "v1p_elastic", "solve (9.6), (9.7) with e = 1")
def _():
    return zero(solve_impact(1)[v1p] - v1p_el)


@claim(F05, "v2p_elastic", "solve (9.6), (9.7) with e = 1")
def _():
    return zero(solve_impact(1)[v2p] - v2p_el)


@claim(F05, "energy_elastic", "subs + simplify")
def _():
    return zero(R(1, 2) * m1 * v1**2 + R(1, 2) * m2 * v2**2 - R(1, 2) * m1 * v1p_el**2 - R(1, 2) * m2 * v2p_el**2)


@claim(F05, "v1p_equal", "subs m2 = m1")
def _():
    return zero(v1p_el.subs(m2, m1) - v2)


@claim(F05, "v2p_equal", "subs m2 = m1")
def _():
    return zero(v2p_el.subs(m2, m1) - v1)


@claim(F05, "v1p_wall", "limit m2 -> oo")
def _():
    f = v1p_el.subs(v2, 0)
    l1 = limit((m1 - m2) * v1 / (m1 + m2), m2, oo)
    l2 = limit((m1 / m2 - 1) * v1 / (m1 / m2 + 1), m2, oo)
    return chain_equal(limit(f, m2, oo), l1, l2, -v1)


@claim(F05, "v2p_wall", "limit m2 -> oo")
def _():
    return chain_equal(limit(v2p_el.subs(v2, 0), m2, oo), limit(2 * m1 * v1 / (m1 + m2), m2, oo), 0)


@claim(F05, "momentum_change_wall", "subs")
def _():
    return zero((m1 * v1p - m1 * v1).subs(v1p, -v1) + 2 * m1 * v1)


@claim(F05, "restitution_plastic", "subs e = 0")
def _():
    return restitution.lhs.subs(e, 0) == 0


vc = (m1 * v1 + m2 * v2) / (m1 + m2)


@claim(F05, "v_common", "solve with e = 0")
def _():
    s = solve_impact(0)
    return zero(s[v1p] - vc) and zero(s[v2p] - vc)


@claim(F05, "energy_loss_plastic", "subs + simplify chain")
def _():
    dT = R(1, 2) * m1 * v1**2 + R(1, 2) * m2 * v2**2 - (R(1, 2) * m1 * vc**2 + R(1, 2) * m2 * vc**2)
    return chain_equal(dT, R(1, 2) * m1 * v1**2 + R(1, 2) * m2 * v2**2 - R(1, 2) * (m1 + m2) * vc**2,
                       R(1, 2) * m1 * m2 / (m1 + m2) * (v1 - v2)**2)


@claim(F05, "energy_after_plastic", "simplify chain")
def _():
    return zero(R(1, 2) * (m1 + m2) * vc**2 - (m1 * v1 + m2 * v2)**2 / (2 * (m1 + m2)))


@claim(F05, "all_lost_when", "solve for v2")
def _():
    return in_solutions(solve((m1 * v1 + m2 * v2)**2 / (2 * (m1 + m2)), v2), -m1 * v1 / m2)


@claim(F05, "v1p_general", "solve (9.6), (9.7)")
def _():
    return zero(solve_impact()[v1p] - v1p_gen)


@claim(F05, "v2p_general", "solve (9.6), (9.7)")
def _():
    return zero(solve_impact()[v2p] - v2p_gen)


@claim(F05, "energy_loss_general", "subs + simplify")
def _():
    dT = R(1, 2) * m1 * v1**2 + R(1, 2) * m2 * v2**2 - (R(1, 2) * m1 * v1p_gen**2 + R(1, 2) * m2 * v2p_gen**2)
    return zero(dT - (1 - e**2) / 2 * m1 * m2 / (m1 + m2) * (v1 - v2)**2)


# ---------------------------------------------------------------------------------------------
# 06_ballistic_pendulum.dc
F06 = "06_ballistic_pendulum"
M, L, v0 = sp.symbols("M L v0", positive=True)
theta = sp.Symbol("theta", real=True)
v1b = sp.Symbol("v1", positive=True)
dh = sp.Symbol("dh", nonnegative=True)


@claim(F06, "v1_after", "solve momentum for v1")
def _():
    return in_solutions(solve(Eq(m * v0, (M + m) * v1b), v1b), m * v0 / (M + m))


@claim(F06, "energy_balance", "subs dT, dV into dT + dV = 0")
def _():
    dT = 0 - R(1, 2) * (M + m) * v1b**2
    dV = (M + m) * g * dh
    return zero((dT + dV) - (0 - R(1, 2) * (M + m) * v1b**2 + (M + m) * g * dh))


@claim(F06, "deflection", "subs + solve for theta")
def _():
    bal = (0 - R(1, 2) * (M + m) * v1b**2 + (M + m) * g * dh).subs(dh, L * (1 - sp.cos(theta)))
    bal = bal.subs(v1b, m * v0 / (M + m))
    return in_solutions(solve(bal, theta), sp.acos(1 - (m / (M + m))**2 * v0**2 / (2 * L * g)))


# ---------------------------------------------------------------------------------------------
# 07_two_ball_bounce.dc
F07 = "07_two_ball_bounce"
y2, r2 = sp.symbols("y2 r2", positive=True)
v0n = sp.Symbol("v0", negative=True)
v0p, e2, e12 = sp.symbols("v0p e2 e12", real=True)
mu = sp.Symbol("mu", positive=True)
v1p_mu = (mu * v1 + v2 - e12 * (v1 - v2)) / (mu + 1)
v2p_mu = (mu * v1 + v2 - e12 * mu * (v2 - v1)) / (mu + 1)
v1p_b = (mu - e2 - e12 * (1 + e2)) / (mu + 1) * v0n
v2p_b = (mu - e2 + mu * e12 * (1 + e2)) / (mu + 1) * v0n


@claim(F07, "fall_speed", "solve, negative root")
def _():
    # y2 > r2 is an assumption SymPy cannot hold on two symbols; a user substitutes y2 = r2 + h
    hh = sp.Symbol("h", positive=True)
    sol = solve(Eq(R(1, 2) * m2 * v0n**2, m2 * g * (y2 - r2)).subs(y2, r2 + hh), v0n)
    return in_solutions(sol, -sqrt(2 * g * hh))


@claim(F07, "ground_bounce", "solve for v0'")
def _():
    return in_solutions(solve(Eq(e2, (0 - v0p) / (v0n - 0)), v0p), -e2 * v0n)


def bounce_solve():
    mom = Eq(m1 * v1 + m2 * v2, m1 * v1p + m2 * v2p)
    res = Eq(e12, (v2p - v1p) / (v1 - v2))
    return solve([mom, res], [v1p, v2p], dict=True)[0]


@claim(F07, "v1p_general", "solve (9.6), (9.7)")
def _():
    return zero(bounce_solve()[v1p] - v1p_gen.subs(e, e12))


@claim(F07, "v2p_general", "solve (9.6), (9.7)")
def _():
    return zero(bounce_solve()[v2p] - v2p_gen.subs(e, e12))


@claim(F07, "v1p_mu", "subs m1 = mu m2")
def _():
    return zero(v1p_gen.subs(e, e12).subs(m1, mu * m2) - v1p_mu)


@claim(F07, "v2p_mu", "subs m1 = mu m2")
def _():
    return zero(v2p_gen.subs(e, e12).subs(m1, mu * m2) - v2p_mu)


@claim(F07, "v1p_bounce", "subs v1 = v0, v2 = -e2 v0")
def _():
    return zero(v1p_mu.subs({v1: v0n, v2: -e2 * v0n}) - v1p_b)


@claim(F07, "v2p_bounce", "subs v1 = v0, v2 = -e2 v0")
def _():
    return zero(v2p_mu.subs({v1: v0n, v2: -e2 * v0n}) - v2p_b)


@claim(F07, "v1p_light", "limit mu -> 0")
def _():
    return zero(limit(v1p_b, mu, 0) + (e2 + (1 + e2) * e12) * v0n)


@claim(F07, "v2p_light", "limit mu -> 0")
def _():
    return zero(limit(v2p_b, mu, 0) + e2 * v0n)


@claim(F07, "v1p_elastic", "subs e2 = e12 = 1")
def _():
    return zero((-(e2 + (1 + e2) * e12) * v0n).subs({e2: 1, e12: 1}) + 3 * v0n)


@claim(F07, "v2p_elastic", "subs e2 = 1")
def _():
    return zero((-e2 * v0n).subs(e2, 1) + v0n)


@claim(F07, "energy_ratio", "subs + simplify")
def _():
    return zero((R(1, 2) * m1 * (-3 * v0n)**2) / (R(1, 2) * m1 * v0n**2) - 9)


@claim(F07, "height_ratio", "subs + simplify")
def _():
    return zero(((-3 * v0n)**2 / (2 * g)) / (v0n**2 / (2 * g)) - 9)


# ---------------------------------------------------------------------------------------------
# 08_oblique_impact.dc
F08 = "08_oblique_impact"
v1n, v2n, v1t, v2t, v1np, v2np, v1tp, v2tp = sp.symbols("v1n v2n v1t v2t v1np v2np v1tp v2tp", real=True)
th1 = sp.Symbol("theta1", positive=True)
vv1 = sp.Symbol("v1", positive=True)


def oblique_solve():
    eqs = [Eq(m1 * v1n + m2 * v2n, m1 * v1np + m2 * v2np), Eq(m1 * v1t, m1 * v1tp),
           Eq(m2 * v2t, m2 * v2tp), Eq(e, (v2np - v1np) / (v1n - v2n))]
    return solve(eqs, [v1np, v2np, v1tp, v2tp], dict=True)[0]


v1np_sol = (m1 * v1n + m2 * v2n - e * m2 * (v1n - v2n)) / (m1 + m2)


@claim(F08, "v1tp_sol", "solve the 4 equations")
def _():
    return zero(oblique_solve()[v1tp] - v1t)


@claim(F08, "v2tp_sol", "solve the 4 equations")
def _():
    return zero(oblique_solve()[v2tp] - v2t)


@claim(F08, "v1np_sol", "solve the 4 equations")
def _():
    return zero(oblique_solve()[v1np] - v1np_sol)


@claim(F08, "v2np_sol", "solve the 4 equations")
def _():
    return zero(oblique_solve()[v2np] - (m1 * v1n + m2 * v2n - e * m1 * (v2n - v1n)) / (m1 + m2))


@claim(F08, "velocity1_after", "solve the 4 equations, both components")
def _():
    sol = oblique_solve()
    return zero(sol[v1np] - (m1 * v1n + m2 * v2n - e * m2 * (v1n - v2n)) / (m1 + m2)) and zero(sol[v1tp] - v1t)


@claim(F08, "velocity2_after", "solve the 4 equations, both components")
def _():
    sol = oblique_solve()
    return zero(sol[v2np] - (m1 * v1n + m2 * v2n - e * m1 * (v2n - v1n)) / (m1 + m2)) and zero(sol[v2tp] - v2t)


@claim(F08, "wall_n", "subs + limit m2 -> oo")
def _():
    f = v1np_sol.subs({v1n: vv1 * sp.cos(th1), v2n: 0})
    return zero(limit(f, m2, oo) + e * vv1 * sp.cos(th1))


@claim(F08, "rebound_angle", "subs + simplify")
def _():
    ep = sp.Symbol("e", positive=True)
    return zero((vv1 * sp.sin(th1)) / (ep * vv1 * sp.cos(th1)) - sp.tan(th1) / ep)


# ---------------------------------------------------------------------------------------------
# 09_rocket.dc
F09 = "09_rocket"
m_r, m0, dm, u_e, mur, dt = sp.symbols("m_r m0 dm u_e mu dt", positive=True)
vr_, dv, ar, D = sp.symbols("v dv a D", real=True)
tt = sp.Symbol("t", nonnegative=True)
mr, vr = Function("mr"), Function("vr")


@claim(F09, "momentum_first_order", "expand, drop dm*dv (series in a scale eps)")
def _():
    eps = sp.Symbol("eps")
    dp = (m_r - dm) * (vr_ + dv) + (vr_ - u_e) * dm - m_r * vr_
    first = sp.series(dp.subs({dm: eps * dm, dv: eps * dv}), eps, 0, 2).removeO().subs(eps, 1)
    return zero(first - (m_r * dv - u_e * dm))


@claim(F09, "rate", "divide by dt")
def _():
    return zero((m_r * dv - u_e * dm) / dt - (m_r * dv / dt - u_e * dm / dt))


@claim(F09, "rate_limit", "subs dv = a dt, dm = mu dt")
def _():
    return zero((m_r * dv / dt - u_e * dm / dt).subs({dv: ar * dt, dm: mur * dt}) - (m_r * ar - u_e * mur))


@claim(F09, "thrust", "solve")
def _():
    a_sol = solve(Eq(m_r * ar - u_e * mur, 0), ar)[0]
    return zero(m_r * a_sol - u_e * mur)


@claim(F09, "thrust_mass", "subs dm_r/dt = -mu")
def _():
    return zero(u_e * mur - (-u_e * diff(mr(tt), tt)).subs(diff(mr(tt), tt), -mur))


@claim(F09, "ideal", "subs D = 0, theta = 0")
def _():
    thr = sp.Symbol("theta")
    lhs = (u_e * mur - D - m_r * g * sp.cos(thr)).subs({D: 0, thr: 0})
    return zero(lhs - (u_e * mur - m_r * g))


@claim(F09, "ideal_ode", "subs a, m_r, mu")
def _():
    ideal = u_e * mur - m_r * g - m_r * ar
    s = ideal.subs({ar: diff(vr(tt), tt), m_r: mr(tt), mur: -diff(mr(tt), tt)})
    target = -u_e * diff(mr(tt), tt) - mr(tt) * g - mr(tt) * diff(vr(tt), tt)
    return zero(s - target)


@claim(F09, "velocity_rate", "solve for dv/dt")
def _():
    dvdt = sp.Symbol("dvdt")
    sol = solve(Eq(mr(tt) * dvdt, -u_e * diff(mr(tt), tt) - mr(tt) * g), dvdt)
    return in_solutions(sol, -u_e * diff(mr(tt), tt) / mr(tt) - g)


@claim(F09, "separated", "the ODE times dt, with dv = v'(t) dt and dm_r = m_r'(t) dt")
def _():
    dT = sp.Symbol("dT", real=True)
    dV, dM = diff(vr(tt), tt) * dT, diff(mr(tt), tt) * dT
    return zero(dV - (-u_e * dM / mr(tt) - g * dT) - dT * (diff(vr(tt), tt) - (-u_e * diff(mr(tt), tt) / mr(tt) - g)))


@claim(F09, "velocity_symbols", "integrate each separated term from v = 0, m_r = m0, t = 0")
def _():
    s = sp.Symbol("s", positive=True)
    integrated = vr_ + u_e * sp.integrate(1 / s, (s, m0, m_r)) + g * tt
    return in_solutions(solve(integrated, vr_), -u_e * log(m_r / m0) - g * tt)


@claim(F09, "mass_ratio", "subs v into exp((v + g t)/u_e)")
def _():
    G = -u_e * log(mr(tt) / m0) - g * tt
    return zero(exp((G + g * tt) / u_e) - m0 / mr(tt))


@claim(F09, "mass_t", "dsolve dm_r/dt = -mu, m_r(0) = m0")
def _():
    sol = sp.dsolve(Eq(diff(mr(tt), tt), -mur), mr(tt), ics={mr(0): m0})
    return zero(sol.rhs - (m0 - mur * tt))


@claim(F09, "burn_time", "solve for t")
def _():
    mrt = sp.Symbol("mrt", positive=True)
    return in_solutions(solve(Eq(mrt, m0 - mur * tt), tt), (m0 - mrt) / mur)


# ---------------------------------------------------------------------------------------------
# 10_falling_chain.dc
F10 = "10_falling_chain"
xs = sp.Symbol("x", positive=True)
vc_ = sp.Symbol("v", nonnegative=True)
N, u, mdot, rho, m_s, vdot = sp.symbols("N u mdot rho m_s vdot", real=True)


@claim(F10, "fall_speed", "solve, nonnegative root")
def _():
    dmm = sp.Symbol("dm", positive=True)
    return in_solutions(solve(Eq(R(1, 2) * dmm * vc_**2, dmm * g * xs), vc_), sqrt(2 * g * xs))


@claim(F10, "on_scale", "subs into F = m_s vdot + mdot u")
def _():
    Fs_ = sp.Symbol("Fsum")
    gen = Eq(Fs_, m_s * vdot + mdot * u).subs({Fs_: N - xs / L * m * g, m_s: xs / L * m, vdot: 0})
    return zero((gen.lhs - gen.rhs) - (N - xs / L * m * g - mdot * u))


@claim(F10, "on_scale_speed", "subs mdot, rho, u, v")
def _():
    e1 = (mdot * u).subs({mdot: rho * vc_, u: vc_}).subs(rho, m / L).subs(vc_, sqrt(2 * g * xs))
    return zero(e1 - sqrt(2 * g * xs) * m / L * sqrt(2 * g * xs))


@claim(F10, "scale_force", "solve for N")
def _():
    sol = solve(Eq(N - xs / L * m * g, sqrt(2 * g * xs) * m / L * sqrt(2 * g * xs)), N)
    return in_solutions(sol, 3 * xs / L * m * g)


# ---------------------------------------------------------------------------------------------
def main(argv):
    verbose = "--verbose" in argv
    json_path = None
    if "--json" in argv:
        json_path = argv[argv.index("--json") + 1]
    rows = []
    for file, label, how, fn in CHECKS:
        t0 = time.perf_counter()
        try:
            r = fn()
            status = "checked" if r is True else ("refuted" if r is False else "cannot")
            why = "" if r is not None else "no matching root / non-zero residual"
        except Exception as ex:  # SymPy raising counts as "cannot check"
            status, why = "cannot", f"{type(ex).__name__}: {ex}"[:160]
        dt_ms = (time.perf_counter() - t0) * 1e3
        rows.append({"file": file, "label": label, "how": how, "status": status, "why": why,
                     "ms": round(dt_ms, 2)})
        if verbose:
            print(f"{file}:{label:24s} {status:8s} {dt_ms:8.1f} ms  {how} {why}")
    n = len(rows)
    counts = {k: sum(r["status"] == k for r in rows) for k in ("checked", "refuted", "cannot")}
    wall = time.perf_counter() - T_START
    print(f"sympy_handout: claims={n} checked={counts['checked']} refuted={counts['refuted']} "
          f"cannot={counts['cannot']} sympy={sp.__version__} seconds={wall:.3f}")
    if json_path:
        with open(json_path + ".tmp", "w") as fh:
            json.dump({"claims": n, **counts, "sympy": sp.__version__, "rows": rows}, fh, indent=1)
        import os
        os.replace(json_path + ".tmp", json_path)
    return 1 if counts["refuted"] else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
