#!/usr/bin/env python3
"""Check the labels of the fifth held-out set against hand-written SymPy models.

Every labelled relation of every document in this folder is transcribed below
by hand.  Each document has a *world*: the value of every quantity its rows
fix, written in the document's free parameters (functions such as T(x) or
y(x,t) are given as Lambdas).  For each relation, in document order:

* given   - holds in the world and mentions a symbol no earlier row (or prose
            relation marked Inline) mentioned;
* derived - uses only symbols already introduced, and holds in the world
            (symbolically, or else to 1e-15 at every sample point);
* wrong   - uses only symbols already introduced, and is false at a sample
            point of the world (where every earlier row holds);
* approx  - uses only symbols already introduced, is not exact, and in the
            regime the prose states (a substitution in a small eps) its
            relative error at eps = 1e-7 is below 1e-5 and not above the one
            at eps = 1e-3.

It also checks the text: the .expect file lists exactly the transcribed
(line, link, label) triples; every labelled line is the first math line of a
displayed row (found by a small parser of the LaTeX environments / $$ blocks);
every displayed row is labelled; the number of links on a line equals the
number of '=' and '\\approx' in the row; and a snippet of each transcribed
relation occurs on its line.

Usage: python3 verify_heldout5.py [NAME ...]      (exit status 1 on mismatch)
"""

import random
import re
import sys
from pathlib import Path

import sympy as sp
from sympy.core.function import AppliedUndef

HERE = Path(__file__).resolve().parent
S = sp.Rational
pi = sp.pi


# --------------------------------------------------------------------------
# data structures

class Rel:
    def __init__(self, line, link, label, lhs, rhs, snip, regime=None):
        self.line, self.link, self.label = line, link, label
        self.lhs, self.rhs = sp.sympify(lhs), sp.sympify(rhs)
        self.snip, self.regime = snip, regime


class Inline:
    """Symbols introduced by a relation in the prose (context, no label)."""

    def __init__(self, *names, note=""):
        self.names, self.note = set(names), note


class Doc:
    def __init__(self, name, fname, world, funcs, sampler, items):
        self.name, self.fname = name, fname
        self.world, self.funcs = world, funcs
        self.sampler, self.items = sampler, items

    def resolve(self, expr):
        expr = sp.sympify(expr)
        for _ in range(12):
            new = expr
            for f, lam in self.funcs.items():
                new = new.replace(f, lam)
            new = new.subs(self.world).doit()
            if new == expr:
                break
            expr = new
        return expr

    def points(self, k=4, seed=5):
        rng = random.Random(seed)
        return [self.sampler(rng) for _ in range(k)]


def rnd(rng, lo, hi):
    """A random rational in [lo, hi]."""
    return S(rng.randint(int(lo * 1000), int(hi * 1000)), 1000)


def names(expr):
    out = {s.name for s in expr.free_symbols}
    out |= {f.func.__name__ for f in expr.atoms(AppliedUndef)}
    return out


# --------------------------------------------------------------------------
# numeric helpers

DIG = 40


def num(expr, pt):
    val = sp.N(expr.subs(pt), DIG)
    if not val.is_number:
        raise ValueError("not numeric: %s" % val)
    return complex(val)


def holds(doc, rel):
    d = doc.resolve(rel.lhs - rel.rhs)
    try:
        if sp.simplify(d) == 0:
            return True, "symbolic"
    except Exception:
        pass
    lw, rw = doc.resolve(rel.lhs), doc.resolve(rel.rhs)
    for pt in doc.points():
        a, b = num(lw, pt), num(rw, pt)
        if abs(a - b) > 1e-15 * (1 + abs(a) + abs(b)):
            return False, "differs at %s: %r vs %r" % (pt, a, b)
    return True, "numeric"


def refuted(doc, rel):
    lw, rw = doc.resolve(rel.lhs), doc.resolve(rel.rhs)
    for pt in doc.points():
        a, b = num(lw, pt), num(rw, pt)
        if abs(a - b) > 1e-6 * (abs(a) + abs(b)):
            return True, "false at a sample point (%.6g vs %.6g)" % (a.real, b.real)
    return False, "holds at every sample point"


def approx_ok(doc, rel):
    eps = sp.Symbol("eps", positive=True)
    d = doc.resolve(rel.lhs - rel.rhs)
    if sp.simplify(d) == 0:
        return False, "exact, should be approx"
    lw = doc.resolve(rel.lhs).subs(rel.regime(eps), simultaneous=True)
    rw = doc.resolve(rel.rhs).subs(rel.regime(eps), simultaneous=True)
    for pt in doc.points():
        errs = []
        for e in (S(1, 10**7), S(1, 10**3)):
            a = num(lw.subs(eps, e), pt)
            b = num(rw.subs(eps, e), pt)
            errs.append(abs(a - b) / abs(a))
        if not (errs[0] < 1e-5 and errs[0] <= errs[1] and errs[1] > 1e-20):
            return False, "relative errors %.3g (1e-7), %.3g (1e-3)" % tuple(errs)
    return True, "relative error %.2g at eps=1e-7" % errs[0]


# --------------------------------------------------------------------------
# text parsing

DISPLAY_ENVS = r"equation\*?|align\*?|gather\*?|eqnarray\*?|multline\*?"
STRIP = [r"\\begin\{(?:split|aligned|gathered)\}", r"\\end\{(?:split|aligned|gathered)\}",
         r"\\label\{[^}]*\}", r"\\tag\{[^}]*\}", r"\\nonumber", r"\\notag"]


def blank(s, pattern):
    return re.sub(pattern, lambda m: " " * len(m.group(0)), s)


