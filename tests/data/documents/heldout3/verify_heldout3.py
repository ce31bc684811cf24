#!/usr/bin/env python3
"""Check the labels of the third held-out set (this folder) with SymPy.

The checking machinery (scanning of displayed rows, the .expect format, the
world model, the derived / given / wrong / approx tests) is that of
../verify.py; this file only holds the hand-written transcriptions of the
documents in this folder and points the machinery here.  See ../README.md for
what is checked and README.md here for what the set is.

Run: python3 tests/data/documents/heldout3/verify_heldout3.py [NAME...]
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
V.DOCS[:] = []         # drop the tuned documents; register only these

S, R_, document, t, eps = V.S, V.R_, V.document, V.t, V.eps
half = sp.Rational(1, 2)
D = lambda f: sp.Derivative(f, t)
D2 = lambda f: sp.Derivative(f, (t, 2))


@document
def rotation():
    M, L, g, R, F, I1, I2, w1 = S("M L g R F I_1 I_2 omega_1")
    lam, Icm, Iend, w, vtip, Id, w2, K1, K2, W, dl = S("lambda I_cm I_end omega v_tip I_d omega_2 K_1 K_2 W delta")
    x = sp.Symbol("x", real=True)
    Om = sp.Function("Omega")
    Wo = {lam: M / L, Icm: M * L**2 / 12, Iend: M * L**2 / 3, w: sp.sqrt(3 * g / L), vtip: w * L,
          Id: half * M * R**2, Om: 2 * F * t / (M * R), w2: I1 * w1 / I2,
          K1: half * I1 * w1**2, K2: half * I2 * w2**2, W: K2 - K1, dl: 1 - I2 / I1}
    integral = sp.Integral(lam * x**2, (x, -L / 2, L / 2))
    rows = [
        R_(17, 0, "given", r"\Icm &= \int_{-L/2}^{L/2}", Icm, integral, "moment of inertia as a sum over the rod, new symbol", intro=[Icm]),
        R_(18, 0, "derived", r"&= \frac{\lambda L^3}{12}", integral, lam * L**3 / 12, "the integral"),
        R_(19, 0, "derived", r"&= \frac{1}{12} M L^2", lam * L**3 / 12, M * L**2 / 12, "lambda = M/L (inline)"),
        R_(25, 1, "given", r"\Iend = \Icm + M \left(", Iend, Icm + M * (L / 2)**2, "parallel-axis theorem at L/2, introduces I_end", intro=[Iend]),
        R_(25, 2, "derived", r"= \frac{1}{3} M L^2", Icm + M * (L / 2)**2, M * L**2 / 3, "substitute I_cm"),
        R_(35, 0, "given", r"M g \, \frac{L}{2} = \frac{1}{2} \Iend", M * g * L / 2, half * Iend * w**2,
           "energy conservation, introduces omega", intro=[w]),
        R_(39, 0, "wrong", r"\omega^2 = \frac{6 g}{L}", w**2, 6 * g / L, "dropped the 1/2 of L/2: 3g/L"),
        R_(43, 1, "given", r"v_{\mathrm{tip}} = \omega L", vtip, w * L, "tip speed, new symbol", intro=[vtip]),
        R_(43, 2, "derived", r"= \sqrt{3 g L}", w * L, sp.sqrt(3 * g * L), "correct omega^2 = 3g/L, omega > 0"),
        R_(53, 0, "given", r"\Id \, \dot{\Omega} = F R", Id * D(Om(t)), F * R, "torque equation, introduces Omega", intro=[Om]),
        R_(57, 0, "derived", r"\dot{\Omega} = \frac{2 F}{M R}", D(Om(t)), 2 * F / (M * R), "I_d = M R^2/2 (inline)"),
        R_(65, 0, "given", r"I_1 \omega_1 = I_2 \omega_2", I1 * w1, I2 * w2, "angular momentum conserved, introduces omega_2", intro=[w2]),
        R_(66, 1, "given", r"K_1 = \tfrac12 I_1 \omega_1^2", K1, half * I1 * w1**2, "kinetic energy before, new symbol", intro=[K1]),
        R_(66, 2, "given", r"K_2 = \tfrac12 I_2 \omega_2^2", K2, half * I2 * w2**2, "kinetic energy after, new symbol", intro=[K2]),
        R_(70, 0, "derived", r"\omega_2 &= \frac{I_1}{I_2}", w2, I1 * w1 / I2, "solve (eq:L)"),
        R_(71, 1, "derived", r"\frac{K_2}{K_1} &=", K2 / K1, I2 * w2**2 / (I1 * w1**2), "ratio of the two energies"),
        R_(71, 2, "wrong", r"= \frac{I_2}{I_1}", I2 * w2**2 / (I1 * w1**2), I2 / I1, "ratio inverted: I_1/I_2"),
        R_(76, 1, "given", r"W = K_2 - K_1", W, K2 - K1, "work by the arms, new symbol", intro=[W]),
        R_(76, 2, "wrong", r"\left( 1 - \frac{I_1}{I_2} \right)", K2 - K1, half * I1 * w1**2 * (1 - I1 / I2), "sign slip: (I_1/I_2 - 1)"),
        R_(81, 0, "approx", r"W \approx K_1 \, \delta", W, K1 * dl, "first order in delta (inline I_2 = I_1 (1 - delta))",
           regime={I2: I1 * (1 - eps)}),
    ]
    return dict(name="rotation.tex", world=Wo, rows=rows, known=["lambda", "I_d", "delta"],
                params={M: (0.5, 3), L: (0.5, 2), g: (9, 10), R: (0.1, 0.5), F: (1, 10), I1: (3, 5), I2: (1, 2.5),
                        w1: (1, 6), t: (0.1, 3)})


@document
def lenses():
    n, R1, R2, so, f1, f2, d, R, y = S("n R_1 R_2 s_o f_1 f_2 d R y")
    f, si, m, xo, xi, s1, s2, feq, th, fy = S("f s_i m x_o x_i s_1 s_2 f_eq theta f_y")
    W = {f: 1 / ((n - 1) * (1 / R1 - 1 / R2)), si: f * so / (so - f), m: -si / so, xo: so - f, xi: si - f,
         s1: 1 / (1 / f1 - 1 / so), s2: 1 / (1 / f2 - 1 / (d - s1)), feq: f1 * f2 / (f1 + f2),
         th: sp.asin(y / R), fy: R - R / (2 * sp.cos(th))}
    Wequi = dict(W)
    Wequi[R2] = -R1
    Wtouch = dict(W)
    Wtouch[d] = 0
    Wsame = dict(W)
    Wsame[f2] = f1
    expand = so * si - f * (so + si) + f**2
    rows = [
        R_(15, 0, "given", r"\inv{f} = (n - 1)", 1 / f, (n - 1) * (1 / R1 - 1 / R2), "lensmaker's formula, introduces f", intro=[f]),
        R_(19, 0, "derived", r"f = \frac{R_1}{2\,(n - 1)}", f, R1 / (2 * (n - 1)), "R_2 = -R_1 (inline)", world=Wequi),
        R_(27, 0, "given", r"\inv{\so} + \inv{\si} &=& \inv{f}", 1 / so + 1 / si, 1 / f, "thin-lens equation, introduces s_i", intro=[si]),
        R_(28, 0, "derived", r"\si &=& \frac{f\,\so}{\so - f}", si, f * so / (so - f), "solve (eq:lens) for s_i"),
        R_(32, 1, "given", r"m = -\frac{\si}{\so}", m, -si / so, "magnification, new symbol", intro=[m]),
        R_(32, 2, "wrong", r"= -\frac{f}{f - \so}", -si / so, -f / (f - so), "sign slip: -f/(s_o - f)"),
        R_(38, 0, "derived", r"x_{\mathrm{o}} \cdot x_{\mathrm{i}} &=&", xo * xi, expand,
           "multiply out (inline x_o = s_o - f, x_i = s_i - f)"),
        R_(39, 0, "derived", r"&=& f^2", expand, f**2, "(eq:lens): s_o s_i = f (s_o + s_i)"),
        R_(43, 1, "derived", r"m = -\frac{f}{x_{\mathrm{o}}}", m, -f / xo, "correct m = -f/(s_o - f) with x_o = s_o - f (inline)"),
        R_(43, 2, "wrong", r"= -\frac{f}{x_{\mathrm{i}}}", -f / xo, -f / xi, "swapped: -x_i/f"),
        R_(51, 0, "given", r"\inv{\so} + \inv{s_1} &= \inv{f_1}", 1 / so + 1 / s1, 1 / f1, "first lens, introduces s_1", intro=[s1]),
        R_(52, 0, "given", r"\inv{d - s_1} + \inv{s_2} &= \inv{f_2}", 1 / (d - s1) + 1 / s2, 1 / f2,
           "second lens, introduces s_2", intro=[s2]),
        R_(56, 0, "derived", r"\inv{\so} + \inv{s_2} = \inv{f_1} + \inv{f_2}", 1 / so + 1 / s2, 1 / f1 + 1 / f2,
           "add (eq:first) and (eq:second) with d = 0 (inline)", world=Wtouch),
        R_(60, 0, "given", r"\inv{\feq} &= \inv{f_1} + \inv{f_2}", 1 / feq, 1 / f1 + 1 / f2, "equivalent lens, new symbol", intro=[feq]),
        R_(61, 0, "derived", r"\feq &= \frac{f_1 f_2}{f_1 + f_2}", feq, f1 * f2 / (f1 + f2), "solve (eq:feq)"),
        R_(65, 0, "wrong", r"\feq = 2 f_1", feq, 2 * f1, "f_2 = f_1 (inline): f_eq = f_1/2", world=Wsame),
        R_(74, 0, "given", r"f_y = R - \frac{R}{2\cos\theta}", fy, R - R / (2 * sp.cos(th)),
           "reflection geometry, introduces f_y (sin theta = y/R inline)", intro=[fy]),
        R_(78, 0, "approx", r"f_y \approx \frac{R}{2} ,", fy, R / 2, "leading order for y << R", regime={y: eps * y}),
        R_(82, 0, "approx", r"f_y \approx \frac{R}{2} - \frac{y^2}{4 R}", fy, R / 2 - y**2 / (4 * R),
           "second order in y/R", regime={y: eps * y}),
    ]
    return dict(name="lenses.tex", world=W, rows=rows, known=["x_o", "x_i", "theta"],
                params={n: (1.4, 1.7), R1: (1, 2), R2: (3, 6), so: (8, 12), f1: (1, 4), f2: (2, 6), d: (1, 3),
                        R: (2, 5), y: (0.1, 1)})


@document
def drag():
    m, g, b, c = S("m g b c")
    vt, tau, th, ut = S("v_t tau t_h u_t")
    tp = sp.Symbol("tp", positive=True)
    v, y, u = sp.symbols("v y u", cls=sp.Function)
    W = {vt: m * g / b, tau: m / b, v: vt * (1 - sp.exp(-t / tau)), y: vt * t - vt * tau * (1 - sp.exp(-t / tau)),
         th: tau * sp.log(2), ut: sp.sqrt(m * g / c), u: ut * sp.tanh(g * t / ut)}
    integral = sp.Integral(v(tp), (tp, 0, t))
    rows = [
        R_(15, 0, "given", r"m \dot{v} = m g - b v", m * D(v(t)), m * g - b * v(t), "Newton with linear drag, introduces v", intro=[v]),
        R_(20, 0, "given", r"m g - b \vt = 0", m * g - b * vt, 0, "terminal condition, introduces v_t", intro=[vt]),
        R_(24, 0, "derived", r"\vt = \frac{m g}{b}", vt, m * g / b, "solve for v_t"),
        R_(28, 0, "given", r"\tau = \frac{m}{b}", tau, m / b, "time constant, new symbol", intro=[tau]),
        R_(32, 0, "derived", r"\dot{v} = \frac{\vt - v}{\tau}", D(v(t)), (vt - v(t)) / tau, "divide (eq:eom) by m"),
        R_(36, 0, "derived", r"-\ln\left( 1 - \frac{v}{\vt} \right)", -sp.log(1 - v(t) / vt), t / tau,
           "separate and integrate (inline v(0) = 0)"),
        R_(37, 0, "derived", r"v &= \vt \left( 1 - e^{-t/\tau}", v(t), vt * (1 - sp.exp(-t / tau)), "solve for v"),
        R_(41, 0, "wrong", r"\dot{v} = -\frac{\vt}{\tau}", D(v(t)), -vt / tau * sp.exp(-t / tau), "sign slip in the chain rule"),
        R_(46, 0, "approx", r"v \approx g t", v(t), g * t, "first order in t/tau", regime={t: eps * t}),
        R_(53, 0, "given", r"y &= \int_0^t v(t')", y(t), integral, "distance as the integral, introduces y", intro=[y]),
        R_(54, 0, "wrong", r"&= \vt \, t - \vt \left(", integral, vt * t - vt * (1 - sp.exp(-t / tau)), "dropped factor tau (units)"),
        R_(58, 0, "approx", r"y \approx \vt \, (t - \tau)", y(t), vt * (t - tau), "t >> tau", regime={t: t / eps}),
        R_(63, 0, "given", r"v(t_{1/2}) = \tfrac12 \vt", v(th), half * vt, "half terminal speed, introduces t_1/2", intro=[th]),
        R_(67, 1, "derived", r"t_{1/2} = \tau \ln 2", th, tau * sp.log(2), "solve e^{-t/tau} = 1/2"),
        R_(67, 2, "approx", r"\approx 0.693\, \tau", tau * sp.log(2), sp.Rational(693, 1000) * tau, "ln 2 to three digits",
           tol=1e-3),
        R_(74, 0, "given", r"m \dot{u} = m g - c u^2", m * D(u(t)), m * g - c * u(t)**2, "Newton with quadratic drag, introduces u",
           intro=[u]),
        R_(75, 0, "given", r"c\, \ut^2 = m g", c * ut**2, m * g, "terminal condition, introduces u_t", intro=[ut]),
        R_(79, 0, "derived", r"\ut = \sqrt{\frac{m g}{c}}", ut, sp.sqrt(m * g / c), "solve for u_t > 0"),
        R_(83, 0, "wrong", r"\frac{\ut}{\vt} = \frac{\sqrt{m g c}}{b}", ut / vt, sp.sqrt(m * g * c) / b,
           "ratio inverted: b/sqrt(m g c)"),
    ]
    return dict(name="drag.tex", world=W, rows=rows,
                params={m: (0.5, 2), g: (9, 10), b: (0.5, 2), c: (0.1, 1), t: (0.2, 3)})


@document
def inductance():
    V0, R, L, C, Q0 = S("V_0 R L C Q_0")
    tau, VL, UL, w0, imax, f0, wd = S("tau V_L U_L omega_0 i_max f_0 omega_d")
    Ip = sp.Symbol("Ip", positive=True)
    I, q, i = sp.symbols("I q i", cls=sp.Function)
    W = {tau: L / R, I: V0 / R * (1 - sp.exp(-t / tau)), VL: V0 * sp.exp(-t / tau), UL: half * L * I(t)**2,
         w0: 1 / sp.sqrt(L * C), q: Q0 * sp.cos(w0 * t), i: -w0 * Q0 * sp.sin(w0 * t), imax: w0 * Q0,
         f0: w0 / (2 * sp.pi), wd: sp.sqrt(1 / (L * C) - R**2 / (4 * L**2))}
    cs, sn = sp.cos(w0 * t), sp.sin(w0 * t)
    integral = sp.Integral(L * Ip, (Ip, 0, I(t)))
    split = Q0**2 / (2 * C) * cs**2 + half * L * w0**2 * Q0**2 * sn**2
    rows = [
        R_(9, 0, "given", r"V_0 - L\frac{dI}{dt} - R I = 0", V0 - L * D(I(t)) - R * I(t), 0, "loop law, introduces I", intro=[I]),
        R_(13, 0, "given", r"\tau = \frac{L}{R}", tau, L / R, "time constant, new symbol", intro=[tau]),
        R_(17, 0, "derived", r"I = \frac{V_0}{R}\left(1 - e^{-t/\tau}", I(t), V0 / R * (1 - sp.exp(-t / tau)),
           "solve (4.1) (inline I(0) = 0)"),
        R_(21, 1, "given", r"V_L = L\frac{dI}{dt}", VL, L * D(I(t)), "coil voltage, new symbol", intro=[VL]),
        R_(21, 2, "wrong", r"= \frac{L V_0}{R}\, e^{-t/\tau}", L * D(I(t)), L * V0 / R * sp.exp(-t / tau),
           "dropped the chain-rule factor 1/tau: V_0 e^{-t/tau}"),
        R_(25, 1, "given", r"U_L = \int_0^{I} L\, I'\, dI'", UL, integral, "stored energy as work, new symbol", intro=[UL]),
        R_(25, 2, "derived", r"= \frac{1}{2} L I^2", integral, half * L * I(t)**2, "the integral"),
        R_(33, 0, "given", r"L\ddot{q} + \frac{q}{C} = 0", L * D2(q(t)) + q(t) / C, 0, "loop law, introduces q", intro=[q]),
        R_(37, 0, "given", r"\omega_0 = \frac{1}{\sqrt{LC}}", w0, 1 / sp.sqrt(L * C), "natural frequency, new symbol", intro=[w0]),
        R_(41, 0, "given", r"q = Q_0\cos\omega_0 t", q(t), Q0 * cs, "solution, introduces Q_0", intro=[Q0]),
        R_(45, 1, "given", r"i = \dot{q}", i(t), D(q(t)), "current, new symbol", intro=[i]),
        R_(45, 2, "derived", r"= -\omega_0 Q_0 \sin\omega_0 t", D(q(t)), -w0 * Q0 * sn, "differentiate q"),
        R_(50, 0, "derived", r"\frac{q^2}{2C} + \frac{1}{2} L i^2 &=", q(t)**2 / (2 * C) + half * L * i(t)**2, split,
           "substitute q and i"),
        R_(51, 0, "derived", r"&= \frac{Q_0^2}{2C}", split, Q0**2 / (2 * C), "L omega_0^2 = 1/C"),
        R_(56, 1, "given", r"i_{\max} = \omega_0 \cdot Q_0", imax, w0 * Q0, "current amplitude, new symbol", intro=[imax]),
        R_(56, 2, "wrong", r"= Q_0\sqrt{LC}", w0 * Q0, Q0 * sp.sqrt(L * C), "inverted: Q_0/sqrt(LC)"),
        R_(60, 1, "given", r"f_0 = \frac{\omega_0}{2\pi}", f0, w0 / (2 * sp.pi), "frequency in hertz, new symbol", intro=[f0]),
        R_(60, 2, "wrong", r"= \frac{1}{2\pi LC}", w0 / (2 * sp.pi), 1 / (2 * sp.pi * L * C), "wrong power: sqrt(LC)"),
        R_(68, 0, "given", r"\omega_d = \sqrt{\frac{1}{LC}", wd, sp.sqrt(1 / (L * C) - R**2 / (4 * L**2)),
           "damped frequency, new symbol", intro=[wd]),
        R_(72, 0, "approx", r"\omega_d \approx \omega_0\left(1 - \frac{R^2 C}{8L}", wd, w0 * (1 - R**2 * C / (8 * L)),
           "first order in R^2 C/L", regime={R: eps * R}),
    ]
    return dict(name="inductance.md", world=W, rows=rows,
                params={V0: (1, 12), R: (0.1, 1), L: (1, 3), C: (0.1, 0.5), Q0: (0.5, 2), t: (0.1, 3)})


@document
def cooling():
    d1, k1, A, d2, k2, Th, Tc, C, R, Ta, T0, T1, T2 = S("d_1 k_1 A d_2 k_2 T_h T_c C R T_a T_0 T_1 T_2")
    R1, R2, Tm, H, tau, th0, Dt = S("R_1 R_2 T_m H tau theta_0 Delta_t")
    T, th = sp.symbols("T theta", cls=sp.Function)
    W = {R1: d1 / (k1 * A), R2: d2 / (k2 * A), Tm: (R2 * Th + R1 * Tc) / (R1 + R2), H: (Th - Tm) / R1,
         tau: R * C, T: Ta + (T0 - Ta) * sp.exp(-t / tau), th: (T0 - Ta) * sp.exp(-t / tau), th0: T0 - Ta,
         Dt: tau * sp.log((T1 - Ta) / (T2 - Ta))}
    Whalf = dict(W)
    Whalf[T2] = Ta + (T1 - Ta) / 2
    rows = [
        R_(10, 1, "given", r"R_1 = \dfrac{d_1}{k_1 A}", R1, d1 / (k1 * A), "thermal resistance of layer 1, new symbol", intro=[R1]),
        R_(10, 2, "given", r"R_2 = \dfrac{d_2}{k_2 A}", R2, d2 / (k2 * A), "thermal resistance of layer 2, new symbol", intro=[R2]),
        R_(14, 0, "given", r"\frac{T_h - T_m}{R_1} = \frac{T_m - T_c}{R_2}", (Th - Tm) / R1, (Tm - Tc) / R2,
           "steady state, introduces T_m", intro=[Tm]),
        R_(18, 0, "wrong", r"T_m = \frac{R_1 T_h + R_2 T_c}", Tm, (R1 * Th + R2 * Tc) / (R1 + R2), "swapped indices: R_2 T_h + R_1 T_c"),
        R_(22, 1, "given", r"H = \frac{T_h - T_m}{R_1}", H, (Th - Tm) / R1, "heat current, new symbol", intro=[H]),
        R_(22, 2, "derived", r"= \frac{T_h - T_c}{R_1 + R_2}", (Th - Tm) / R1, (Th - Tc) / (R1 + R2), "substitute the correct T_m"),
        R_(26, 0, "derived", r"H = \frac{A\,(T_h - T_c)}", H, A * (Th - Tc) / (d1 / k1 + d2 / k2), "(1) into (3)"),
        R_(32, 0, "given", r"C\,\frac{dT}{dt} = -\frac{T - T_{\mathrm{a}}}{R}", C * D(T(t)), -(T(t) - Ta) / R,
           "Newton's law of cooling, introduces T", intro=[T]),
        R_(36, 1, "given", r"\tau = R C", tau, R * C, "time constant, new symbol", intro=[tau]),
        R_(36, 2, "given", r"\theta = T - T_{\mathrm{a}}", th(t), T(t) - Ta, "excess temperature, new symbol", intro=[th]),
        R_(40, 0, "derived", r"\dot{\theta} = -\frac{\theta}{\tau}", D(th(t)), -th(t) / tau, "(4) with (5); T_a constant"),
        R_(44, 0, "derived", r"\theta = \theta_0\, e^{-t/\tau}", th(t), th0 * sp.exp(-t / tau),
           "solve (inline theta_0 = T_0 - T_a)"),
        R_(48, 0, "derived", r"T = T_{\mathrm{a}} + \left(T_0", T(t), Ta + (T0 - Ta) * sp.exp(-t / tau), "theta + T_a"),
        R_(52, 0, "approx", r"T \approx T_0 - \left(T_0", T(t), T0 - (T0 - Ta) * t / tau, "first order in t/tau",
           regime={t: eps * t}),
        R_(58, 0, "given", r"T_2 - T_{\mathrm{a}} = \left(T_1", T2 - Ta, (T1 - Ta) * sp.exp(-Dt / tau),
           "two readings, introduces Delta t", intro=[Dt]),
        R_(62, 0, "wrong", r"\Delta t = \tau \ln\dfrac{T_2", Dt, tau * sp.log((T2 - Ta) / (T1 - Ta)), "ratio inverted (negative time)"),
        R_(66, 0, "derived", r"\Delta t = \tau \ln 2", Dt, tau * sp.log(2),
           "T_2 - T_a = (T_1 - T_a)/2 (inline) in the correct Delta t", world=Whalf),
    ]
    return dict(name="cooling.md", world=W, rows=rows, known=["theta_0"],
                params={d1: (0.05, 0.2), k1: (0.5, 2), A: (1, 10), d2: (0.05, 0.2), k2: (0.02, 0.1), Th: (80, 100),
                        Tc: (1, 10), C: (100, 500), R: (0.5, 5), Ta: (15, 25), T0: (70, 95), T1: (60, 90),
                        T2: (30, 50), t: (1, 500)})


@document
def gravity():
    G, M, R, h, m = S("G M R h m")
    g0, gh, ve, r, vc, T, E = S("g_0 g_h v_esc r v_c T E")
    W = {g0: G * M / R**2, gh: G * M / (R + h)**2, ve: sp.sqrt(2 * G * M / R), r: R + h, vc: sp.sqrt(G * M / r),
         T: 2 * sp.pi * r / vc, E: -G * M * m / (2 * r)}
    low = {h: eps * h}
    rows = [
        R_(9, 0, "given", r"g_0 = \frac{GM}{R^2}", g0, G * M / R**2, "surface field, new symbol", intro=[g0]),
        R_(13, 1, "given", r"g_h = \frac{GM}{(R + h)^2}", gh, G * M / (R + h)**2, "field at height h, new symbol", intro=[gh]),
        R_(13, 2, "derived", r"= g_0\,\frac{R^2}{(R + h)^2}", G * M / (R + h)**2, g0 * R**2 / (R + h)**2, "(1)"),
        R_(17, 0, "wrong", r"g_h = g_0 \left(1 + \frac{h}{R}\right)^{2}", gh, g0 * (1 + h / R)**2, "inverted: power -2"),
        R_(21, 0, "approx", r"g_h \approx g_0 \left(1 - \frac{2h}{R}", gh, g0 * (1 - 2 * h / R), "first order in h/R", regime=low),
        R_(29, 0, "given", r"\tfrac12 m v_{\mathrm{esc}}^2 - \frac{GMm}{R} = 0", half * m * ve**2 - G * M * m / R, 0,
           "zero total energy, introduces v_esc", intro=[ve]),
        R_(33, 1, "derived", r"v_{\mathrm{esc}} = \sqrt{\frac{2GM}{R}}", ve, sp.sqrt(2 * G * M / R), "solve for v_esc > 0"),
        R_(33, 2, "derived", r"= \sqrt{2 g_0 R}", sp.sqrt(2 * G * M / R), sp.sqrt(2 * g0 * R), "GM = g_0 R^2 from (1)"),
        R_(41, 0, "given", r"\frac{m v_c^2}{r} = \frac{GMm}{r^2}", m * vc**2 / r, G * M * m / r**2,
           "gravity supplies the centripetal force, introduces v_c (r = R + h inline)", intro=[vc]),
        R_(45, 0, "derived", r"v_c = \sqrt{\frac{GM}{r}}", vc, sp.sqrt(G * M / r), "solve for v_c > 0"),
        R_(49, 0, "approx", r"v_c \approx \sqrt{g_0 R}", vc, sp.sqrt(g0 * R), "h << R with r = R + h (inline)", regime=low),
        R_(53, 0, "approx", r"v_{\mathrm{esc}} \approx \sqrt{2}\, v_c", ve, sp.sqrt(2) * vc, "h << R", regime=low),
        R_(57, 0, "given", r"T = \frac{2\pi r}{v_c}", T, 2 * sp.pi * r / vc, "period, new symbol", intro=[T]),
        R_(61, 0, "wrong", r"T^2 = \frac{4\pi^2 r^2}{GM}", T**2, 4 * sp.pi**2 * r**2 / (G * M), "wrong power: r^3"),
        R_(65, 0, "derived", r"\frac{T^2}{r^3} = \frac{4\pi^2}{GM}", T**2 / r**3, 4 * sp.pi**2 / (G * M), "Kepler III from T and (4)"),
        R_(73, 1, "given", r"E = \tfrac12 m v_c^2 - \frac{GMm}{r}", E, half * m * vc**2 - G * M * m / r, "orbital energy, new symbol",
           intro=[E]),
        R_(73, 2, "wrong", r"= -\frac{GMm}{r}$$", half * m * vc**2 - G * M * m / r, -G * M * m / r, "dropped factor 1/2"),
        R_(77, 0, "derived", r"E = -\tfrac12 m v_c^2", E, -half * m * vc**2, "correct E = -GMm/(2r) with (4)"),
    ]
    return dict(name="gravity.md", world=W, rows=rows, known=["r"],
                params={G: (1, 2), M: (5, 20), R: (1, 3), h: (0.1, 1), m: (0.5, 2)})


if __name__ == "__main__":
    sys.exit(V.main())
