#!/usr/bin/env python3
"""Check the labels of the held-out documents in this folder with SymPy.

The checking machinery (scanning of displayed rows, the .expect format, the
world model, the derived / given / wrong / approx tests) is that of
../verify.py; this file only holds the hand-written transcriptions of the
held-out documents and points the machinery at this folder.  See ../README.md
for what is checked and README.md here for what the set is.

Run: python3 tests/data/documents/heldout/verify_heldout.py [NAME...]
(exit status 1 on a mismatch)
"""
import os
import sys

import sympy as sp

sys.dont_write_bytecode = True  # write nothing outside this folder
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
import verify as V  # noqa: E402

V.HERE = HERE          # check_doc opens NAME and NAME.expect relative to V.HERE
V.DOCS[:] = []         # drop the tuned documents; register only the held-out ones

S, R_, document, t, eps = V.S, V.R_, V.document, V.t, V.eps
half = sp.Rational(1, 2)


@document
def shm():
    m, k, A, ph, g, w0, T, K, U, E, d = S("m k A phi g omega_0 T K U E d")
    x, v = sp.symbols("x v", cls=sp.Function)
    arg = w0 * t + ph
    sn, cs = sp.sin(arg), sp.cos(arg)
    W = {w0: sp.sqrt(k / m), x: A * sp.cos(arg), v: -w0 * A * sp.sin(arg), T: 2 * sp.pi / w0,
         K: half * m * v(t)**2, U: half * k * x(t)**2, E: K + U, d: m * g / k}
    X = x(t)
    D = lambda f: sp.Derivative(f, t)
    D2 = lambda f: sp.Derivative(f, (t, 2))
    bracket = half * A**2 * (m * w0**2 * sn**2 + k * cs**2)
    rows = [
        R_(16, 0, "given", r"m \ddt{x} = -k x", m * D2(X), -k * X, "Newton with Hooke's law, introduces x(t)", intro=[x]),
        R_(20, 0, "given", r"\wo^2 = \frac{k}{m}", w0**2, k / m, "definition, new symbol omega_0", intro=[w0]),
        R_(24, 0, "derived", r"\ddt{x} + \wo^2 x = 0", D2(X) + w0**2 * X, 0, "divide (eq:newton) by m"),
        R_(28, 0, "given", r"x = A \cos\ph", X, A * cs, "general solution, introduces A and phi", intro=[A, ph]),
        R_(33, 1, "given", r"v = \od{x}{t}", v(t), D(X), "velocity defined, new symbol", intro=[v]),
        R_(33, 2, "derived", r"&= -\wo A \sin\ph", D(X), -w0 * A * sn, "differentiate (eq:x)"),
        R_(34, 1, "derived", r"\od{v}{t} &=", D(v(t)), -w0**2 * A * cs, "differentiate (eq:v)"),
        R_(34, 2, "derived", r"= -\wo^2 x", -w0**2 * A * cs, -w0**2 * X, "(eq:x)"),
        R_(39, 0, "given", r"T &= \frac{2\pi}{\wo}", T, 2 * sp.pi / w0, "period, new symbol", intro=[T]),
        R_(40, 0, "derived", r"&= 2\pi \sqrt{\frac{m}{k}}", 2 * sp.pi / w0, 2 * sp.pi * sp.sqrt(m / k), "substitute (eq:w0)"),
        R_(47, 1, "given", r"K &= \tfrac{1}{2} m v^2", K, half * m * v(t)**2, "kinetic energy, new symbol", intro=[K]),
        R_(47, 2, "wrong", r"\tfrac{1}{2} m \wo A^2", half * m * v(t)**2, half * m * w0 * A**2 * sn**2,
           "wrong power: omega_0 should be squared (units)"),
        R_(48, 1, "given", r"U &= \tfrac{1}{2} k x^2", U, half * k * X**2, "spring energy, new symbol", intro=[U]),
        R_(48, 2, "derived", r"\tfrac{1}{2} k A^2 \cos^2\ph", half * k * X**2, half * k * A**2 * cs**2, "substitute (eq:x)"),
        R_(52, 0, "given", r"E &= K + U", E, K + U, "total energy, new symbol", intro=[E]),
        R_(53, 0, "derived", r"\left[ m \wo^2 \sin^2\ph", K + U, bracket, "substitute K and U (correct K)"),
        R_(54, 0, "derived", r"&= \tfrac{1}{2} k A^2", bracket, half * k * A**2, "m omega_0^2 = k"),
        R_(64, 0, "given", r"k d = m g", k * d, m * g, "static balance, introduces d", intro=[d]),
        R_(69, 0, "derived", r"\wo = \sqrt{g/d}", w0, sp.sqrt(g / d), "(eq:w0) with k/m = g/d"),
        R_(73, 0, "wrong", r"T = 2\pi \sqrt{\frac{g}{d}}", T, 2 * sp.pi * sp.sqrt(g / d), "ratio inverted: sqrt(d/g) (units)"),
    ]
    return dict(name="shm.tex", world=W, rows=rows,
                params={m: (0.1, 2), k: (5, 50), A: (0.05, 0.5), ph: (0.1, 1.5), g: (9, 10), t: (0.1, 5)})