def rows_of(text, start, end):
    """Rows of the display text[start:end]: {line: row text}."""
    body = text[start:end]
    for pat in STRIP:
        body = blank(body, pat)
    rows, pos = {}, 0
    for seg in re.split(r"(\\\\)", body):
        if seg != "\\\\":
            m = re.search(r"\S", seg)
            if m:
                line = text.count("\n", 0, start + pos + m.start()) + 1
                rows[line] = seg
        pos += len(seg)
    return rows


def display_rows(path):
    text = path.read_text()
    rows = {}
    if path.suffix == ".tex":
        # drop comments, keeping positions
        text = re.sub(r"(?<!\\)%[^\n]*", lambda m: " " * len(m.group(0)), text)
        for m in re.finditer(r"\\begin\{(%s)\}|\\\[" % DISPLAY_ENVS, text):
            if m.group(1):
                e = re.compile(r"\\end\{%s\}" % re.escape(m.group(1))).search(text, m.end())
            else:
                e = re.compile(r"\\\]").search(text, m.end())
            rows.update(rows_of(text, m.end(), e.start()))
    else:
        text = re.sub(r"<!--.*?-->", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text,
                      flags=re.S)
        marks = [m.start() for m in re.finditer(r"\$\$", text)]
        assert len(marks) % 2 == 0, "unbalanced $$ in %s" % path
        for a, b in zip(marks[0::2], marks[1::2]):
            rows.update(rows_of(text, a + 2, b))
    return rows


def n_relations(row):
    return row.count("=") + row.count("\\approx")


def read_expect(path):
    out = []
    for raw in path.read_text().splitlines():
        s = raw.split("#", 1)[0].strip()
        if not s:
            continue
        line, link, label = s.split()
        out.append((int(line), int(link), label))
    return out


# --------------------------------------------------------------------------
# documents

def doc_skater():
    M, R, m, r1, r2, wi, r, u = sp.symbols("M R m r_1 r_2 omega_i r u", positive=True)
    Ib, Ii, If, L, wf, Ki, Kf, DK, W = sp.symbols("I_b I_i I_f L omega_f K_i K_f DeltaK W")
    om, F = sp.Function("omega"), sp.Function("F")
    world = {Ib: M * R**2 / 2, Ii: Ib + 2 * m * r1**2, If: Ib + 2 * m * r2**2,
             L: Ii * wi, wf: Ii * wi / If, Ki: Ii * wi**2 / 2, Kf: If * wf**2 / 2,
             DK: Kf - Ki, W: L**2 / 2 * (1 / If - 1 / Ii)}
    funcs = {om: sp.Lambda(r, L / (Ib + 2 * m * r**2)),
             F: sp.Lambda(r, m * om(r)**2 * r)}

    def sampler(g):
        return {M: rnd(g, 50, 80), R: rnd(g, 0.15, 0.25), m: rnd(g, 1, 5),
                r1: rnd(g, 0.6, 0.9), r2: rnd(g, 0.2, 0.35), wi: rnd(g, 2, 6),
                r: rnd(g, 0.2, 0.9)}

    bar = Ii * wi**2 / 2 * (Ii / If - 1)
    Wint = -sp.Integral(2 * F(r), (r, r1, r2))
    items = [
        Rel(25, 0, "given", Ib, M * R**2 / 2, r"\Ib = \tfrac12 M R^2"),
        Rel(30, 0, "given", Ii, Ib + 2 * m * r1**2, r"\Ii &= \Ib + 2 m r_1^2"),
        Rel(31, 0, "given", If, Ib + 2 * m * r2**2, r"\If &= \Ib + 2 m r_2^2"),
        Rel(35, 1, "given", L, Ii * wi, r"L = \Ii\,\wi"),
        Rel(35, 2, "given", Ii * wi, If * wf, r"= \If\,\wf"),
        Rel(40, 1, "derived", wf, Ii / If * wi, r"\wf = \frac{\Ii}{\If}\,\wi"),
        Rel(40, 2, "wrong", Ii / If * wi,
            (M * R**2 + 2 * m * r1**2) / (M * R**2 + 2 * m * r2**2) * wi, r"\wf = \frac"),
        Rel(46, 0, "approx", wf / wi, 1 + 4 * m * (r1**2 - r2**2) / (M * R**2),
            r"\approx 1 + \frac{4 m\,(r_1^2 - r_2^2)}{M R^2}",
            regime=lambda e: {m: e * m}),
        Rel(54, 1, "given", Ki, Ii * wi**2 / 2, r"K_{\text{i}} = \tfrac12\,\Ii\,\wi^2"),
        Rel(54, 2, "given", Kf, If * wf**2 / 2, r"K_{\text{f}} = \tfrac12\,\If\,\wf^2"),
        Rel(55, 1, "derived", Kf / Ki, If * wf**2 / (Ii * wi**2), r"\frac{\If\,\wf^2}{\Ii\,\wi^2}"),
        Rel(55, 2, "wrong", If * wf**2 / (Ii * wi**2), If / Ii, r"= \frac{\If}{\Ii}"),
        Rel(60, 1, "given", DK, Kf - Ki, r"\Delta K = K_{\text{f}} - K_{\text{i}}"),
        Rel(60, 2, "derived", Kf - Ki, bar, r"\Delta K"),
        Rel(62, 0, "derived", bar, L**2 / 2 * (1 / If - 1 / Ii),
            r"&= \frac{L^2}{2}\left(\frac{1}{\If} - \frac{1}{\Ii}\right)"),
        Rel(67, 0, "given", om(r), L / (Ib + 2 * m * r**2), r"\omega(r) = \frac{L}{\Ib + 2 m r^2}"),
        Rel(71, 1, "given", F(r), m * om(r)**2 * r, r"F(r) = m\,\omega(r)^2\, r"),
        Rel(71, 2, "derived", m * om(r)**2 * r, m * L**2 * r / (Ib + 2 * m * r**2)**2,
            r"= \frac{m L^2 r}{(\Ib + 2 m r^2)^2}"),
        Rel(76, 0, "given", W, Wint, r"W &= -\int_{r_1}^{r_2} 2F(r)\,\dd r"),
        Rel(77, 0, "derived", Wint,
            sp.Integral(2 * m * L**2 * r / (Ib + 2 * m * r**2)**2, (r, r2, r1)),
            r"&= \int_{r_2}^{r_1} \frac{2 m L^2 r}{(\Ib + 2 m r^2)^2}\,\dd r"),
        Rel(82, 1, "derived", W, L**2 / 2 * sp.Integral(1 / u**2, (u, If, Ii)),
            r"W = \frac{L^2}{2}\int_{\If}^{\Ii} \frac{\dd u}{u^2}"),
        Rel(82, 2, "derived", L**2 / 2 * sp.Integral(1 / u**2, (u, If, Ii)),
            L**2 / 2 * (1 / If - 1 / Ii), r"W = "),
        Rel(82, 3, "derived", L**2 / 2 * (1 / If - 1 / Ii), DK, r"W = "),
    ]
    return Doc("skater", "skater.tex", world, funcs, sampler, items)


