#!/usr/bin/env python3
"""Check the labels of the fourth held-out set (this folder) with SymPy.

The checking machinery (scanning of displayed rows, the .expect format, the
world model, the derived / given / wrong / approx tests) is that of
../verify.py; this file only holds the hand-written transcriptions of the
documents in this folder and points the machinery here.  See ../README.md for
what is checked and README.md here for what the set is.

Run: python3 tests/data/documents/heldout4/verify_heldout4.py [NAME...]
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
Dt = lambda f: sp.Derivative(f, t)


@document
def hydrostatics():
    rho, g, p0, h, w, H, rb, rw, a, A, m, ms, ro, rs, ra = S(
        "rho g p_0 h w H rho_b rho_w a A m m_s rho_o rho_s rho_a")
    F, taub, yc, d, f, dp, Dd, mmax, mo = S("F tau_b y_c d f d_p Delta_d m_max m_o")
    z = sp.Symbol("z", positive=True)  # the integration variable (written h in the document)
    p = sp.Function("p")
    W = {p: p0 + rho * g * t, F: half * rho * g * w * H**2, taub: rho * g * w * H**3 / 6, yc: H / 3,
         d: rb * a / rw, f: rb / rw, dp: (rb * a + m / A) / rw, Dd: m / (rw * A), mmax: (rw - rb) * A * a,
         mo: ms * ro * (rs - ra) / (rs * (ro - ra))}
    Fint = sp.Integral(rho * g * z * w, (z, 0, H))
    tint = sp.Integral(rho * g * w * z * (H - z), (z, 0, H))
    tmid = rho * g * w * (H**3 / 2 - H**3 / 3)
    rows = [
        R_(21, 0, "given", r"\frac{\dd p}{\dd h} = \rho g", sp.Derivative(p(h), h), rho * g,
           "hydrostatic balance of a slab, introduces p", intro=[p]),
        R_(26, 0, "derived", r"p(h) = p_0 + \rho g h", p(h), p0 + rho * g * h, "integrate (eq:hs) (inline p(0) = p_0)"),
        R_(36, 0, "given", r"F &= \int_0^H \rho g h", F, Fint, "force as a sum over strips, new symbol", intro=[F]),
        R_(37, 0, "derived", r"&= \tfrac12 \rho g w H^2", Fint, half * rho * g * w * H**2, "the integral"),
        R_(42, 0, "given", r"\taub &= \int_0^H", taub, tint, "moment about the foot, new symbol", intro=[taub]),
        R_(43, 0, "derived", r"&= \rho g w \left( \frac{H^3}{2}", tint, tmid, "integrate term by term"),
        R_(44, 0, "derived", r"&= \frac{\rho g w H^3}{6}", tmid, rho * g * w * H**3 / 6, "1/2 - 1/3 = 1/6"),
        R_(49, 1, "given", r"y_{\mathrm{c}} = \frac{\taub}{F}", yc, taub / F, "height of the resultant, new symbol",
           intro=[yc]),
        R_(49, 2, "wrong", r"= \frac{2H}{3}", taub / F, 2 * H / 3, "it is H/3 (height above the foot, not depth)"),
        R_(54, 0, "derived", r"H - y_{\mathrm{c}} = \frac{2}{3}\, H", H - yc, 2 * H / 3, "correct y_c = H/3"),
        R_(65, 0, "given", r"\rw g A d = \rb g A a", rw * g * A * d, rb * g * A * a, "Archimedes, introduces d",
           intro=[d]),
        R_(69, 1, "derived", r"d = \frac{\rb}{\rw}\, a", d, rb * a / rw, "solve (eq:float) for d"),
        R_(69, 2, "given", r"f = \frac{d}{a}", f, d / a, "submerged fraction, new symbol", intro=[f]),
        R_(69, 3, "derived", r"= \frac{\rb}{\rw} .", d / a, rb / rw, "substitute d"),
        R_(74, 0, "given", r"\rw g A d' = \rb g A a + m g", rw * g * A * dp, rb * g * A * a + m * g,
           "loaded block, introduces d'", intro=[dp]),
        R_(78, 1, "given", r"\Delta d = d' - d", Dd, dp - d, "change of draft, new symbol", intro=[Dd]),
        R_(78, 2, "wrong", r"= \frac{m}{\rb A}", dp - d, m / (rb * A), "swapped densities: m/(rho_w A)"),
        R_(84, 0, "given", r"\rw g A a = \rb g A a + m_{\max}", rw * g * A * a, rb * g * A * a + mmax * g,
           "flush with the water (inline d' = a), introduces m_max", intro=[mmax]),
        R_(85, 0, "derived", r"m_{\max} = (\rw - \rb) A a", mmax, (rw - rb) * A * a, "solve for m_max"),
        R_(96, 0, "given", r"m_{\mathrm{o}}\, g \left( 1 -", mo * g * (1 - ra / ro), ms * g * (1 - ra / rs),
           "balance with air buoyancy, introduces m_o", intro=[mo]),
        R_(101, 0, "derived", r"m_{\mathrm{o}} = m_{\mathrm{s}}\,", mo, ms * ro * (rs - ra) / (rs * (ro - ra)),
           "solve for m_o"),
        R_(108, 0, "approx", r"m_{\mathrm{o}} \approx m_{\mathrm{s}}", mo, ms * (1 + ra / ro - ra / rs),
           "first order in rho_a", regime={ra: eps * ra}),
    ]
    return dict(name="hydrostatics.tex", world=W, rows=rows,
                params={rho: (800, 1200), g: (9, 10), p0: (90000, 110000), h: (0.1, 10), w: (2, 20), H: (1, 30),
                        rb: (400, 900), rw: (1000, 1030), a: (0.1, 1), A: (0.5, 3), m: (1, 20), ms: (0.1, 2),
                        ro: (500, 3000), rs: (7800, 8100), ra: (1.1, 1.3)})


@document
def beam():
    P, L, a, q, Wt, ell, th, mu, x = S("P L a q W ell theta mu x")
    RA, RB, b, Mmax, R, xm, Nw, f, thmin = S("R_A R_B b M_max R x_m N_w f theta_min")
    s = sp.Symbol("s", positive=True)
    M, Vq, Mq = sp.symbols("M V_q M_q", cls=sp.Function)
    W = {RB: P * a / L, RA: P * (L - a) / L, b: L - a, M: RA * t, Mmax: RA * a, R: q * L / 2, Vq: R - q * t,
         Mq: q * t * (L - t) / 2, xm: L / 2, Nw: Wt / (2 * sp.tan(th)), f: Nw, thmin: sp.atan(1 / (2 * mu))}
    Wmid = dict(W)
    Wmid[a] = L / 2
    Mint = sp.Integral(Vq(s), (s, 0, x))
    rows = [
        R_(17, 0, "given", r"R_B L - P a = 0", RB * L - P * a, 0, "moments about A, introduces R_B", intro=[RB]),
        R_(18, 0, "given", r"R_A + R_B - P = 0", RA + RB - P, 0, "vertical balance, introduces R_A", intro=[RA]),
        R_(22, 0, "derived", r"R_B &=& \frac{P a}{L}", RB, P * a / L, "solve (M_A)"),
        R_(23, 1, "derived", r"R_A &=& P - R_B", RA, P - RB, "solve (V)"),
        R_(23, 2, "wrong", r"= \frac{P a}{L} .", P - RB, P * a / L, "swapped: P b / L"),
        R_(28, 0, "given", r"M(x) = R_A\, x", M(x), RA * x, "bending moment left of the load, introduces M", intro=[M]),
        R_(32, 1, "given", r"M_{\max} = M(a)", Mmax, M(a), "peak moment, new symbol", intro=[Mmax]),
        R_(32, 2, "derived", r"= \frac{P a b}{L}", M(a), P * a * b / L, "correct R_A = P b/L (inline b = L - a)"),
        R_(36, 0, "derived", r"M_{\max} = \frac{P L}{4}", Mmax, P * L / 4, "mid-span load (inline a = b = L/2)",
           world=Wmid),
        R_(45, 1, "given", r"2 R = q L", 2 * R, q * L, "vertical balance by symmetry, introduces R", intro=[R]),
        R_(45, 2, "derived", r"R = \tfrac{1}{2} q L", R, half * q * L, "solve for R"),
        R_(50, 0, "given", r"\Vq(x) &= R - q x", Vq(x), R - q * x, "shear force, new symbol", intro=[Vq]),
        R_(51, 0, "given", r"\frac{\mathrm{d}\Mq}{\mathrm{d}x} &= \Vq", sp.Derivative(Mq(x), x), Vq(x),
           "moment-shear relation, introduces M_q", intro=[Mq]),
        R_(57, 0, "derived", r"\Mq(x) &= \int_0^x \Vq(s)", Mq(x), Mint, "integrate (eq:dM) (inline M_q(0) = 0)"),
        R_(58, 0, "derived", r"&= R x - \tfrac12 q x^2", Mint, R * x - half * q * x**2, "substitute (eq:V), integrate"),
        R_(59, 0, "derived", r"&= \tfrac12 q x (L - x)", R * x - half * q * x**2, half * q * x * (L - x), "R = qL/2"),
        R_(64, 1, "given", r"\Vq(x_m) = 0", Vq(xm), 0, "shear vanishes at the peak, introduces x_m", intro=[xm]),
        R_(64, 2, "derived", r"x_m = \frac{L}{2}", xm, L / 2, "solve R - q x_m = 0"),
        R_(68, 0, "wrong", r"\Mq(x_m) = \frac{q L^2}{4}", Mq(xm), q * L**2 / 4, "dropped factor 1/2: q L^2 / 8"),
        R_(81, 0, "given", r"N_w\, \ell \sin\theta &= W", Nw * ell * sp.sin(th), Wt * ell / 2 * sp.cos(th),
           "moments about the foot, introduces N_w", intro=[Nw]),
        R_(82, 0, "given", r"f &= N_w", f, Nw, "horizontal balance, introduces f", intro=[f]),
        R_(86, 0, "derived", r"f = \frac{W}{2 \tan\theta}", f, Wt / (2 * sp.tan(th)), "(eq:mom) and (eq:forces)"),
        R_(91, 0, "given", r"\frac{W}{2 \tan\thmin} &= \mu W", Wt / (2 * sp.tan(thmin)), mu * Wt,
           "limiting friction (inline N = W), introduces theta_min", intro=[thmin]),
        R_(92, 0, "wrong", r"\tan\thmin &= 2 \mu", sp.tan(thmin), 2 * mu, "inverted: 1/(2 mu)"),
        R_(96, 0, "derived", r"\thmin = \arctan \frac{1}{2 \mu}", thmin, sp.atan(1 / (2 * mu)), "correct tan = 1/(2 mu)"),
    ]
    return dict(name="beam.tex", world=W, rows=rows, known=["b"],
                params={P: (1, 10), L: (4, 6), a: (0.5, 3.5), q: (1, 5), Wt: (100, 500), ell: (2, 5), th: (0.3, 1.3),
                        mu: (0.2, 0.8), x: (0.1, 3.9)})


@document
def kinetics():
    k, A0, k2, D0, X0, ka, kb = S("k A_0 k_2 D_0 X_0 k_a k_b")
    th, thp, tmax = S("t_half t_halfp t_max")
    c = sp.Symbol("c", positive=True)
    A, Dc, X, Y = sp.symbols("A D X Y", cls=sp.Function)
    W = {A: A0 * sp.exp(-k * t), th: sp.log(2) / k, Dc: D0 / (1 + k2 * D0 * t), thp: 1 / (k2 * D0),
         X: X0 * sp.exp(-ka * t), Y: ka * X0 / (kb - ka) * (sp.exp(-ka * t) - sp.exp(-kb * t)),
         tmax: sp.log(kb / ka) / (kb - ka)}
    rows = [
        R_(18, 0, "given", r"\diff{\conc{A}}{t} = -k\, \conc{A}", Dt(A(t)), -k * A(t), "first-order rate law, introduces [A]",
           intro=[A]),
        R_(23, 0, "derived", r"\int_{\conc{A}_0}^{\conc{A}} \frac{\mathrm{d}c}{c}", sp.Integral(1 / c, (c, A0, A(t))), -k * t,
           "separate (r1) and integrate from 0 to t (inline [A](0) = [A]_0)"),
        R_(24, 0, "derived", r"\ln \frac{\conc{A}}{\conc{A}_0} &= -k t", sp.log(A(t) / A0), -k * t, "the integral"),
        R_(25, 0, "derived", r"\conc{A} &= \conc{A}_0\, e^{-k t}", A(t), A0 * sp.exp(-k * t), "exponentiate"),
        R_(29, 1, "given", r"\conc{A}(t_{1/2}) = \tfrac12 \conc{A}_0", A(th), half * A0, "half-life, new symbol", intro=[th]),
        R_(29, 2, "derived", r"\conc{A}(t_{1/2}) = \tfrac12", th, sp.log(2) / k, "solve e^{-k t} = 1/2 (continues on line 30)"),
        R_(38, 0, "given", r"\diff{\conc{D}}{t} = -k_2 \conc{D}^2", Dt(Dc(t)), -k2 * Dc(t)**2,
           "second-order rate law, introduces [D]", intro=[Dc]),
        R_(43, 0, "derived", r"\frac{1}{\conc{D}} - \frac{1}{\conc{D}_0} = k_2 t", 1 / Dc(t) - 1 / D0, k2 * t,
           "separate and integrate (inline [D](0) = [D]_0)"),
        R_(47, 0, "derived", r"\conc{D} = \frac{\conc{D}_0}{1 + k_2", Dc(t), D0 / (1 + k2 * D0 * t), "solve for [D]"),
        R_(52, 1, "given", r"\conc{D}(t'_{1/2}) = \tfrac12 \conc{D}_0", Dc(thp), half * D0, "second-order half-life, new symbol",
           intro=[thp]),
        R_(52, 2, "wrong", r"\conc{D}(t'_{1/2}) = \tfrac12", thp, 1 / (k2 * D0**2), "wrong power: 1/(k_2 [D]_0) (continues on line 53)"),
        R_(58, 0, "approx", r"\conc{D} \approx \conc{D}_0 \left( 1 - k_2", Dc(t), D0 * (1 - k2 * D0 * t),
           "first order in k_2 [D]_0 t", regime={t: eps * t}),
        R_(66, 0, "given", r"\diff{\conc{X}}{t} &= -k_a \conc{X}", Dt(X(t)), -ka * X(t), "first step, introduces [X]",
           intro=[X]),
        R_(67, 0, "given", r"\diff{\conc{Y}}{t} &= k_a \conc{X} - k_b", Dt(Y(t)), ka * X(t) - kb * Y(t),
           "intermediate, introduces [Y]", intro=[Y]),
        R_(73, 0, "derived", r"\conc{X} &=& \conc{X}_0\, e^{-k_a t}", X(t), X0 * sp.exp(-ka * t),
           "as (a1) (inline [X](0) = [X]_0)"),
        R_(74, 0, "derived", r"\conc{Y} &=& \frac{k_a \conc{X}_0}{k_b - k_a}", Y(t),
           ka * X0 / (kb - ka) * (sp.exp(-ka * t) - sp.exp(-kb * t)), "solves (y) (inline [Y](0) = 0)"),
        R_(79, 0, "derived", r"\diff{\conc{Y}}{t} = \frac{k_a \conc{X}_0}{k_b - k_a}", Dt(Y(t)),
           ka * X0 / (kb - ka) * (kb * sp.exp(-kb * t) - ka * sp.exp(-ka * t)), "differentiate (ysol)"),
        R_(84, 0, "given", r"k_a e^{-k_a t_{\max}} &= k_b e^{-k_b t_{\max}}", ka * sp.exp(-ka * tmax), kb * sp.exp(-kb * tmax),
           "the peak, introduces t_max", intro=[tmax]),
        R_(85, 0, "wrong", r"t_{\max} &= \frac{\ln (k_a / k_b)}{k_b - k_a}", tmax, sp.log(ka / kb) / (kb - ka),
           "ratio inverted: ln(k_b/k_a)"),
        R_(90, 0, "derived", r"\lim_{k_b \to k_a} t_{\max} = \frac{1}{k_a}", sp.Limit(tmax, kb, ka), 1 / ka,
           "limit of the correct t_max"),
    ]
    return dict(name="kinetics.tex", world=W, rows=rows,
                params={k: (0.1, 2), A0: (0.1, 2), k2: (0.1, 2), D0: (0.1, 2), X0: (0.1, 2), ka: (0.1, 0.6),
                        kb: (1, 3), t: (0.1, 5)})


@document
def fin():
    k, ell, r1, r2, T1, T2, r, h, P, Ac, thb, x, Dm = S("k ell r_1 r_2 T_1 T_2 r h P A_c theta_b x D")
    H, Rth, dl, m, Qf, ef = S("H R_th delta m Q_f varepsilon_f")
    Tv, rr = sp.symbols("Tv rr", positive=True)
    T, th = sp.symbols("T theta", cls=sp.Function)
    W = {H: 2 * sp.pi * k * ell * (T1 - T2) / sp.log(r2 / r1), T: T1 - (T1 - T2) * sp.log(t / r1) / sp.log(r2 / r1),
         Rth: sp.log(r2 / r1) / (2 * sp.pi * k * ell), dl: r2 - r1, m: sp.sqrt(h * P / (k * Ac)),
         th: thb * sp.exp(-m * t), Qf: sp.sqrt(h * P * k * Ac) * thb, ef: sp.sqrt(k * P / (h * Ac))}
    Wpin = dict(W)
    Wpin[P] = sp.pi * Dm
    Wpin[Ac] = sp.pi * Dm**2 / 4
    dth = sp.Derivative(th(x), x)
    root = sp.Subs(dth, x, 0)
    rows = [
        R_(16, 0, "given", r"H = -k \, 2\pi r \ell \, \frac{dT}{dr}", H, -k * 2 * sp.pi * r * ell * sp.Derivative(T(r), r),
           "Fourier's law through a cylinder, introduces T and H", intro=[T, H]),
        R_(22, 0, "derived", r"\int_{T_1}^{T_2} dT = -\frac{H}{2\pi k \ell}", sp.Integral(1, (Tv, T1, T2)),
           -H / (2 * sp.pi * k * ell) * sp.Integral(1 / rr, (rr, r1, r2)), "separate (1), integrate r_1 to r_2"),
        R_(28, 0, "derived", r"T_1 - T_2 = \frac{H}{2\pi k \ell} \ln", T1 - T2, H / (2 * sp.pi * k * ell) * sp.log(r2 / r1),
           "the integrals"),
        R_(34, 1, "given", r"R_{\mathrm{th}} = \frac{T_1 - T_2}{H}", Rth, (T1 - T2) / H, "thermal resistance, new symbol",
           intro=[Rth]),
        R_(34, 2, "derived", r"= \frac{\ln(r_2/r_1)}{2\pi k\ell}", (T1 - T2) / H, sp.log(r2 / r1) / (2 * sp.pi * k * ell),
           "from (2)"),
        R_(41, 0, "wrong", r"T(r) = T_1 + (T_1 - T_2)", T(r), T1 + (T1 - T2) * sp.log(r / r1) / sp.log(r2 / r1),
           "sign slip: T_1 - (T_1 - T_2) ln(r/r_1)/ln(r_2/r_1)"),
        R_(49, 0, "approx", r"R_{\mathrm{th}} \approx \frac{\delta}{2\pi k \ell\, r_1}", Rth, dl / (2 * sp.pi * k * ell * r1),
           "thin lagging, first order in delta/r_1 (inline delta = r_2 - r_1)", regime={r2: r1 + eps * r2}),
        R_(62, 0, "given", r"k A_c \frac{d^2\theta}{dx^2} = h P", k * Ac * sp.Derivative(th(x), (x, 2)), h * P * th(x),
           "fin energy balance, introduces theta", intro=[th]),
        R_(68, 0, "given", r"m^2 = \frac{h P}{k A_c}", m**2, h * P / (k * Ac), "fin parameter, new symbol", intro=[m]),
        R_(74, 0, "derived", r"\frac{d^2\theta}{dx^2} = m^2 \theta", sp.Derivative(th(x), (x, 2)), m**2 * th(x),
           "divide (3) by k A_c"),
        R_(81, 1, "derived", r"\theta(x) = \theta_b \, e^{-m x}", th(x), thb * sp.exp(-m * x),
           "decaying solution (inline theta(0) = theta_b)"),
        R_(81, 2, "derived", r"\theta(x) = \theta_b \, e^{-m x}", dth, -m * thb * sp.exp(-m * x),
           "differentiate (continues on line 82)"),
        R_(89, 0, "given", r"Q_f &= -k A_c \left.\frac{d\theta}{dx}", Qf, -k * Ac * root, "heat through the root, new symbol",
           intro=[Qf]),
        R_(90, 0, "derived", r"&= k A_c\, m\, \theta_b", -k * Ac * root, k * Ac * m * thb, "theta'(0) = -m theta_b"),
        R_(91, 0, "derived", r"&= \sqrt{h P k A_c}\; \theta_b", k * Ac * m * thb, sp.sqrt(h * P * k * Ac) * thb,
           "m = sqrt(hP/(kA_c))"),
        R_(99, 1, "given", r"\varepsilon_f = \frac{Q_f}{h A_c \theta_b}", ef, Qf / (h * Ac * thb), "effectiveness, new symbol",
           intro=[ef]),
        R_(99, 2, "wrong", r"= \sqrt{\frac{h A_c}{k P}}", Qf / (h * Ac * thb), sp.sqrt(h * Ac / (k * P)),
           "inverted: sqrt(k P / (h A_c))"),
        R_(105, 1, "derived", r"m = \sqrt{\frac{4h}{kD}}", m, sp.sqrt(4 * h / (k * Dm)), "pin (inline P = pi D, A_c = pi D^2/4)",
           world=Wpin),
        R_(105, 2, "derived", r"\varepsilon_f = 2\sqrt{\frac{k}{hD}}", ef, 2 * sp.sqrt(k / (h * Dm)),
           "correct effectiveness for the pin (inline P, A_c)", world=Wpin),
    ]
    return dict(name="fin.md", world=W, rows=rows, known=["delta"],
                params={k: (0.03, 200), ell: (1, 10), r1: (0.02, 0.05), r2: (0.06, 0.15), T1: (80, 150), T2: (20, 40),
                        r: (0.02, 0.15), h: (5, 50), P: (0.01, 0.1), Ac: (0.001, 0.01), thb: (20, 80), x: (0.01, 0.3),
                        Dm: (0.002, 0.02)})


@document
def acpower():
    R, X, V0, w, r = S("R X V_0 omega r")
    Z, ph, I0, Pw, T, Vr, Ir, Sa, Q, Pl = S("Z varphi I_0 P T V_rms I_rms S Q P_l")
    tp = sp.Symbol("tp", positive=True)
    v, i, p = sp.symbols("v i p", cls=sp.Function)
    W = {Z: sp.sqrt(R**2 + X**2), ph: sp.atan(X / R), I0: V0 / Z, v: V0 * sp.cos(w * t), i: I0 * sp.cos(w * t - ph),
         p: V0 * sp.cos(w * t) * I0 * sp.cos(w * t - ph), T: 2 * sp.pi / w, Pw: half * V0 * I0 * sp.cos(ph),
         Vr: V0 / sp.sqrt(2), Ir: I0 / sp.sqrt(2), Sa: Vr * Ir, Q: Vr * Ir * sp.sin(ph), Pl: Ir**2 * r}
    avg = sp.Integral(p(tp), (tp, 0, T)) / T
    rows = [
        R_(11, 1, "given", r"Z = \sqrt{R^2 + X^2}", Z, sp.sqrt(R**2 + X**2), "impedance, new symbol", intro=[Z]),
        R_(11, 2, "given", r"\tan\varphi = \frac{X}{R}", sp.tan(ph), X / R, "phase lag, new symbol", intro=[ph]),
        R_(11, 3, "given", r"I_0 = \frac{V_0}{Z}", I0, V0 / Z, "current amplitude, new symbol", intro=[I0]),
        R_(15, 1, "given", r"v(t) = V_0 \cos\omega t", v(t), V0 * sp.cos(w * t), "source voltage, new symbol", intro=[v]),
        R_(15, 2, "given", r"i(t) = I_0 \cos(\omega t - \varphi)", i(t), I0 * sp.cos(w * t - ph), "current, new symbol",
           intro=[i]),
        R_(20, 1, "given", r"p(t) = v(t)\, i(t)", p(t), v(t) * i(t), "instantaneous power, new symbol", intro=[p]),
        R_(20, 2, "derived", r"= \tfrac12 V_0 I_0 \left[ \cos\varphi", v(t) * i(t),
           half * V0 * I0 * (sp.cos(ph) + sp.cos(2 * w * t - ph)), "product to sum"),
        R_(25, 1, "given", r"P = \frac{1}{T} \int_0^T p(t)", Pw, avg, "average power, new symbol (inline T = 2 pi/omega)",
           intro=[Pw]),
        R_(25, 2, "derived", r"= \tfrac12 V_0 I_0 \cos\varphi", avg, half * V0 * I0 * sp.cos(ph),
           "the 2 omega term averages to zero"),
        R_(31, 1, "given", r"V_{\mathrm{rms}} = \frac{V_0}{\sqrt2}", Vr, V0 / sp.sqrt(2), "rms voltage, new symbol",
           intro=[Vr]),
        R_(31, 2, "given", r"I_{\mathrm{rms}} = \frac{I_0}{\sqrt2}", Ir, I0 / sp.sqrt(2), "rms current, new symbol",
           intro=[Ir]),
        R_(35, 0, "derived", r"P = V_{\mathrm{rms}} I_{\mathrm{rms}} \cos\varphi", Pw, Vr * Ir * sp.cos(ph), "(9.4) with rms"),
        R_(40, 0, "derived", r"\cos\varphi = \frac{R}{Z}", sp.cos(ph), R / Z, "tan phi = X/R, 0 < phi < pi/2"),
        R_(44, 1, "derived", r"P = I_{\mathrm{rms}}^2 R", Pw, Ir**2 * R, "cos phi = R/Z and I_0 = V_0/Z"),
        R_(44, 2, "wrong", r"= \frac{V_{\mathrm{rms}}^2 R}{Z}", Ir**2 * R, Vr**2 * R / Z, "wrong power: Z^2"),
        R_(49, 0, "approx", r"\cos\varphi \approx 1 - \frac{X^2}{2 R^2}", sp.cos(ph), 1 - X**2 / (2 * R**2),
           "X << R", regime={X: eps * X}),
        R_(55, 1, "given", r"S = V_{\mathrm{rms}} I_{\mathrm{rms}}", Sa, Vr * Ir, "apparent power, new symbol", intro=[Sa]),
        R_(55, 2, "given", r"Q = V_{\mathrm{rms}} I_{\mathrm{rms}} \sin\varphi", Q, Vr * Ir * sp.sin(ph),
           "reactive power, new symbol", intro=[Q]),
        R_(59, 1, "derived", r"S^2 = P^2 + Q^2", Sa**2, Pw**2 + Q**2, "sin^2 + cos^2 = 1"),
        R_(59, 2, "derived", r"Q = I_{\mathrm{rms}}^2 X", Q, Ir**2 * X, "sin phi = X/Z (inline)"),
        R_(69, 1, "given", r"P_{\ell} = I_{\mathrm{rms}}^2\, r", Pl, Ir**2 * r, "loss in the feeder, new symbol", intro=[Pl]),
        R_(69, 2, "derived", r"I_{\mathrm{rms}} = \frac{P}{V_{\mathrm{rms}} \cos\varphi}", Ir, Pw / (Vr * sp.cos(ph)),
           "from P = V_rms I_rms cos phi"),
        R_(73, 0, "wrong", r"P_{\ell} = \frac{P^2\, r}{V_{\mathrm{rms}}^2 \cos\varphi}", Pl,
           Pw**2 * r / (Vr**2 * sp.cos(ph)), "wrong power: cos^2"),
    ]
    return dict(name="acpower.md", world=W, rows=rows, known=["T"],
                params={R: (1, 20), X: (1, 20), V0: (100, 400), w: (50, 400), r: (0.1, 2), t: (0.001, 0.1)})


@document
def atwood():
    M, rad, m1, m2, g, h = S("M r m_1 m_2 g h")
    I, a, al, T1, T2, v, th = S("I a alpha T_1 T_2 v t_h")
    y = sp.Function("y")
    den = m1 + m2 + M / 2
    W = {I: half * M * rad**2, a: (m1 - m2) * g / den, al: a / rad, T1: m1 * (g - a), T2: m2 * (g + a),
         y: half * a * t**2, v: sp.sqrt(2 * a * h), th: sp.sqrt(2 * h / a)}
    rows = [
        R_(10, 0, "given", r"I = \tfrac12 M r^2", I, half * M * rad**2, "disc, new symbol", intro=[I]),
        R_(18, 0, "given", r"a = r \alpha", a, rad * al, "no slip, introduces a", intro=[a]),
        R_(27, 0, "given", r"m_1 g - T_1 &= m_1 a", m1 * g - T1, m1 * a, "Newton for m_1, introduces T_1", intro=[T1]),
        R_(28, 0, "given", r"T_2 - m_2 g &= m_2 a", T2 - m2 * g, m2 * a, "Newton for m_2, introduces T_2", intro=[T2]),
        R_(29, 0, "given", r"(T_1 - T_2)\, r &= I \alpha", (T1 - T2) * rad, I * al, "torque on the pulley, introduces alpha",
           intro=[al]),
        R_(38, 1, "derived", r"T_1 - T_2 = \frac{I a}{r^2}", T1 - T2, I * a / rad**2, "torque / r with (2)"),
        R_(38, 2, "derived", r"= \tfrac12 M a", I * a / rad**2, half * M * a, "(1)"),
        R_(45, 0, "derived", r"(m_1 - m_2)\, g = \left( m_1 + m_2", (m1 - m2) * g, den * a, "add the block equations"),
        R_(49, 0, "derived", r"a = \frac{m_1 - m_2}{m_1 + m_2 + M/2}", a, (m1 - m2) * g / den, "solve for a"),
        R_(55, 1, "derived", r"T_1 = m_1 (g - a)", T1, m1 * (g - a), "first block equation"),
        R_(55, 2, "wrong", r"\frac{m_1 \left( 2 m_2 + M \right) g}", m1 * (g - a), m1 * (2 * m2 + M) * g / den,
           "dropped the 1/2: 2 m_2 + M/2"),
        R_(59, 1, "derived", r"T_2 = m_2 (g + a)", T2, m2 * (g + a), "second block equation"),
        R_(59, 2, "derived", r"\frac{m_2 \left( 2 m_1 + \tfrac12 M \right) g}", m2 * (g + a), m2 * (2 * m1 + M / 2) * g / den,
           "substitute (4)"),
        R_(65, 0, "derived", r"\lim_{M \to 0} a", sp.Limit(a, M, 0), (m1 - m2) / (m1 + m2) * g, "massless pulley"),
        R_(72, 0, "approx", r"a \approx \frac{m_1 - m_2}{m_1 + m_2} \left( 1", a,
           (m1 - m2) / (m1 + m2) * (1 - M / (2 * (m1 + m2))) * g, "first order in M/(m_1 + m_2)", regime={M: eps * M}),
        R_(81, 0, "given", r"\ddot{y} = a", sp.Derivative(y(t), (t, 2)), a, "equation of motion, introduces y", intro=[y]),
        R_(87, 1, "derived", r"\dot{y} = a t", Dt(y(t)), a * t, "integrate (inline ydot(0) = 0)"),
        R_(87, 2, "derived", r"y = \tfrac12 a t^2", y(t), half * a * t**2, "integrate again (inline y(0) = 0)"),
        R_(95, 0, "given", r"\tfrac12 (m_1 + m_2) v^2 + \tfrac12 I", half * (m1 + m2) * v**2 + half * I * (v / rad)**2,
           (m1 - m2) * g * h, "energy conservation, introduces v", intro=[v]),
        R_(101, 1, "derived", r"v^2 = \frac{2 (m_1 - m_2) g h}", v**2, 2 * (m1 - m2) * g * h / den, "solve with (1)"),
        R_(101, 2, "wrong", r"= a h ,", 2 * (m1 - m2) * g * h / den, a * h, "dropped factor 2: 2 a h"),
        R_(108, 1, "given", r"h = \tfrac12 a t_h^2", h, half * a * th**2, "fall time, new symbol", intro=[th]),
        R_(108, 2, "derived", r"t_h = \sqrt{\frac{2h}{a}}", th, sp.sqrt(2 * h / a), "solve for t_h > 0"),
        R_(112, 0, "derived", r"v = \sqrt{2 a h}", v, sp.sqrt(2 * a * h), "correct v^2 = 2 a h, v > 0"),
    ]
    return dict(name="atwood.md", world=W, rows=rows,
                params={M: (0.1, 2), rad: (0.05, 0.3), m1: (2, 4), m2: (0.5, 1.8), g: (9, 10), h: (0.2, 3), t: (0.1, 3)})


if __name__ == "__main__":
    sys.exit(V.main())