@document
def idealgas():
    n, R, T1, V1, V2, ga, Vv = S("n R T_1 V_1 V_2 gamma V")
    p, T, p1, W, Q, p2, T2, p3, T3, Wad = S("p T p_1 W Q p_2 T_2 p_3 T_3 W_ad")
    Wo = {p: n * R * T / Vv, T: T1, p1: n * R * T1 / V1, W: n * R * T1 * sp.log(V2 / V1), Q: W,
          p2: p1 * V1 / V2, T2: T1, p3: p1 * (V1 / V2)**ga, T3: p3 * V2 / (n * R),
          Wad: n * R * (T1 - T3) / (ga - 1)}
    adint = p1 * V1**ga / (1 - ga) * (V2**(1 - ga) - V1**(1 - ga))
    rows = [
        R_(5, 0, "given", r"p V = n R T", p * Vv, n * R * T, "equation of state, introduces p and T", intro=[p, T]),
        R_(9, 0, "given", r"p_1 = \frac{n R T_1}{V_1}", p1, n * R * T1 / V1, "state 1, introduces p_1", intro=[p1]),
        R_(17, 1, "given", r"W = \int_{V_1}^{V_2} p\,dV", W, sp.Integral(p, (Vv, V1, V2)), "work defined, new symbol", intro=[W]),
        R_(17, 2, "derived", r"= n R T_1 \int", sp.Integral(p, (Vv, V1, V2)), n * R * T1 * sp.Integral(1 / Vv, (Vv, V1, V2)),
           "gas law with T = T_1 (inline)"),
        R_(17, 3, "derived", r"= n R T_1 \ln\frac{V_2}{V_1}", n * R * T1 * sp.Integral(1 / Vv, (Vv, V1, V2)),
           n * R * T1 * sp.log(V2 / V1), "the integral"),
        R_(21, 0, "given", r"Q = W", Q, W, "first law with no change of internal energy, introduces Q", intro=[Q]),
        R_(25, 1, "given", r"p_2 V_2 = n R T_2", p2 * V2, n * R * T2, "gas law for state 2, introduces p_2", intro=[p2]),
        R_(25, 2, "derived", r"= p_1 V_1", n * R * T2, p1 * V1, "T_2 = T_1 (inline)"),
        R_(29, 0, "wrong", r"W = p_1 V_1 \ln\frac{p_2}{p_1}", W, p1 * V1 * sp.log(p2 / p1), "log inverted: ln(p_1/p_2)"),
        R_(33, 0, "approx", r"W \approx p_1", W, p1 * (V2 - V1), "first order in (V_2 - V_1)/V_1",
           regime={V2: V1 * (1 + eps)}),
        R_(41, 0, "given", r"p_3 V_2^{\gamma} = p_1 V_1^{\gamma}", p3 * V2**ga, p1 * V1**ga, "adiabat, introduces p_3", intro=[p3]),
        R_(43, 0, "given", r"p_3 V_2 = n R T_3", p3 * V2, n * R * T3, "gas law for state 3, introduces T_3", intro=[T3]),
        R_(47, 0, "wrong", r"T_3 V_2^{\gamma} = T_1 V_1^{\gamma}", T3 * V2**ga, T1 * V1**ga, "wrong power: gamma - 1"),
        R_(51, 0, "derived", r"T_3 = T_1 \left(", T3, T1 * (V1 / V2)**(ga - 1), "eliminate p_1, p_3"),
        R_(55, 1, "given", r"W_{\mathrm{ad}} = p_1 V_1^{\gamma} \int", Wad,
           p1 * V1**ga * sp.Integral(Vv**(-ga), (Vv, V1, V2)), "adiabatic work, new symbol", intro=[Wad]),
        R_(55, 2, "derived", r"{1 - \gamma} \left(", p1 * V1**ga * sp.Integral(Vv**(-ga), (Vv, V1, V2)), adint, "the integral"),
        R_(59, 1, "derived", r"W_{\mathrm{ad}} = \frac{p_1 V_1 - p_3 V_2}", Wad, (p1 * V1 - p3 * V2) / (ga - 1), "multiply out, p_3 V_2^gamma = p_1 V_1^gamma"),
        R_(59, 2, "wrong", r"\left( T_3 - T_1 \right)", (p1 * V1 - p3 * V2) / (ga - 1), n * R * (T3 - T1) / (ga - 1),
           "sign slip: T_1 - T_3"),
        R_(63, 0, "derived", r"\frac{W_{\mathrm{ad}}}{W}", Wad / W,
           (1 - (V1 / V2)**(ga - 1)) / ((ga - 1) * sp.log(V2 / V1)), "ratio of the two works"),
    ]
    return dict(name="idealgas.md", world=Wo, rows=rows, known=["T_2"],
                params={n: (0.5, 3), R: (8, 9), T1: (250, 400), V1: (1, 2), V2: (3, 6), ga: (1.3, 1.7), Vv: (1, 6)})