def doc_cyclotron():
    q, m, v, B, R, V, al = sp.symbols("q m v B R V alpha", positive=True)
    t = sp.Symbol("t", real=True)
    r, wc, T, vmax, Kmax, N, vpar, vperp, rh, p, de = sp.symbols(
        "r omega_c T v_max K_max N v_par v_perp r_h p delta")
    x, y, vx, vy = (sp.Function(s) for s in ("x", "y", "v_x", "v_y"))
    world = {r: m * v / (q * B), wc: q * B / m, T: 2 * pi / wc,
             vmax: q * B * R / m, Kmax: m * vmax**2 / 2, N: Kmax / (2 * q * V),
             vpar: v * sp.cos(al), vperp: v * sp.sin(al), rh: m * vperp / (q * B),
             p: vpar * T, de: pi / 2 - al}
    funcs = {x: sp.Lambda(t, r * sp.sin(wc * t)), y: sp.Lambda(t, r * (sp.cos(wc * t) - 1)),
             vx: sp.Lambda(t, sp.diff(r * sp.sin(wc * t), t)),
             vy: sp.Lambda(t, sp.diff(r * (sp.cos(wc * t) - 1), t))}

    def sampler(g):
        return {q: rnd(g, 1, 3), m: rnd(g, 1, 4), v: rnd(g, 1, 5), B: rnd(g, 0.5, 2),
                t: rnd(g, 0.1, 3), R: rnd(g, 1, 3), V: rnd(g, 0.5, 2), al: rnd(g, 0.3, 1.2)}

    items = [
        Rel(17, 0, "given", q * v * B, m * v**2 / r, r"q v B = \frac{m v^2}{r}"),
        Rel(21, 0, "derived", r, m * v / (q * B), r"r = \frac{m v}{q B}"),
        Rel(25, 1, "given", wc, v / r, r"\wc = \frac{v}{r}"),
        Rel(25, 2, "derived", v / r, q * B / m, r"= \frac{q B}{m}"),
        Rel(30, 1, "given", T, 2 * pi / wc, r"T = \frac{2\pi}{\wc}"),
        Rel(30, 2, "derived", 2 * pi / wc, 2 * pi * m / (q * B), r"= \frac{2\pi m}{q B}"),
        Rel(39, 0, "given", x(t), r * sp.sin(wc * t), r"x(t) &=& r \sin(\wc t)"),
        Rel(40, 0, "given", y(t), r * (sp.cos(wc * t) - 1), r"y(t) &=& r\left[\cos(\wc t) - 1\right]"),
        Rel(44, 1, "given", vx(t), sp.Derivative(x(t), t), r"v_x &= \dot{x}"),
        Rel(44, 2, "derived", sp.Derivative(x(t), t), v * sp.cos(wc * t), r"= v\cos(\wc t)"),
        Rel(45, 1, "given", vy(t), sp.Derivative(y(t), t), r"v_y &= \dot{y}"),
        Rel(45, 2, "derived", sp.Derivative(y(t), t), -v * sp.sin(wc * t), r"= -v\sin(\wc t)"),
        Rel(50, 1, "derived", m * sp.Derivative(vx(t), t), -m * v * wc * sp.sin(wc * t),
            r"m\,\dot{v}_x &=& -m v\wc \sin(\wc t)"),
        Rel(50, 2, "derived", -m * v * wc * sp.sin(wc * t), q * B * vy(t), r"= q B\, v_y"),
        Rel(51, 1, "derived", m * sp.Derivative(vy(t), t), -m * v * wc * sp.cos(wc * t),
            r"m\,\dot{v}_y &=& -m v\wc \cos(\wc t)"),
        Rel(51, 2, "wrong", -m * v * wc * sp.cos(wc * t), q * B * vx(t), r"= q B\, v_x"),
        Rel(63, 0, "given", R, m * vmax / (q * B), r"R = \frac{m v_{\max}}{q B}"),
        Rel(64, 1, "given", Kmax, m * vmax**2 / 2, r"K_{\max} = \tfrac12 m v_{\max}^2"),
        Rel(64, 2, "wrong", m * vmax**2 / 2, q**2 * B * R**2 / (2 * m), r"= \frac{q^2 B R^2}{2 m}"),
        Rel(69, 1, "given", Kmax, 2 * N * q * V, r"K_{\max} = 2 N q V"),
        Rel(69, 2, "derived", N, q * B**2 * R**2 / (4 * m * V), r"N = \frac{q B^2 R^2}{4 m V}"),
        Inline("v_par", "v_perp", "alpha", "r_h",
               note=r"$\vpar = v\cos\alpha$, $\vperp = v\sin\alpha$, $r_{\text{h}} = m\vperp/(qB)$"),
        Rel(81, 1, "given", p, vpar * T, r"p = \vpar\,T"),
        Rel(81, 2, "derived", vpar * T, 2 * pi * m * v * sp.cos(al) / (q * B),
            r"= \frac{2\pi m v\cos\alpha}{q B}"),
        Rel(85, 1, "derived", p / rh, 2 * pi * vpar / vperp, r"\frac{p}{r_{\text{h}}} = \frac{2\pi\vpar}{\vperp}"),
        Rel(85, 2, "wrong", 2 * pi * vpar / vperp, 2 * pi * sp.tan(al), r"= 2\pi\tan\alpha"),
        Inline("delta", note=r"$\alpha = \pi/2 - \delta$"),
        Rel(90, 0, "approx", p, 2 * pi * r * de, r"p \approx 2\pi r\,\delta",
            regime=lambda e: {al: pi / 2 - e}),
    ]
    return Doc("cyclotron", "cyclotron.tex", world, funcs, sampler, items)


def doc_wall():
    k1, k2, L1, L2, hi, ho, Ti, To, A, t = sp.symbols(
        "k_1 k_2 L_1 L_2 h_i h_o T_i T_o A t", positive=True)
    x, tp = sp.symbols("x t'", real=True)
    q, T1, T2, T3, Rtot, U, Qd, Q = sp.symbols("q T_1 T_2 T_3 R_tot U Qdot Q")
    T = sp.Function("T")
    world = {Rtot: 1 / hi + L1 / k1 + L2 / k2 + 1 / ho, U: 1 / Rtot, q: (Ti - To) / Rtot,
             T1: Ti - q / hi, T2: T1 - q * L1 / k1, T3: T2 - q * L2 / k2,
             Qd: q * A, Q: Qd * t}
    funcs = {T: sp.Lambda(x, T1 - q * x / k1)}

    def sampler(g):
        return {k1: rnd(g, 0.6, 1.0), k2: rnd(g, 0.02, 0.05), L1: rnd(g, 0.1, 0.25),
                L2: rnd(g, 0.05, 0.15), hi: rnd(g, 5, 10), ho: rnd(g, 15, 30),
                Ti: rnd(g, 290, 295), To: rnd(g, 265, 280), A: rnd(g, 5, 20),
                t: rnd(g, 1000, 90000), x: rnd(g, 0, 0.1)}

    brick = q * (1 / hi + L1 / k1)
    items = [
        Rel(23, 0, "given", q, -k1 * sp.Derivative(T(x), x), r"q = -k_1\,\frac{\mathrm{d}T}{\mathrm{d}x}"),
        Inline("T_1", note="$T(0) = T_1$"),
        Rel(29, 0, "derived", T(x), T1 - q * x / k1, r"T(x) = T_1 - \frac{q\,x}{k_1}"),
        Rel(34, 1, "given", T2, T(L1), r"T_2 = T(L_1)"),
        Rel(34, 2, "derived", T(L1), T1 - q * L1 / k1, r"= T_1 - \frac{q L_1}{k_1}"),
        Rel(34, 3, "derived", q, k1 / L1 * (T1 - T2), r"T_2 = T(L_1) = T_1"),
        Rel(46, 0, "given", q, hi * (Ti - T1), r"q &= \hi\,(\Ti - T_1)"),
        Rel(47, 0, "given", q, k2 / L2 * (T2 - T3), r"q &= \frac{k_2}{L_2}\,(T_2 - T_3)"),
        Rel(48, 0, "given", q, ho * (T3 - To), r"q &= \ho\,(T_3 - \To)"),
        Rel(52, 1, "derived", Ti - T1, q / hi, r"\Ti - T_1 &= q/\hi"),
        Rel(52, 2, "wrong", T1 - T2, q * k1 / L1, r"T_1 - T_2 &= q\,k_1/L_1"),
        Rel(53, 1, "derived", T2 - T3, q * L2 / k2, r"T_2 - T_3 &= q\,L_2/k_2"),
        Rel(53, 2, "derived", T3 - To, q / ho, r"T_3 - \To &= q/\ho"),
        Rel(57, 0, "derived", Ti - To, q * (1 / hi + L1 / k1 + L2 / k2 + 1 / ho),
            r"\Ti - \To = q\left(\frac{1}{\hi}"),
        Rel(63, 1, "given", Rtot, 1 / hi + L1 / k1 + L2 / k2 + 1 / ho, r"\Rtot = \frac{1}{\hi}"),
        Rel(63, 2, "given", U, 1 / Rtot, r"\Rtot = "),
        Rel(65, 1, "derived", q, (Ti - To) / Rtot, r"q = \frac{\Ti - \To}{\Rtot}"),
        Rel(65, 2, "derived", (Ti - To) / Rtot, U * (Ti - To), r"= U\,(\Ti - \To)"),
        Inline("A", "Qdot", note=r"$\dot{Q} = q A$"),
        Rel(70, 1, "given", Q, sp.Integral(Qd, (tp, 0, t)), r"Q = \int_0^t \dot{Q}\,\mathrm{d}t'"),
        Rel(70, 2, "derived", sp.Integral(Qd, (tp, 0, t)), U * A * (Ti - To) * t,
            r"= U A\,(\Ti - \To)\,t"),
        Rel(79, 0, "derived", T2, Ti - brick, r"T_2 &= \Ti - q\left(\frac{1}{\hi} + \frac{L_1}{k_1}\right)"),
        Rel(80, 0, "wrong", Ti - brick, To - q * (L2 / k2 + 1 / ho),
            r"&= \To - q\left(\frac{L_2}{k_2} + \frac{1}{\ho}\right)"),
        Rel(87, 1, "derived", (T2 - T3) / (Ti - To), (L2 / k2) / Rtot,
            r"\frac{T_2 - T_3}{\Ti - \To} = \frac{L_2/k_2}{\Rtot}"),
        Rel(87, 2, "derived", (L2 / k2) / Rtot, L2 / (k2 * Rtot), r"\frac{T_2 - T_3}"),
        Rel(93, 0, "approx", q, k2 / L2 * (Ti - To), r"q \approx \frac{k_2}{L_2}\,(\Ti - \To)",
            regime=lambda e: {k2: e * k2}),
    ]
    return Doc("wall", "wall.tex", world, funcs, sampler, items)