@document
def bernoulli():
    rho, A1, A2, v1, p1, rm, g = S("rho A_1 A_2 v_1 p_1 rho_m g")
    Q, v2, p2, Dp, h, p0 = S("Q v_2 p_2 Delta_p h p_0")
    W = {Q: A1 * v1, v2: A1 * v1 / A2, p2: p1 + half * rho * (v1**2 - v2**2), Dp: p1 - p2,
         h: Dp / ((rm - rho) * g), p0: p1 + half * rho * v1**2}
    root = sp.sqrt(2 * Dp / (rho * (A1**2 - A2**2)))
    rows = [
        R_(13, 1, "given", r"Q = A_1 v_1", Q, A1 * v1, "flow rate defined, new symbol", intro=[Q]),
        R_(13, 2, "given", r"= A_2 v_2", A1 * v1, A2 * v2, "continuity, introduces v_2", intro=[v2]),
        R_(17, 0, "derived", r"v_2 = \frac{A_1}{A_2}\, v_1", v2, A1 / A2 * v1, "solve (cont)"),
        R_(26, 0, "given", r"p_1 + \frac{1}{2}\rho v_1^2 = p_2", p1 + half * rho * v1**2, p2 + half * rho * v2**2,
           "Bernoulli, introduces p_2", intro=[p2]),
        R_(30, 1, "given", r"\Delta p = p_1 - p_2", Dp, p1 - p2, "pressure drop defined, new symbol", intro=[Dp]),
        R_(30, 2, "wrong", r"\left( v_1^2 - v_2^2 \right)", p1 - p2, half * rho * (v1**2 - v2**2), "sign slip: v_2^2 - v_1^2"),
        R_(34, 0, "derived", r"\Delta p = \frac{1}{2}\rho v_1^2 \left(", Dp, half * rho * v1**2 * (A1**2 / A2**2 - 1),
           "(bern) with v_2 from (cont)"),
        R_(41, 0, "derived", r"v_1 = A_2 \sqrt{\frac{2\,\Delta p}", v1, A2 * root, "solve for v_1 > 0"),
        R_(45, 0, "derived", r"Q = A_1 A_2 \sqrt", Q, A1 * A2 * root, "Q = A_1 v_1"),
        R_(51, 0, "approx", r"v_2 \approx", v2, sp.sqrt(2 * Dp / rho), "leading order for A_2 << A_1",
           regime={A2: eps * A2}),
        R_(57, 0, "given", r"\Delta p = (\rho_m - \rho)\, g h", Dp, (rm - rho) * g * h, "manometer, introduces h", intro=[h]),
        R_(61, 0, "wrong", r"\frac{g h\,(\rho_m - \rho)}", v1, A2 * sp.sqrt(g * h * (rm - rho) / (rho * (A1**2 - A2**2))),
           "dropped factor 2 under the root"),
        R_(70, 0, "given", r"p_0 = p_1 + \tfrac{1}{2}\rho v_1^2", p0, p1 + half * rho * v1**2,
           "stagnation pressure (Bernoulli to rest), new symbol", intro=[p0]),
        R_(74, 0, "derived", r"v_1 = \sqrt{2\,(p_0 - p_1)/\rho}", v1, sp.sqrt(2 * (p0 - p1) / rho), "solve for v_1"),
        R_(78, 0, "derived", r"\frac{\Delta p}{Q^2}", Dp / Q**2, rho / 2 * (1 / A2**2 - 1 / A1**2), "Delta p over (A_1 v_1)^2"),
    ]
    return dict(name="bernoulli.tex", world=W, rows=rows,
                params={rho: (0.9, 1.1), A1: (2, 4), A2: (0.5, 1.5), v1: (0.5, 3), p1: (50, 100), rm: (10, 14), g: (9, 10)})