def doc_escape():
    G, M, m, R, r, v0 = sp.symbols("G M m R r v_0", positive=True)
    h, vesc, g, vc, E, K, dv, dE = sp.symbols("h v_esc g v_c E K Delta_v Delta_E")
    U, F = sp.Function("U"), sp.Function("F")
    world = {h: R**2 * v0**2 / (2 * G * M - R * v0**2), vesc: sp.sqrt(2 * G * M / R),
             g: G * M / R**2, vc: sp.sqrt(G * M / r), E: m * vc**2 / 2 - G * M * m / r,
             K: m * vc**2 / 2, dv: sp.sqrt(2 * G * M / r) - vc,
             dE: m * (sp.sqrt(2) * vc)**2 / 2 - m * vc**2 / 2}
    funcs = {U: sp.Lambda(r, -G * M * m / r), F: sp.Lambda(r, -G * M * m / r**2)}

    def sampler(gen):
        Gv, Mv, Rv = rnd(gen, 0.5, 2), rnd(gen, 1, 5), rnd(gen, 1, 2)
        v0v = rnd(gen, 0.2, 0.8) * sp.sqrt(2 * Gv * Mv / Rv)
        return {G: Gv, M: Mv, m: rnd(gen, 1, 3), R: Rv, r: rnd(gen, 2, 5), v0: v0v}

    half = m * vc**2 / 2
    items = [
        Rel(13, 0, "given", U(r), -G * M * m / r, r"U(r) = -\frac{G M m}{r}"),
        Rel(17, 1, "given", F(r), -sp.Derivative(U(r), r), r"F(r) = -\frac{dU}{dr}"),
        Rel(17, 2, "derived", -sp.Derivative(U(r), r), -G * M * m / r**2, r"= -\frac{G M m}{r^2}"),
        Rel(27, 0, "given", m * v0**2 / 2 - G * M * m / R, -G * M * m / (R + h),
            r"\tfrac12 m v_0^2 - \frac{G M m}{R} = -\frac{G M m}{R + h}"),
        Rel(34, 1, "given", m * vesc**2 / 2, G * M * m / R, r"\tfrac12 m v_{\text{esc}}^2 = \frac{G M m}{R}"),
        Rel(34, 2, "wrong", vesc, sp.sqrt(G * M / R), r"v_{\text{esc}} = \sqrt{\frac{G M}{R}}"),
        Rel(38, 1, "given", g, G * M / R**2, r"g = \frac{G M}{R^2}"),
        Rel(38, 2, "derived", vesc**2, 2 * g * R, r"v_{\text{esc}}^2 = 2 g R"),
        Rel(42, 0, "derived", G * M / (R + h), (vesc**2 - v0**2) / 2,
            r"\frac{G M}{R + h} = \tfrac12\left(v_{\text{esc}}^2 - v_0^2\right)"),
        Rel(46, 0, "wrong", h, R * v0**2 / (vesc**2 + v0**2),
            r"h = \frac{R\, v_0^2}{v_{\text{esc}}^2 + v_0^2}"),
        Rel(52, 1, "approx", h, R * v0**2 / vesc**2, r"h \approx \frac{R\, v_0^2}{v_{\text{esc}}^2}",
            regime=lambda e: {v0: e * v0}),
        Rel(52, 2, "derived", R * v0**2 / vesc**2, v0**2 / (2 * g), r"= \frac{v_0^2}{2g}"),
        Rel(58, 1, "given", m * vc**2 / r, G * M * m / r**2, r"\frac{m v_{\text{c}}^2}{r} = \frac{G M m}{r^2}"),
        Rel(58, 2, "derived", vc, sp.sqrt(G * M / r), r"v_{\text{c}} = \sqrt{\frac{G M}{r}}"),
        Rel(62, 1, "given", E, half - G * M * m / r, r"E = \tfrac12 m v_{\text{c}}^2 - \frac{G M m}{r}"),
        Rel(62, 2, "derived", half - G * M * m / r, -G * M * m / (2 * r), r"= -\frac{G M m}{2 r}"),
        Rel(67, 1, "given", K, half, r"K = \tfrac12 m v_{\text{c}}^2"),
        Rel(67, 2, "derived", half, -E, r"= -E"),
        Rel(67, 3, "derived", U(r), 2 * E, r"U(r) = 2E"),
        Rel(72, 1, "given", dv, sp.sqrt(2 * G * M / r) - vc, r"\Delta v = \sqrt{\frac{2 G M}{r}} - v_{\text{c}}"),
        Rel(72, 2, "derived", sp.sqrt(2 * G * M / r) - vc, (sp.sqrt(2) - 1) * vc,
            r"= \left(\sqrt2 - 1\right) v_{\text{c}}"),
        Rel(76, 1, "given", dE, m * (sp.sqrt(2) * vc)**2 / 2 - half,
            r"\Delta E = \tfrac12 m\left(\sqrt2\,v_{\text{c}}\right)^2 - \tfrac12 m v_{\text{c}}^2"),
        Rel(76, 2, "derived", m * (sp.sqrt(2) * vc)**2 / 2 - half, half, r"= \tfrac12 m v_{\text{c}}^2 ="),
        Rel(76, 3, "wrong", half, G * M * m / (2 * r**2), r"= \frac{G M m}{2 r^2}"),
    ]
    return Doc("escape", "escape.md", world, funcs, sampler, items)