@document
def capacitor():
    Q, A, d, e0, C1, C2, V0 = S("Q A d epsilon_0 C_1 C_2 V_0")
    sg, E, Vv, C, U, u, Qs, Cs, Us, Q1, Q2, Cp = S("sigma E V C U u Q_s C_s U_s Q_1 Q_2 C_p")
    q = sp.Symbol("q", positive=True)
    W = {sg: Q / A, E: sg / e0, Vv: E * d, C: Q / Vv, U: Q**2 / (2 * C), u: U / (A * d),
         Qs: V0 * C1 * C2 / (C1 + C2), Cs: Qs / V0, Us: half * Cs * V0**2,
         Q1: C1 * V0, Q2: C2 * V0, Cp: (Q1 + Q2) / V0}
    Weq = dict(W)
    Weq[C2] = C1
    rows = [
        R_(9, 0, "given", r"\sigma = \dfrac{Q}{A}", sg, Q / A, "surface density, new symbol", intro=[sg]),
        R_(13, 0, "given", r"E = \dfrac{\sigma}{\epsilon_0}", E, sg / e0, "Gauss's law, introduces E", intro=[E]),
        R_(17, 0, "given", r"V = E d", Vv, E * d, "uniform field, introduces V", intro=[Vv]),
        R_(21, 0, "derived", r"V = \dfrac{Q d}{\epsilon_0 A}", Vv, Q * d / (e0 * A), "(1) into (2) into (3)"),
        R_(25, 1, "given", r"C = \dfrac{Q}{V}", C, Q / Vv, "capacitance defined, new symbol", intro=[C]),
        R_(25, 2, "derived", r"= \dfrac{\epsilon_0 A}{d}", Q / Vv, e0 * A / d, "substitute V"),
        R_(33, 1, "given", r"U = \int_0^Q", U, sp.Integral(q / C, (q, 0, Q)), "energy as work of charging, new symbol", intro=[U]),
        R_(33, 2, "derived", r"= \dfrac{Q^2}{2C}", sp.Integral(q / C, (q, 0, Q)), Q**2 / (2 * C), "the integral"),
        R_(33, 3, "derived", r"= \dfrac{1}{2} C V^2", Q**2 / (2 * C), half * C * Vv**2, "Q = C V from (4)"),
        R_(37, 1, "given", r"u = \dfrac{U}{A d}", u, U / (A * d), "energy density, new symbol", intro=[u]),
        R_(37, 2, "wrong", r"= \epsilon_0 E^2", U / (A * d), e0 * E**2, "dropped factor 1/2"),
        R_(45, 0, "given", r"V_0 = \dfrac{Q_s}{C_1}", V0, Qs / C1 + Qs / C2, "voltages add in series, introduces Q_s", intro=[Qs]),
        R_(49, 1, "derived", r"\dfrac{1}{C_s} =", 1 / Cs, 1 / C1 + 1 / C2, "divide (6) by Q_s; C_s = Q_s/V_0 (inline)"),
        R_(49, 2, "derived", r"C_s = \dfrac{C_1 C_2}{C_1 + C_2}", Cs, C1 * C2 / (C1 + C2), "solve for C_s"),
        R_(53, 1, "given", r"U_s = \dfrac{1}{2} C_s V_0^2", Us, half * Cs * V0**2, "energy of the pair, new symbol", intro=[Us]),
        R_(53, 2, "wrong", r"= \dfrac{C_1 C_2 V_0^2}{C_1 + C_2}", half * Cs * V0**2, C1 * C2 * V0**2 / (C1 + C2), "dropped factor 1/2"),
        R_(57, 1, "given", r"C_p = \dfrac{Q_1 + Q_2}{V_0}", Cp, (Q1 + Q2) / V0, "parallel capacitance, new symbol", intro=[Cp]),
        R_(57, 2, "derived", r"= C_1 + C_2", (Q1 + Q2) / V0, C1 + C2, "Q_1 = C_1 V_0, Q_2 = C_2 V_0 (inline)"),
        R_(61, 0, "derived", r"\dfrac{(C_1 + C_2)^2}{C_1 C_2}", Cp / Cs, (C1 + C2)**2 / (C1 * C2), "(7) and (8)"),
        R_(65, 0, "wrong", r"\dfrac{C_p}{C_s} = 2", Cp / Cs, 2, "C_1 = C_2 (inline): the ratio is 4", world=Weq),
    ]
    return dict(name="capacitor.md", world=W, rows=rows, known=["C_s", "Q_1", "Q_2"],
                params={Q: (1, 5), A: (0.5, 2), d: (0.01, 0.1), e0: (1, 2), C1: (1, 5), C2: (1, 5), V0: (1, 12)})


@document
def inclined():
    m, g, th, ms, mk, L, v0 = S("m g theta mu_s mu_k L v_0")
    Wx, Wy, N, tc, a, v, Wf, au, s = S("W_x W_y N theta_c a v W_f a_up s")
    sn, cs = sp.sin(th), sp.cos(th)
    W = {Wx: m * g * sn, Wy: -m * g * cs, N: m * g * cs, tc: sp.atan(ms), a: g * (sn - mk * cs),
         v: sp.sqrt(2 * a * L), Wf: mk * m * g * L * cs, au: g * (sn + mk * cs), s: v0**2 / (2 * au)}
    rows = [
        R_(12, 0, "given", r"W_x &=& m g \sin\theta", Wx, m * g * sn, "weight component, new symbol", intro=[Wx]),
        R_(13, 0, "given", r"W_y &=& -m g \cos\theta", Wy, -m * g * cs, "weight component, new symbol", intro=[Wy]),
        R_(18, 0, "given", r"N + W_y &=& 0", N + Wy, 0, "no motion across the slope, introduces N", intro=[N]),
        R_(19, 0, "derived", r"N &=& m g \cos\theta", N, m * g * cs, "substitute W_y"),
        R_(27, 0, "given", r"m g \sin\theta_c &=& \mu_s", m * g * sp.sin(tc), ms * m * g * sp.cos(tc),
           "friction at its limit, introduces theta_c", intro=[tc]),
        R_(28, 0, "derived", r"\tan\theta_c &=& \mu_s", sp.tan(tc), ms, "divide by m g cos theta_c"),
        R_(33, 0, "wrong", r"\cos\theta_c = \frac{1}{1 + \mu_s^2}", sp.cos(tc), 1 / (1 + ms**2), "square root missing"),
        R_(40, 0, "given", r"m a &=& W_x - \mu_k N", m * a, Wx - mk * N, "Newton along the slope, introduces a", intro=[a]),
        R_(41, 0, "derived", r"&=& m g \sin\theta - \mu_k", Wx - mk * N, m * g * sn - mk * m * g * cs, "substitute W_x and N"),
        R_(42, 0, "wrong", r"a &=& g \left( \cos\theta - \mu_k \sin\theta", a, g * (cs - mk * sn), "sin and cos swapped"),
        R_(47, 0, "given", r"v^2 &=& 2 a L", v**2, 2 * a * L, "uniform acceleration from rest, introduces v", intro=[v]),
        R_(48, 0, "derived", r"&=& 2 g L \left( \sin\theta", 2 * a * L, 2 * g * L * (sn - mk * cs), "substitute the correct a"),
        R_(52, 1, "given", r"W_f &=& \mu_k N L", Wf, mk * N * L, "work of friction, new symbol", intro=[Wf]),
        R_(52, 2, "derived", r"= \mu_k m g L \cos\theta", mk * N * L, mk * m * g * L * cs, "(eq:N)"),
        R_(53, 0, "derived", r"\tfrac{1}{2} m v^2 &=& m g L \sin\theta - W_f", half * m * v**2, m * g * L * sn - Wf, "energy balance"),
        R_(60, 0, "approx", r"a \approx g \left( \theta - \mu_k \right)", a, g * (th - mk), "first order in theta, mu_k",
           regime={th: eps * th, mk: eps * mk}),
        R_(67, 0, "given", r"a_{\mathrm{up}} = g \left( \sin\theta + \mu_k", au, g * (sn + mk * cs),
           "Newton with friction reversed, new symbol", intro=[au]),
        R_(71, 0, "given", r"v_0^2 &=& 2 a_{\mathrm{up}} s", v0**2, 2 * au * s, "uniform deceleration, introduces s", intro=[s]),
        R_(72, 0, "wrong", r"s &=& \frac{v_0^2}{g \left(", s, v0**2 / (g * (sn + mk * cs)), "dropped factor 2"),
    ]
    return dict(name="inclined.tex", world=W, rows=rows,
                params={m: (0.5, 5), g: (9, 10), th: (0.6, 1.2), ms: (0.2, 0.9), mk: (0.1, 0.5), L: (1, 5), v0: (1, 5)})