def doc_string():
    F, mu, A, k, L, de = sp.symbols("F mu A k L delta", positive=True)
    n = sp.Symbol("n", integer=True, positive=True)
    x, t = sp.symbols("x t", real=True)
    v, w, ys, kn, lam, f1p, wn, En = sp.symbols("v omega y_s k_n lambda_n f_1' omega_n E_n")
    y, y1, y2, yn, f, Kn = (sp.Function(s) for s in ("y", "y_1", "y_2", "y_n", "f", "K_n"))
    Y1 = A * sp.sin(k * x - w * t)
    Y2 = A * sp.sin(k * x + w * t)
    world = {v: sp.sqrt(F / mu), w: k * v, ys: Y1 + Y2, kn: n * pi / L, lam: 2 * pi / kn,
             f1p: sp.sqrt(F * (1 + de) / mu) / (2 * L), wn: v * kn, En: mu * A**2 * wn**2 * L}
    funcs = {y1: sp.Lambda((x, t), Y1), y2: sp.Lambda((x, t), Y2),
             y: sp.Lambda((x, t), Y1 + Y2), f: sp.Lambda(n, n * v / (2 * L)),
             yn: sp.Lambda((x, t), 2 * A * sp.sin(kn * x) * sp.cos(wn * t)),
             Kn: sp.Lambda(t, mu * A**2 * wn**2 * L * sp.sin(wn * t)**2)}

    def sampler(g):
        return {F: rnd(g, 1, 5), mu: rnd(g, 0.5, 2), A: rnd(g, 0.1, 1), k: rnd(g, 0.5, 3),
                L: rnd(g, 1, 3), de: rnd(g, 0.01, 0.1), n: g.randint(1, 4),
                x: rnd(g, 0, 2), t: rnd(g, 0, 2)}

    Kint = sp.Integral(mu / 2 * sp.Derivative(yn(x, t), t)**2, (x, 0, L))
    Kmid = 2 * mu * A**2 * wn**2 * sp.sin(wn * t)**2 * sp.Integral(sp.sin(kn * x)**2, (x, 0, L))
    items = [
        Rel(14, 0, "given", mu * sp.Derivative(y(x, t), (t, 2)), F * sp.Derivative(y(x, t), (x, 2)),
            r"\mu\,\frac{\partial^2 y}{\partial t^2} = F\,\frac{\partial^2 y}{\partial x^2}"),
        Rel(21, 0, "given", v, sp.sqrt(F / mu), r"v = \sqrt{\frac{F}{\mu}}"),
        Rel(29, 0, "given", y1(x, t), Y1, r"y_1(x,t) = A\sin(kx - \omega t)"),
        Rel(36, 0, "derived", mu * w**2, F * k**2, r"\mu\,\omega^2 = F k^2"),
        Rel(40, 1, "derived", w / k, sp.sqrt(F / mu), r"\frac{\omega}{k} = \sqrt{\frac{F}{\mu}}"),
        Rel(40, 2, "derived", sp.sqrt(F / mu), v, r"= v"),
        Rel(48, 0, "given", y2(x, t), Y2, r"y_2(x,t) = A\sin(kx + \omega t)"),
        Rel(54, 1, "given", ys, y1(x, t) + y2(x, t), r"y_{\text{s}} = y_1 + y_2"),
        Rel(54, 2, "wrong", y1(x, t) + y2(x, t), A * sp.sin(k * x) * sp.cos(w * t),
            r"= A\sin(kx)\cos(\omega t)"),
        Rel(61, 0, "given", kn, n * pi / L, r"k_n = \frac{n\pi}{L}"),
        Rel(65, 1, "given", lam, 2 * pi / kn, r"\lambda_n = \frac{2\pi}{k_n}"),
        Rel(65, 2, "derived", 2 * pi / kn, 2 * L / n, r"= \frac{2L}{n}"),
        Rel(67, 1, "given", f(n), v / lam, r"f_n = \frac{v}{\lambda_n}"),
        Rel(67, 2, "wrong", v / lam, n / (2 * L) * F / mu, r"= \frac{n}{2L}\,\frac{F}{\mu}"),
        Rel(72, 1, "derived", f(2) / f(1), 2, r"\frac{f_2}{f_1} = 2"),
        Rel(72, 2, "derived", f(3) / f(1), 3, r"\frac{f_3}{f_1} = 3"),
        Rel(77, 1, "given", f1p, sp.sqrt(F * (1 + de) / mu) / (2 * L),
            r"f_1' = \frac{1}{2L}\sqrt{\frac{F(1 + \delta)}{\mu}}"),
        Rel(77, 2, "approx", sp.sqrt(F * (1 + de) / mu) / (2 * L), f(1) * (1 + de / 2),
            r"\approx f_1\left(1 + \frac{\delta}{2}\right)", regime=lambda e: {de: e}),
        Inline("y_n", "omega_n", note=r"$y_n = 2A\sin(k_n x)\cos(\omega_n t)$, $\omega_n = v k_n$"),
        Rel(88, 0, "given", Kn(t), Kint,
            r"K_n(t) &= \int_0^L \tfrac12\mu\left(\frac{\partial y_n}{\partial t}\right)^2 dx"),
        Rel(89, 0, "derived", Kint, Kmid,
            r"&= 2\mu A^2\omega_n^2\sin^2(\omega_n t)\int_0^L \sin^2(k_n x)\,dx"),
        Rel(90, 0, "derived", Kmid, mu * A**2 * wn**2 * L * sp.sin(wn * t)**2,
            r"&= \mu A^2 \omega_n^2 L\,\sin^2(\omega_n t)"),
        Rel(97, 1, "given", En, mu * A**2 * wn**2 * L, r"E_n = \mu A^2\omega_n^2 L"),
        Rel(97, 2, "wrong", mu * A**2 * wn**2 * L, pi**2 * n**2 * F * A**2 / L**2,
            r"= \frac{\pi^2 n^2 F A^2}{L^2}"),
    ]
    return Doc("string", "string.md", world, funcs, sampler, items)


def doc_carnot():
    n, R, Th, Tc, V1, V2, ga, V = sp.symbols("n R T_h T_c V_1 V_2 gamma V", positive=True)
    p, W12, Qh, V3, V4, Qc, W, eta, DT, dSh, dSc, Kr = sp.symbols(
        "p W_12 Q_h V_3 V_4 Q_c W eta DeltaT DeltaS_h DeltaS_c K_ref")
    world = {p: n * R * Th / V, W12: n * R * Th * sp.log(V2 / V1), Qh: W12,
             V3: V2 * (Th / Tc)**(1 / (ga - 1)), V4: V1 * (Th / Tc)**(1 / (ga - 1)),
             Qc: n * R * Tc * sp.log(V3 / V4), W: Qh - Qc, eta: W / Qh, DT: Th - Tc,
             dSh: Qh / Th, dSc: Qc / Tc, Kr: Qc / W}

    def sampler(g):
        return {n: rnd(g, 1, 3), R: rnd(g, 8, 9), Th: rnd(g, 350, 600), Tc: rnd(g, 250, 300),
                V1: rnd(g, 1, 2), V2: rnd(g, 2.5, 5), ga: rnd(g, 1.3, 1.67), V: rnd(g, 1, 5)}

    items = [
        Rel(17, 0, "given", p, n * R * Th / V, r"p = \frac{n R T_{\text{h}}}{V}"),
        Rel(23, 0, "given", W12, sp.Integral(p, (V, V1, V2)), r"W_{12} &= \int_{V_1}^{V_2} p\, dV"),
        Rel(24, 0, "derived", sp.Integral(p, (V, V1, V2)), n * R * Th * sp.log(V2 / V1),
            r"&= n R T_{\text{h}} \ln\frac{V_2}{V_1}"),
        Rel(33, 0, "given", Qh, W12, r"Q_{\text{h}} = W_{12}"),
        Rel(38, 0, "derived", V2 / V1, sp.exp(Qh / (n * R * Th)),
            r"\frac{V_2}{V_1} = e^{Q_{\text{h}}/(n R T_{\text{h}})}"),
        Rel(45, 1, "given", Th * V2**(ga - 1), Tc * V3**(ga - 1),
            r"T_{\text{h}} V_2^{\gamma-1} = T_{\text{c}} V_3^{\gamma-1}"),
        Rel(45, 2, "given", Th * V1**(ga - 1), Tc * V4**(ga - 1),
            r"T_{\text{h}} V_1^{\gamma-1} = T_{\text{c}} V_4^{\gamma-1}"),
        Rel(49, 1, "derived", (V2 / V1)**(ga - 1), (V3 / V4)**(ga - 1),
            r"\left(\frac{V_2}{V_1}\right)^{\gamma-1} = \left(\frac{V_3}{V_4}\right)^{\gamma-1}"),
        Rel(49, 2, "derived", V3 / V4, V2 / V1, r"\frac{V_3}{V_4} = \frac{V_2}{V_1}"),
        Rel(58, 1, "given", Qc, n * R * Tc * sp.log(V3 / V4),
            r"Q_{\text{c}} = n R T_{\text{c}} \ln\frac{V_3}{V_4}"),
        Rel(58, 2, "derived", n * R * Tc * sp.log(V3 / V4), n * R * Tc * sp.log(V2 / V1),
            r"= n R T_{\text{c}} \ln\frac{V_2}{V_1}"),
        Rel(62, 0, "derived", Qc / Qh, Tc / Th, r"\frac{Q_{\text{c}}}{Q_{\text{h}}} = \frac{T_{\text{c}}}{T_{\text{h}}}"),
        Rel(66, 0, "given", W, Qh - Qc, r"W = Q_{\text{h}} - Q_{\text{c}}"),
        Rel(70, 1, "given", eta, W / Qh, r"\eta = \frac{W}{Q_{\text{h}}}"),
        Rel(70, 2, "derived", W / Qh, 1 - Qc / Qh, r"= 1 - \frac{Q_{\text{c}}}{Q_{\text{h}}}"),
        Rel(70, 3, "derived", 1 - Qc / Qh, 1 - Tc / Th, r"= 1 - \frac{T_{\text{c}}}{T_{\text{h}}}"),
        Inline("DeltaT", note=r"$\Delta T = T_{\text{h}} - T_{\text{c}}$"),
        Rel(76, 0, "approx", eta, DT / Tc, r"\eta \approx \frac{\Delta T}{T_{\text{c}}}",
            regime=lambda e: {Th: Tc * (1 + e)}),
        Rel(82, 1, "given", dSh, Qh / Th, r"\Delta S_{\text{h}} = \frac{Q_{\text{h}}}{T_{\text{h}}}"),
        Rel(82, 2, "wrong", Qh / Th, n * R * Th * sp.log(V2 / V1), r"= n R\, T_{\text{h}} \ln\frac{V_2}{V_1}"),
        Rel(84, 1, "given", dSc, Qc / Tc, r"\Delta S_{\text{c}} = \frac{Q_{\text{c}}}{T_{\text{c}}}"),
        Rel(84, 2, "derived", Qc / Tc, dSh, r"= \Delta S_{\text{h}}"),
        Rel(94, 1, "given", Kr, Qc / W, r"K_{\text{ref}} = \frac{Q_{\text{c}}}{W}"),
        Rel(94, 2, "wrong", Qc / W, Th / (Th - Tc), r"= \frac{T_{\text{h}}}{T_{\text{h}} - T_{\text{c}}}"),
    ]
    return Doc("carnot", "carnot.md", world, {}, sampler, items)