@document
def relativity():
    v, c, Dtau, f0, m = S("v c Delta_tau f_0 m")
    be, ga, Dt, d, dp, T0, T, f, E, p = S("beta gamma Delta_t d d' T_0 T f E p")
    W = {be: v / c, ga: 1 / sp.sqrt(1 - v**2 / c**2), Dt: ga * Dtau, d: v * Dt, dp: d / ga,
         T0: 1 / f0, T: ga * (1 - be) * T0, f: 1 / T, E: ga * m * c**2, p: ga * m * v}
    rows = [
        R_(11, 1, "given", r"\beta = \frac{v}{c}", be, v / c, "definition, new symbol", intro=[be]),
        R_(11, 2, "given", r"\gamma = \frac{1}{\sqrt{1 - v^2/c^2}}", ga, 1 / sp.sqrt(1 - v**2 / c**2), "Lorentz factor, new symbol", intro=[ga]),
        R_(11, 3, "derived", r"= \frac{1}{\sqrt{1 - \beta^2}}", 1 / sp.sqrt(1 - v**2 / c**2), 1 / sp.sqrt(1 - be**2), "v/c = beta"),
        R_(15, 0, "wrong", r"v = c \sqrt{1 - 1/\gamma}", v, c * sp.sqrt(1 - 1 / ga), "wrong power: 1/gamma^2"),
        R_(19, 0, "derived", r"\beta^2 = 1 - \frac{1}{\gamma^2}", be**2, 1 - 1 / ga**2, "invert gamma"),
        R_(27, 0, "given", r"\Delta t = \gamma\, \Delta\tau", Dt, ga * Dtau, "time dilation, new symbol", intro=[Dt]),
        R_(31, 1, "given", r"d = v\, \Delta t", d, v * Dt, "distance in the lab, new symbol", intro=[d]),
        R_(31, 2, "derived", r"\frac{v\, \Delta\tau}{\sqrt{1 - v^2/c^2}}", v * Dt, v * Dtau / sp.sqrt(1 - v**2 / c**2), "substitute Delta t, gamma"),
        R_(35, 1, "given", r"d' = \frac{d}{\gamma}", dp, d / ga, "length contraction, new symbol", intro=[dp]),
        R_(35, 2, "derived", r"= v\, \Delta\tau", d / ga, v * Dtau, "substitute d"),
        R_(45, 0, "given", r"T = \gamma\, (1 - \beta)\, T_0", T, ga * (1 - be) * T0, "received period, new symbol", intro=[T]),
        R_(49, 1, "given", r"f = \frac{1}{T}", f, 1 / T, "received frequency, new symbol", intro=[f]),
        R_(49, 2, "derived", r"= \frac{f_0}{\gamma\, (1 - \beta)}", 1 / T, f0 / (ga * (1 - be)), "T_0 = 1/f_0 (inline)"),
        R_(53, 0, "wrong", r"\frac{1}{\gamma\, (1 - \beta)} = \sqrt{\frac{1 - \beta}{1 + \beta}}", 1 / (ga * (1 - be)),
           sp.sqrt((1 - be) / (1 + be)), "ratio inverted: sqrt((1+beta)/(1-beta))"),
        R_(57, 0, "derived", r"f = f_0 \sqrt{\frac{1 + \beta}{1 - \beta}}", f, f0 * sp.sqrt((1 + be) / (1 - be)), "from the correct identity"),
        R_(61, 0, "approx", r"f \approx f_0", f, f0 * (1 + v / c), "first order in v/c", regime={v: eps * v}),
        R_(69, 1, "given", r"E = \gamma m c^2", E, ga * m * c**2, "energy, new symbol", intro=[E]),
        R_(69, 2, "given", r"p = \gamma m v", p, ga * m * v, "momentum, new symbol", intro=[p]),
        R_(73, 1, "derived", r"E^2 - p^2 c^2 = \gamma^2 m^2 c^4", E**2 - p**2 * c**2, ga**2 * m**2 * c**4 * (1 - be**2), "substitute E, p"),
        R_(73, 2, "derived", r"= m^2 c^4", ga**2 * m**2 * c**4 * (1 - be**2), m**2 * c**4, "gamma^2 (1 - beta^2) = 1"),
    ]
    return dict(name="relativity.md", world=W, rows=rows, known=["T_0"],
                params={v: (0.1, 1.5), c: (2, 3), Dtau: (1, 3), f0: (1, 10), m: (0.5, 2)})


if __name__ == "__main__":
    sys.exit(V.main())