DOCS = [doc_skater, doc_cyclotron, doc_wall, doc_escape, doc_string, doc_carnot]


# --------------------------------------------------------------------------
# checking

def check(doc):
    problems = []
    path = HERE / doc.fname
    lines = path.read_text().splitlines()
    rels = [it for it in doc.items if isinstance(it, Rel)]

    # text: expect file, rows, snippets, link counts
    expect = read_expect(path.with_suffix(".expect"))
    mine = [(r.line, r.link, r.label) for r in rels]
    if sorted(expect) != sorted(mine):
        problems.append("expect file differs from transcription: only in expect %s, only here %s"
                        % (sorted(set(expect) - set(mine)), sorted(set(mine) - set(expect))))
    if len(set(mine)) != len(mine):
        problems.append("duplicate (line, link) in transcription")
    rows = display_rows(path)
    labelled = {}
    for r in rels:
        labelled.setdefault(r.line, []).append(r.link)
        if r.snip not in lines[r.line - 1]:
            problems.append("line %d: snippet %r not on the line" % (r.line, r.snip))
    for line, links in labelled.items():
        if line not in rows:
            problems.append("line %d is not the first math line of a displayed row" % line)
            continue
        want = [0] if n_relations(rows[line]) == 1 else list(range(1, n_relations(rows[line]) + 1))
        if sorted(links) != want:
            problems.append("line %d: links %s but the row has %d relation(s)"
                            % (line, sorted(links), n_relations(rows[line])))
    for line in rows:
        if line not in labelled:
            problems.append("displayed row at line %d is not labelled" % line)

    # maths
    known = set()
    counts = {}
    for it in doc.items:
        if isinstance(it, Inline):
            known |= it.names
            continue
        r = it
        counts[r.label] = counts.get(r.label, 0) + 1
        used = names(r.lhs) | names(r.rhs)
        new = used - known
        tag = "line %d link %d (%s)" % (r.line, r.link, r.label)
        if r.label == "given":
            if not new:
                problems.append("%s: introduces no new symbol" % tag)
            ok, how = holds(doc, r)
            if not ok:
                problems.append("%s: does not hold in the world: %s" % (tag, how))
        else:
            if new:
                problems.append("%s: uses symbols not yet introduced: %s" % (tag, sorted(new)))
            if r.label == "derived":
                ok, how = holds(doc, r)
                if not ok:
                    problems.append("%s: does not hold: %s" % (tag, how))
            elif r.label == "wrong":
                ok, how = refuted(doc, r)
                if not ok:
                    problems.append("%s: not refuted: %s" % (tag, how))
            elif r.label == "approx":
                ok, how = approx_ok(doc, r)
                if not ok:
                    problems.append("%s: %s" % (tag, how))
            else:
                problems.append("%s: unknown label" % tag)
        known |= used
    return problems, counts, len(rels), len(labelled)


def main(argv):
    chosen = [d for d in DOCS if not argv[1:] or d.__name__[4:] in argv[1:]]
    total, bad = {}, 0
    nrel = nrow = 0
    for make in chosen:
        doc = make()
        problems, counts, k, rws = check(doc)
        nrel += k
        nrow += rws
        for lab, c in counts.items():
            total[lab] = total.get(lab, 0) + c
        status = "ok" if not problems else "MISMATCH"
        print("%-10s %-14s %2d relations on %2d rows: %2d derived, %2d given, %d wrong, %d approx  %s"
              % (doc.name, doc.fname, k, rws, counts.get("derived", 0), counts.get("given", 0),
                 counts.get("wrong", 0), counts.get("approx", 0), status))
        for p in problems:
            print("    " + p)
        bad += len(problems)
    print("total: %d relations on %d rows: %d derived, %d given, %d wrong, %d approx; %d problem(s)"
          % (nrel, nrow, total.get("derived", 0), total.get("given", 0), total.get("wrong", 0),
             total.get("approx", 0), bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
