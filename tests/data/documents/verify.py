#!/usr/bin/env python3
"""Check the labels of the test documents in this folder with SymPy.

For every document NAME.tex / NAME.md there is a sidecar NAME.expect
(`LINE LINK LABEL  # reason`, see README.md).  This script holds, per
document, a hand-written SymPy transcription of every labelled relation,
keyed by (LINE, LINK), and checks:

  * the .expect file and the transcription table agree (same keys, labels);
  * every LINE is the first math line of a displayed row of the document,
    every displayed row has a label, and a short text anchor written in
    the table occurs on that line (so line numbers cannot drift silently);
  * `given` rows hold in the document's model ("world") and introduce at
    least one symbol not fixed by earlier rows;
  * `derived` rows use only symbols fixed by earlier rows (or parameters)
    and hold identically in the world (symbolic simplification to 0, or
    at 6 random points to a relative 1e-12 with 50-digit arithmetic);
  * `wrong` rows use only fixed symbols and fail at a random point of the
    world (where every earlier true row holds), by more than 1e-6 relative;
  * `approx` rows hold to a relative error that goes to 0 in the regime
    the document states (a substitution in a small parameter eps).

The world of a document is its unique solution: every quantity that the
rows fix, written in terms of the free parameters.  The givens are
checked against it, so the world cannot disagree with the document.

Run: python3 tests/data/documents/verify.py   (exit status 1 on a mismatch)
"""
import os
import random
import re
import sys

import sympy as sp

HERE = os.path.dirname(os.path.abspath(__file__))
LABELS = ("derived", "given", "wrong", "approx")
t = sp.Symbol("t", positive=True)
eps = sp.Symbol("eps", positive=True)


def S(names):
    """Positive real symbols; names as in the document (v_1p stands for v_1')."""
    out = sp.symbols(names, positive=True)
    return out


class Row:
    def __init__(self, line, link, label, anchor, lhs, rhs, reason,
                 intro=(), regime=None, world=None, tol=None):
        assert label in LABELS, label
        self.line, self.link, self.label = line, link, label
        self.anchor, self.lhs, self.rhs = anchor, sp.sympify(lhs), sp.sympify(rhs)
        self.reason, self.intro, self.regime = reason, tuple(intro), regime
        self.world = world  # a different model for this row (a special case the prose states)
        self.tol = tol  # for a numeric approx row: the relative error its digits allow


def R_(*a, **k):
    return Row(*a, **k)


# ---------------------------------------------------------------- scanning

TEX_ENVS = r"(?:equation|align|gather|multline|eqnarray|flalign|alignat)\*?"


def strip_tex_comments(text):
    out = []
    for line in text.split("\n"):
        m = re.search(r"(?<!\\)%", line)
        out.append(line if m is None else line[:m.start()] + " " * (len(line) - m.start()))
    return "\n".join(out)


def display_regions(text, kind):
    """(start, end) offsets of the contents of displayed math."""
    regs = []
    if kind == "tex":
        body = strip_tex_comments(text)
        pat = re.compile(r"\\begin\{(" + TEX_ENVS + r")\}(.*?)\\end\{\1\}|\\\[(.*?)\\\]|\$\$(.*?)\$\$", re.S)
        for m in pat.finditer(body):
            g = 2 if m.group(2) is not None else (3 if m.group(3) is not None else 4)
            regs.append((m.start(g), m.end(g), m.group(1) or ""))
        return body, regs
    body = re.sub(r"<!--.*?-->", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text, flags=re.S)
    for m in re.finditer(r"\$\$(.*?)\$\$", body, re.S):
        regs.append((m.start(1), m.end(1), ""))
    return body, regs


SKIP = re.compile(r"\s+|\\begin\{[a-zA-Z*]+\}|\\end\{[a-zA-Z*]+\}|\\label\{[^}]*\}|\\nonumber\b|\\notag\b")


def row_start_lines(text, kind, with_text=False):
    """First math line of every displayed row (with the row's text and display number)."""
    body, regs = display_regions(text, kind)
    starts = []
    for di, (a, b, env) in enumerate(regs):
        seg = body[a:b]
        pieces = []
        pos = 0
        # a multline is one equation broken over lines: its \\ makes no new row
        breaks = [] if env.startswith("multline") else re.finditer(r"\\\\(\[[^\]]*\])?", seg)
        for m in breaks:
            pieces.append((pos, m.start()))
            pos = m.end()
        pieces.append((pos, len(seg)))
        for pa, pb in pieces:
            i = pa
            while i < pb:
                m = SKIP.match(seg, i, pb)
                if not m or m.end() == i:
                    break
                i = m.end()
            if i < pb:
                ln = body.count("\n", 0, a + i) + 1
                starts.append((ln, di, seg[i:pb]) if with_text else ln)
    return starts


# ---------------------------------------------------------------- checking

def names_of(expr):
    out = {str(s) for s in expr.free_symbols}
    out |= {f.func.__name__ for f in expr.atoms(sp.core.function.AppliedUndef)}
    return out


def apply_world(expr, world):
    for _ in range(6):
        new = expr
        for k, v in world.items():
            if isinstance(k, sp.FunctionClass):
                new = new.replace(k, sp.Lambda(t, v))
            else:
                new = new.subs(k, v)
        new = new.doit()
        if new == expr:
            break
        expr = new
    return expr


def rand_point(params, rng):
    pt = {}
    for s, (lo, hi) in params.items():
        pt[s] = sp.Rational(rng.randint(int(lo * 1000), int(hi * 1000)), 1000)
    return pt


def residual(l, r):
    """(absolute difference, scale) at 50 digits."""
    lv, rv = sp.N(l, 50), sp.N(r, 50)
    d = abs(complex(sp.N(lv - rv, 50)))
    sc = max(abs(complex(lv)), abs(complex(rv)))
    return d, sc


def holds_at(l, r, tol=1e-12):
    d, sc = residual(l, r)
    return d <= tol * sc + 1e-25, d, sc


def check_doc(doc, rng):
    errors = []
    name = doc["name"]
    path = os.path.join(HERE, name)
    text = open(path, encoding="utf-8").read()
    lines = text.split("\n")
    kind = "tex" if name.endswith(".tex") else "md"
    rows = doc["rows"]
    # the .expect file against the table
    exp_path = os.path.splitext(path)[0] + ".expect"
    exp = {}
    for n, ln in enumerate(open(exp_path, encoding="utf-8").read().split("\n"), 1):
        core = ln.split("#", 1)[0].strip()
        if not core:
            continue
        f = core.split()
        if len(f) != 3 or f[2] not in LABELS:
            errors.append(f"{exp_path}:{n}: bad line {ln!r}")
            continue
        key = (int(f[0]), int(f[1]))
        if key in exp:
            errors.append(f"{exp_path}:{n}: duplicate {key}")
        exp[key] = f[2]
    table = {}
    for r in rows:
        key = (r.line, r.link)
        if key in table:
            errors.append(f"{name}: table has {key} twice")
        table[key] = r
    for k in sorted(set(exp) | set(table)):
        if k not in exp:
            errors.append(f"{name}: {k} in verify.py but not in .expect")
        elif k not in table:
            errors.append(f"{name}: {k} in .expect but not in verify.py")
        elif exp[k] != table[k].label:
            errors.append(f"{name}: {k} label .expect={exp[k]} verify.py={table[k].label}")
    # lines: every label on a row start, every row start labelled, anchors
    starts = set(row_start_lines(text, kind))
    labelled = {k[0] for k in exp}
    for ln in sorted(labelled - starts):
        errors.append(f"{name}:{ln}: labelled line is not the first math line of a displayed row: "
                      f"{lines[ln - 1] if 0 < ln <= len(lines) else '<past end>'!r}")
    for ln in sorted(starts - labelled):
        errors.append(f"{name}:{ln}: displayed row without a label: {lines[ln - 1]!r}")
    for r in rows:
        if not (0 < r.line <= len(lines)) or r.anchor not in lines[r.line - 1]:
            where = [i + 1 for i, l in enumerate(lines) if r.anchor in l]
            errors.append(f"{name}:{r.line}:{r.link}: anchor {r.anchor!r} not on that line (found on {where})")
    # one slip is one wrong relation: a wrong link is the last of its row, and
    # the next row of the same display does not continue from it with "&="
    info = row_start_lines(text, kind, with_text=True)
    for k, lab in sorted(exp.items()):
        if lab != "wrong":
            continue
        if (k[0], k[1] + 1) in exp:
            errors.append(f"{name}:{k[0]}: wrong link {k[1]} is not the last link of its row")
        for j, (ln, di, seg) in enumerate(info):
            if ln == k[0] and j + 1 < len(info) and info[j + 1][1] == di \
                    and info[j + 1][2].lstrip().startswith("&"):
                errors.append(f"{name}:{k[0]}: the row after a wrong row continues from it with '&'")
    for k in sorted(exp):
        if k[1] > 0 and (k[0], 0) in exp:
            errors.append(f"{name}:{k[0]}: link 0 and link {k[1]} on one row")
    # the relations
    params = doc["params"]
    pnames = {str(s) for s in params}
    introduced = {str(s) for r in rows if r.label == "given" for s in r.intro}
    fixed = (set(pnames) - introduced) | set(doc.get("known", ()))
    rows_sorted = sorted(rows, key=lambda r: (r.line, r.link))
    for r in rows_sorted:
        tag = f"{name}:{r.line}:{r.link} [{r.label}]"
        used = names_of(r.lhs) | names_of(r.rhs)
        if r.label == "given":
            new = [str(s) for s in r.intro]
            if not new:
                errors.append(f"{tag}: a given must introduce a symbol")
            for s in new:
                if s in fixed:
                    errors.append(f"{tag}: introduces {s}, already fixed")
                if s not in used:
                    errors.append(f"{tag}: introduces {s}, which it does not use")
        else:
            if r.intro:
                errors.append(f"{tag}: only a given introduces symbols")
            loose = used - fixed - {"eps"}
            if loose and r.world is None:
                errors.append(f"{tag}: uses {sorted(loose)} not fixed by earlier rows")
        world = r.world if r.world is not None else doc["world"]
        L, Rr = apply_world(r.lhs, world), apply_world(r.rhs, world)
        if r.label in ("derived", "given"):
            exact = False
            try:
                exact = sp.simplify(L - Rr) == 0
            except Exception:
                pass
            if not exact:
                for _ in range(6):
                    pt = rand_point(params, rng)
                    ok, d, sc = holds_at(L.subs(pt), Rr.subs(pt))
                    if not ok:
                        errors.append(f"{tag}: does not hold at {pt}: |diff|={d:.3g}, scale={sc:.3g}  ({r.reason})")
                        break
        elif r.label == "wrong":
            fails = 0
            for _ in range(6):
                pt = rand_point(params, rng)
                d, sc = residual(L.subs(pt), Rr.subs(pt))
                if d > 1e-6 * sc and d > 1e-20:
                    fails += 1
            if fails == 0:
                errors.append(f"{tag}: labelled wrong but holds at every point tried  ({r.reason})")
        else:  # approx
            if r.tol is not None:
                for _ in range(3):
                    pt = rand_point(params, rng)
                    d, sc = residual(L.subs(pt), Rr.subs(pt))
                    if d > r.tol * sc:
                        errors.append(f"{tag}: relative error {d / sc:.3g} above {r.tol}  ({r.reason})")
                        break
            elif r.regime is None:
                errors.append(f"{tag}: approx row without a regime")
            else:
                for _ in range(3):
                    pt = rand_point(params, rng)
                    errs = []
                    for e in (sp.Rational(1, 10**3), sp.Rational(1, 10**7)):
                        Le = L.subs(r.regime).subs(pt).subs(eps, e)
                        Re = Rr.subs(r.regime).subs(pt).subs(eps, e)
                        d, sc = residual(Le, Re)
                        errs.append(d / sc if sc else d)
                    if not (errs[1] < 1e-5 and errs[1] <= errs[0]):
                        errors.append(f"{tag}: not close in the regime: rel err {errs}  ({r.reason})")
                        break
        if r.label == "given":
            fixed |= {str(s) for s in r.intro}
    counts = {l: sum(1 for r in rows if r.label == l) for l in LABELS}
    return errors, len(starts), counts


DOCS = []


def document(fn):
    DOCS.append(fn)
    return fn


# ================================================================ documents

@document
def projectile():
    v0, al, g, T, R, t1, H = S("v_0 alpha g T R t_1 H")
    tp = sp.Symbol("tp", positive=True)
    vx, vy, x, y = sp.symbols("v_x v_y x y", cls=sp.Function)
    half = sp.Rational(1, 2)
    world = {
        vx: v0 * sp.cos(al), vy: v0 * sp.sin(al) - g * t,
        x: v0 * t * sp.cos(al), y: v0 * t * sp.sin(al) - half * g * t**2,
        T: 2 * v0 * sp.sin(al) / g, R: v0**2 * sp.sin(2 * al) / g,
        t1: v0 * sp.sin(al) / g, H: v0**2 * sp.sin(al)**2 / (2 * g),
    }
    X, Y = x(t), y(t)
    rows = [
        R_(23, 1, "given", "v_x = v_0", vx(t), v0 * sp.cos(al), "horizontal velocity", intro=[vx]),
        R_(23, 2, "given", "v_y = v_0", vy(t), v0 * sp.sin(al) - g * t, "vertical velocity", intro=[vy]),
        R_(28, 0, "wrong", "\\dd v_y", sp.Derivative(vy(t), t), g, "sign slip: dv_y/dt = -g"),
        R_(32, 1, "given", "x &=", X, sp.Integral(vx(tp), (tp, 0, t)), "x defined as the integral (origin at launch)", intro=[x]),
        R_(32, 2, "derived", "x &=", sp.Integral(vx(tp), (tp, 0, t)), v0 * t * sp.cos(al), "integrating a constant"),
        R_(33, 1, "given", "y &=", Y, sp.Integral(vy(tp), (tp, 0, t)), "y defined as the integral", intro=[y]),
        R_(33, 2, "derived", "y &=", sp.Integral(vy(tp), (tp, 0, t)), v0 * t * sp.sin(al) - half * g * t**2, "integrating v_y"),
        R_(39, 0, "given", "v_0 T", v0 * T * sp.sin(al) - half * g * T**2, 0, "landing condition, introduces T (T>0 inline)", intro=[T]),
        R_(43, 0, "derived", "T = ", T, 2 * v0 * sp.sin(al) / g, "nonzero root of the quadratic"),
        R_(48, 0, "given", "R &=", R, v0 * T * sp.cos(al), "range = x at T, introduces R", intro=[R]),
        R_(49, 0, "derived", "&= \\frac{2", R, 2 * v0**2 * sp.sin(al) * sp.cos(al) / g, "substitute T"),
        R_(50, 0, "derived", "sin 2\\alpha", 2 * v0**2 * sp.sin(al) * sp.cos(al) / g, v0**2 * sp.sin(2 * al) / g, "double angle"),
        R_(54, 0, "wrong", "\\dd R", sp.Derivative(R, al), v0**2 * sp.cos(2 * al) / g, "dropped chain-rule factor 2"),
        R_(61, 0, "given", "g t_1 = 0", v0 * sp.sin(al) - g * t1, 0, "top of the path, introduces t_1", intro=[t1]),
        R_(65, 1, "derived", "t_1 =", t1, v0 * sp.sin(al) / g, "solve for t_1"),
        R_(65, 2, "derived", "t_1 =", v0 * sp.sin(al) / g, half * T, "compare with T"),
        R_(70, 0, "given", "H &=", H, v0 * t1 * sp.sin(al) - half * g * t1**2, "H = y(t_1), introduces H", intro=[H]),
        R_(71, 0, "derived", "&= \\frac{v_0^2", v0 * t1 * sp.sin(al) - half * g * t1**2,
           v0**2 * sp.sin(al)**2 / g - v0**2 * sp.sin(al)**2 / (2 * g), "substitute t_1"),
        R_(72, 0, "derived", "{2 g}", v0**2 * sp.sin(al)**2 / g - v0**2 * sp.sin(al)**2 / (2 * g),
           v0**2 * sp.sin(al)**2 / (2 * g), "collect"),
        R_(78, 0, "derived", "t = \\frac{x}", t, X / (v0 * sp.cos(al)), "solve x for t"),
        R_(82, 0, "wrong", "v_0^2\\cos\\alpha}", Y, v0 * sp.sin(al) * X / (v0 * sp.cos(al)) - half * g * X**2 / (v0**2 * sp.cos(al)),
           "wrong power: cos alpha should be squared"),
        R_(86, 0, "derived", "x \\tan", Y, X * sp.tan(al) - g * X**2 / (2 * v0**2 * sp.cos(al)**2), "trajectory (from the correct substitution)"),
        R_(90, 0, "derived", "- g T", v0 * sp.sin(al) - g * T, -v0 * sp.sin(al), "v_y at landing"),
        R_(94, 0, "derived", "v_x^2 + v_y^2", vx(t)**2 + vy(t)**2, v0**2 - 2 * g * Y, "energy: follows from v_x, v_y, y"),
    ]
    return dict(name="projectile.tex", params={v0: (1, 30), al: (0.1, 1.4), g: (9, 10), t: (0.1, 3)},
                world=world, rows=rows)


@document
def collision():
    m1, m2, v1, v2, e, v1p, v2p, dT, mu, J = S("m_1 m_2 v_1 v_2 e v_1p v_2p DeltaT mu J")
    m, M, u, V, g, h = S("m M u V g h")
    half = sp.Rational(1, 2)
    W = {
        v1p: (m1 * v1 + m2 * v2 - e * m2 * (v1 - v2)) / (m1 + m2),
        v2p: (m1 * v1 + m2 * v2 + e * m1 * (v1 - v2)) / (m1 + m2),
        dT: m1 * m2 * (1 - e**2) * (v1 - v2)**2 / (2 * (m1 + m2)),
        mu: m1 * m2 / (m1 + m2), J: -m1 * m2 * (1 + e) * (v1 - v2) / (m1 + m2),
        V: m * u / (m + M), h: m**2 * u**2 / (2 * g * (m + M)**2),
    }
    swap = dict(W); swap.update({e: 1, m2: m1})
    plastic = dict(W); plastic.update({e: 0})
    heavy = {m2: m1 / eps}
    rows = [
        R_(11, 0, "given", "(3.1)", m1 * v1 + m2 * v2, m1 * v1p + m2 * v2p, "momentum conservation, introduces v_2'", intro=[v2p]),
        R_(15, 0, "given", "(3.2)", e, (v2p - v1p) / (v1 - v2), "restitution, introduces v_1'", intro=[v1p]),
        R_(19, 0, "derived", "v_2' = v_1'", v2p, v1p + e * (v1 - v2), "(3.2) rearranged"),
        R_(23, 0, "derived", "(m_1 + m_2)", m1 * v1 + m2 * v2, (m1 + m2) * v1p + e * m2 * (v1 - v2), "substitution into (3.1)"),
        R_(27, 0, "derived", "(3.3)", v1p, W[v1p], "solve for v_1'"),
        R_(29, 0, "derived", "(3.4)", v2p, W[v2p], "back-substitute"),
        R_(33, 1, "derived", "v_1' = v_2", v1p, v2, "under e = 1, m_1 = m_2 stated inline", world=swap),
        R_(33, 2, "derived", "v_2' = v_1", v2p, v1, "under e = 1, m_1 = m_2 stated inline", world=swap),
        R_(37, 0, "approx", "v_1' \\approx", v1p, v2 - e * (v1 - v2), "m_2 >> m_1", regime=heavy),
        R_(39, 0, "approx", "v_2' \\approx", v2p, v2, "m_2 >> m_1", regime=heavy),
        R_(45, 0, "given", "\\Delta T = \\tfrac", dT, half * m1 * v1**2 + half * m2 * v2**2 - half * m1 * v1p**2 - half * m2 * v2p**2,
           "definition of the loss", intro=[dT]),
        R_(49, 0, "derived", "(3.5)", dT, W[dT], "substitute (3.3), (3.4)"),
        R_(53, 0, "given", "\\mu =", mu, m1 * m2 / (m1 + m2), "reduced mass, new symbol", intro=[mu]),
        R_(57, 0, "wrong", "\\Delta T = \\frac{m_1 m_2 (", dT, m1 * m2 * (v1 - v2)**2 / (m1 + m2),
           "dropped factor 1/2 (under e = 0 stated inline)", world=plastic),
        R_(61, 1, "given", "J = m_1", J, m1 * (v1p - v1), "impulse on cart 1, new symbol", intro=[J]),
        R_(61, 2, "derived", "J = m_1", m1 * (v1p - v1), -mu * (1 + e) * (v1 - v2), "substitute (3.3)"),
        R_(65, 0, "wrong", "m_2 (v_2' - v_2)", m2 * (v2p - v2), mu * (1 - e) * (v1 - v2), "sign slip: 1 + e"),
        R_(71, 0, "given", "m u =", m * u, (m + M) * V, "momentum through the impact, introduces V", intro=[V]),
        R_(73, 0, "derived", "V = \\frac", V, m * u / (m + M), "solve for V"),
        R_(77, 0, "wrong", "\\frac{\\tfrac12", (half * (m + M) * V**2) / (half * m * u**2), M / (m + M), "swapped: should be m/(m+M)"),
        R_(81, 0, "given", "g h$$", half * (m + M) * V**2, (m + M) * g * h, "energy in the swing, introduces h", intro=[h]),
        R_(83, 1, "derived", "h = \\frac{V^2}", h, V**2 / (2 * g), "solve for h"),
        R_(83, 2, "derived", "h = \\frac{V^2}", V**2 / (2 * g), m**2 * u**2 / (2 * g * (m + M)**2), "substitute V"),
        R_(87, 0, "derived", "u = \\frac", u, (m + M) / m * sp.sqrt(2 * g * h), "solve for u (positive root)"),
        R_(91, 0, "approx", "u \\approx", u, M / m * sp.sqrt(2 * g * h), "M >> m", regime={M: m / eps}),
    ]
    return dict(name="collision.md", world=W, rows=rows,
                params={m1: (0.5, 5), m2: (0.5, 5), v1: (2, 10), v2: (0.1, 1.5), e: (0.1, 0.95),
                        m: (0.005, 0.05), M: (1, 5), u: (100, 500), g: (9, 10)})


@document
def rocket():
    m0, m1, k, u, g, F, tb = S("m_0 m_1 k u g F_thrust t_b")
    tp = sp.Symbol("tp", positive=True)
    m, v, y = sp.symbols("m v y", cls=sp.Function)
    L = sp.log(m0 / (m0 - k * t))
    vexpr = u * L - g * t
    W = {m: m0 - k * t, v: vexpr, F: u * k, tb: (m0 - m1) / k,
         y: u * t - u * (m0 - k * t) / k * L - g * t**2 / 2}
    free = dict(W); free.update({g: 0})
    D = lambda f: sp.Derivative(f, t)
    rows = [
        R_(14, 0, "given", "m = m_0 - k t", m(t), m0 - k * t, "constant burn rate, introduces m(t)", intro=[m]),
        R_(18, 0, "derived", "= -k", D(m(t)), -k, "differentiate"),
        R_(23, 1, "given", "F_{\\text{thrust}} =", F, -u * D(m(t)), "thrust defined, new symbol", intro=[F]),
        R_(23, 2, "derived", "= u k", -u * D(m(t)), u * k, "dm/dt = -k"),
        R_(28, 0, "given", "F_{\\text{thrust}} - m g", m(t) * D(v(t)), F - m(t) * g, "Newton's law, introduces v(t)", intro=[v]),
        R_(34, 0, "wrong", "= -\\frac{k", D(L), -k / (m0 - k * t), "sign slip: derivative is +k/(m_0 - k t)"),
        R_(38, 0, "derived", "& = & \\frac{u k}", D(v(t)), u * k / (m0 - k * t) - g, "divide (eom) by m"),
        R_(39, 0, "derived", "\\int_0^t \\left(", v(t), sp.Integral(u * k / (m0 - k * tp) - g, (tp, 0, t)), "integrate with v(0) = 0 (inline)"),
        R_(40, 0, "derived", "u \\ln", sp.Integral(u * k / (m0 - k * tp) - g, (tp, 0, t)), vexpr, "the integral"),
        R_(48, 0, "given", "m_0 - k t_b = m_1", m0 - k * tb, m1, "burnout condition, introduces t_b", intro=[tb]),
        R_(52, 0, "derived", "t_b = \\frac", tb, (m0 - m1) / k, "solve"),
        R_(56, 0, "derived", "- g t_b", u * sp.log(m0 / (m0 - k * tb)) - g * tb, u * sp.log(m0 / m1) - g * (m0 - m1) / k, "substitute t_b"),
        R_(62, 0, "given", "y & = &", y(t), sp.Integral(v(tp), (tp, 0, t)), "height defined (y(0) = 0), introduces y", intro=[y]),
        R_(63, 0, "derived", "& = & u t", sp.Integral(v(tp), (tp, 0, t)), W[y], "integral of the log"),
        R_(68, 0, "wrong", "= u + u", D(y(t)), u + u * L - g * t, "product-rule slip: the u terms cancel"),
        R_(74, 0, "approx", "\\approx \\frac{k t}", L, k * t / m0, "first order, k t << m_0", regime={t: eps * t}),
        R_(78, 0, "approx", "v \\approx", v(t), (u * k / m0 - g) * t, "first order, k t << m_0", regime={t: eps * t}),
        R_(84, 0, "derived", "e^{v/u}", m0 / (m0 - k * t), sp.exp(v(t) / u), "invert (eq:v) with g = 0 (inline)", world=free),
        R_(88, 0, "wrong", "e^{u/v}", m0 - k * t, m0 * sp.exp(u / v(t)), "exponent inverted: should be e^{-v/u}", world=free),
    ]
    return dict(name="rocket.tex", world=W, rows=rows,
                params={m0: (500, 1000), m1: (100, 400), k: (10, 50), u: (2000, 3000), g: (9, 10), t: (0.1, 8)})


@document
def orbits():
    G, M, m, r, R, h, F, v, T, K, U, E, ve = S("G M m r R h F v T K U E v_esc")
    W = {F: G * M * m / r**2, v: sp.sqrt(G * M / r), T: 2 * sp.pi * sp.sqrt(r**3 / (G * M)),
         K: G * M * m / (2 * r), U: -G * M * m / r, E: -G * M * m / (2 * r), ve: sp.sqrt(2 * G * M / r),
         h: r - R}
    half = sp.Rational(1, 2)
    rows = [
        R_(14, 0, "given", "F = \\frac{G M m}", F, G * M * m / r**2, "gravitation, introduces F", intro=[F]),
        R_(15, 0, "given", "F = \\frac{m v^2}", F, m * v**2 / r, "centripetal force, introduces v", intro=[v]),
        R_(20, 0, "derived", "&= \\frac{m v^2}{r}", G * M * m / r**2, m * v**2 / r, "equate the two"),
        R_(21, 0, "derived", "v &= \\sqrt", v, sp.sqrt(G * M / r), "solve for v > 0"),
        R_(27, 0, "given", "T &= \\frac{2 \\pi r}", T, 2 * sp.pi * r / v, "period defined, new symbol", intro=[T]),
        R_(28, 0, "derived", "&= 2\\pi", 2 * sp.pi * r / v, 2 * sp.pi * sp.sqrt(r**3 / (G * M)), "substitute v"),
        R_(32, 0, "derived", "\\tag{K3}", T**2, 4 * sp.pi**2 / (G * M) * r**3, "square"),
        R_(37, 0, "wrong", "\\frac{T^2}{r^3}", T**2 / r**3, G * M / (4 * sp.pi**2), "ratio inverted: 4 pi^2/(G M)"),
        R_(42, 0, "derived", "r = \\left(", r, (G * M * T**2 / (4 * sp.pi**2))**sp.Rational(1, 3), "invert (K3)"),
        R_(47, 0, "derived", "2 \\sqrt{2}\\, T", 2 * sp.pi * sp.sqrt((2 * r)**3 / (G * M)), 2 * sp.sqrt(2) * T, "period at 2r"),
        R_(48, 0, "wrong", "\\frac{v}{2}", sp.sqrt(G * M / (2 * r)), v / 2, "should be v/sqrt(2)"),
        R_(52, 1, "derived", "\\frac{dT}{dr}", sp.Derivative(T, r), 3 * T / (2 * r), "differentiate (K3)"),
        R_(52, 2, "wrong", "\\frac{dT}{dr}", sp.Derivative(v, r), v / (2 * r), "sign slip: -v/(2r)"),
        R_(59, 1, "given", "K &=", K, half * m * v**2, "kinetic energy, new symbol", intro=[K]),
        R_(59, 2, "derived", "K &=", half * m * v**2, G * M * m / (2 * r), "substitute v"),
        R_(60, 0, "given", "U &=", U, -G * M * m / r, "potential energy, new symbol", intro=[U]),
        R_(64, 1, "given", "E = K + U", E, K + U, "total energy, new symbol", intro=[E]),
        R_(64, 2, "derived", "E = K + U", K + U, -G * M * m / (2 * r), "add"),
        R_(64, 3, "derived", "E = K + U", -G * M * m / (2 * r), -K, "compare with K"),
        R_(68, 0, "derived", "\\lim_{r", sp.Limit(E, r, sp.oo), 0, "limit r -> oo"),
        R_(73, 0, "given", "v_{\\mathrm{esc}}^2", half * m * ve**2 - G * M * m / r, 0, "zero energy, introduces v_esc", intro=[ve]),
        R_(77, 1, "derived", "v_{\\mathrm{esc}} =", ve, sp.sqrt(2 * G * M / r), "solve"),
        R_(77, 2, "derived", "v_{\\mathrm{esc}} =", sp.sqrt(2 * G * M / r), sp.sqrt(2) * v, "compare with v"),
        R_(83, 0, "given", "r = R + h", r, R + h, "height above the surface, introduces h", intro=[h]),
        R_(88, 0, "approx", "v \\approx", v, sp.sqrt(G * M / R) * (1 - h / (2 * R)), "first order in h/R", regime={r: R + eps * R}),
    ]
    return dict(name="orbits.tex", world=W, rows=rows,
                params={G: (0.5, 2), M: (1, 10), m: (0.1, 2), r: (1.5, 10), R: (0.5, 1.4)})


@document
def damped():
    m, k, b, A, ga, w0, wd, E, th, Td, de = S("m k b A gamma omega_0 omega_d E t_half T_d delta")
    x = sp.Function("x")
    X = x(t)
    Xd, Xdd = sp.Derivative(X, t), sp.Derivative(X, (t, 2))
    ex = sp.exp(-ga * t)
    c, s = sp.cos(wd * t), sp.sin(wd * t)
    half = sp.Rational(1, 2)
    W = {x: A * ex * c, ga: b / (2 * m), w0: sp.sqrt(k / m), wd: sp.sqrt(w0**2 - ga**2),
         E: half * m * Xd**2 + half * k * X**2, th: sp.log(2) / ga, Td: 2 * sp.pi / wd, de: ga * Td}
    rows = [
        R_(12, 0, "given", "m\\ddot{x}", m * Xdd, -k * X - b * Xd, "Newton's law, introduces x(t)", intro=[x]),
        R_(17, 1, "given", "\\gamma = ", ga, b / (2 * m), "definition, new symbol", intro=[ga]),
        R_(17, 2, "given", "\\omega_0^2 =", w0**2, k / m, "definition, new symbol", intro=[w0]),
        R_(21, 0, "derived", "\\ddot{x} + 2", Xdd + 2 * ga * Xd + w0**2 * X, 0, "divide by m"),
        R_(27, 0, "given", "\\omega_d =", wd, sp.sqrt(w0**2 - ga**2), "definition, new symbol", intro=[wd]),
        R_(31, 0, "given", "x = A", X, A * ex * c, "trial solution, introduces A", intro=[A]),
        R_(35, 0, "derived", "\\dot{x} &=", Xd, -A * ex * (ga * c + wd * s), "differentiate"),
        R_(36, 0, "derived", "\\ddot{x} &=", Xdd, A * ex * ((ga**2 - wd**2) * c + 2 * ga * wd * s), "differentiate again"),
        R_(42, 0, "derived", "\\omega_0^2 x", Xdd + 2 * ga * Xd + w0**2 * X, A * ex * (ga**2 - wd**2 - 2 * ga**2 + w0**2) * c, "substitute"),
        R_(44, 0, "derived", "- \\omega_d^2\\right)", A * ex * (ga**2 - wd**2 - 2 * ga**2 + w0**2) * c, A * ex * (w0**2 - ga**2 - wd**2) * c, "collect"),
        R_(45, 0, "derived", "&= 0", A * ex * (w0**2 - ga**2 - wd**2) * c, 0, "omega_d^2 = omega_0^2 - gamma^2"),
        R_(52, 0, "given", "E = \\half", E, half * m * Xd**2 + half * k * X**2, "energy defined, new symbol", intro=[E]),
        R_(56, 1, "derived", "\\dot{E} =", sp.Derivative(E, t), m * Xd * Xdd + k * X * Xd, "differentiate E"),
        R_(56, 2, "wrong", "\\dot{E} =", m * Xd * Xdd + k * X * Xd, b * Xd**2, "sign slip: -b xdot^2"),
        R_(62, 0, "given", "t_{1/2}} = \\half", sp.exp(-ga * th), half, "half-life condition, introduces t_1/2", intro=[th]),
        R_(66, 1, "derived", "t_{1/2} =", th, sp.log(2) / ga, "take logs"),
        R_(66, 2, "wrong", "t_{1/2} =", sp.log(2) / ga, m * sp.log(2) / (2 * b), "gamma inverted: 2 m ln2 / b"),
        R_(71, 0, "derived", "\\e^{\\gamma T_d}", A * ex / (A * sp.exp(-ga * (t + Td))), sp.exp(ga * Td), "algebra"),
        R_(75, 0, "given", "\\delta &=", de, ga * Td, "decrement defined, new symbol", intro=[de]),
        R_(76, 0, "derived", "\\frac{2\\pi\\gamma}", ga * Td, 2 * sp.pi * ga / wd, "T_d = 2 pi/omega_d (inline)"),
        R_(77, 0, "wrong", "\\omega_d^2}", 2 * sp.pi * ga / wd, sp.pi * b / (m * wd**2), "wrong power of omega_d"),
        R_(82, 0, "approx", "\\omega_d \\approx", wd, w0 * (1 - ga**2 / (2 * w0**2)), "light damping", regime={b: eps * b}),
    ]
    return dict(name="damped.tex", world=W, rows=rows, known=["T_d"],
                params={m: (1, 2), k: (10, 20), b: (0.1, 2), A: (0.1, 1), t: (0.1, 5)})


@document
def pendulum():
    m, g, L, th, th0, thd, thdd, vm, T, w, tau = S("m g L theta theta_0 thetadot thetaddot v_max T omega tau")
    half = sp.Rational(1, 2)
    W = {thdd: -g / L * sp.sin(th), thd: sp.sqrt(2 * g / L * (sp.cos(th) - sp.cos(th0))),
         vm: sp.sqrt(2 * g * L * (1 - sp.cos(th0))), T: m * g * (3 - 2 * sp.cos(th0)),
         w: sp.sqrt(g / L), tau: 2 * sp.pi * sp.sqrt(L / g)}
    rows = [
        R_(10, 0, "given", "(5.1)", m * L * thdd, -m * g * sp.sin(th), "Newton along the arc, introduces theta''", intro=[thdd]),
        R_(14, 0, "derived", "\\ddot\\theta = -", thdd, -g / L * sp.sin(th), "divide by m L"),
        R_(20, 0, "given", "(5.2)", half * m * L**2 * thd**2 - m * g * L * sp.cos(th), -m * g * L * sp.cos(th0),
           "energy conservation, introduces theta'", intro=[thd]),
        R_(24, 0, "wrong", "\\dot\\theta^2", thd**2, g / L * (sp.cos(th) - sp.cos(th0)), "dropped factor 2"),
        R_(28, 1, "given", "v_{\\max} =", vm, sp.sqrt(2 * g * L * (1 - sp.cos(th0))), "speed at the bottom, new symbol", intro=[vm]),
        R_(28, 2, "derived", "v_{\\max} =", sp.sqrt(2 * g * L * (1 - sp.cos(th0))), 2 * sp.sqrt(g * L) * sp.sin(th0 / 2), "half-angle"),
        R_(32, 0, "derived", "\\sin^2", sp.sin(th0 / 2)**2, (1 - sp.cos(th0)) / 2, "identity"),
        R_(36, 1, "given", "(5.3)", T, m * g + m * vm**2 / L, "tension at the bottom, new symbol", intro=[T]),
        R_(36, 2, "derived", "(5.3)", m * g + m * vm**2 / L, m * g * (3 - 2 * sp.cos(th0)), "substitute v_max"),
        R_(42, 0, "derived", "\\lim_{\\theta", sp.Limit(sp.sin(th) / th, th, 0), 1, "standard limit"),
        R_(46, 0, "approx", "\\sin\\theta \\approx", sp.sin(th), th, "first order in theta", regime={th: eps * th}),
        R_(50, 0, "approx", "(5.4)", thdd, -g / L * th, "first order in theta", regime={th: eps * th}),
        R_(54, 0, "given", "\\omega =", w, sp.sqrt(g / L), "definition, new symbol", intro=[w]),
        R_(56, 1, "given", "(5.5)", tau, 2 * sp.pi / w, "period defined, new symbol", intro=[tau]),
        R_(56, 2, "derived", "(5.5)", 2 * sp.pi / w, 2 * sp.pi * sp.sqrt(L / g), "substitute omega"),
        R_(60, 0, "wrong", "= 4\\tau", 2 * sp.pi * sp.sqrt(4 * L / g), 4 * tau, "sqrt 4 = 2: should be 2 tau"),
        R_(64, 0, "wrong", "L = \\frac{g\\,\\tau}", L, g * tau / (4 * sp.pi**2), "tau not squared (units)"),
        R_(68, 0, "approx", "v_{\\max} \\approx", vm, th0 * sp.sqrt(g * L), "small amplitude", regime={th0: eps * th0}),
        R_(70, 0, "approx", "T - m g \\approx", T - m * g, m * g * th0**2, "small amplitude", regime={th0: eps * th0}),
    ]
    return dict(name="pendulum.md", world=W, rows=rows,
                params={m: (0.1, 2), g: (9, 10), L: (0.2, 3), th: (0.05, 0.3), th0: (0.4, 1.2)})


@document
def rolling():
    m, r, g, h, be, I, w, v, a, al, f, N, s, t1 = S("m r g h beta I omega v a alpha f N s t_1")
    half = sp.Rational(1, 2)
    W = {I: sp.Rational(2, 5) * m * r**2, v: sp.sqrt(sp.Rational(10, 7) * g * h), w: v / r,
         a: sp.Rational(5, 7) * g * sp.sin(be), al: a / r, f: sp.Rational(2, 7) * m * g * sp.sin(be),
         N: m * g * sp.cos(be), s: h / sp.sin(be), t1: sp.sqrt(2 * s / a)}
    W30 = dict(W); W30[be] = sp.pi / 6
    deg = sp.pi / 180
    rows = [
        R_(11, 0, "given", "I = \\frac{2}{5}", I, sp.Rational(2, 5) * m * r**2, "solid ball, new symbol", intro=[I]),
        R_(15, 0, "given", "v = \\omega r", v, w * r, "no-slip constraint, introduces omega", intro=[w]),
        R_(19, 0, "given", "\\tfrac12 I \\omega^2$$", m * g * h, half * m * v**2 + half * I * w**2, "energy conservation, fixes v", intro=[v]),
        R_(23, 1, "derived", "\\tfrac12 \\cdot", m * g * h, half * m * v**2 + half * sp.Rational(2, 5) * m * r**2 * v**2 / r**2, "substitute I and omega"),
        R_(23, 2, "derived", "\\tfrac12 \\cdot", half * m * v**2 + half * sp.Rational(2, 5) * m * r**2 * v**2 / r**2, sp.Rational(7, 10) * m * v**2, "collect"),
        R_(27, 0, "derived", "v = \\sqrt{10", v, sp.sqrt(10 * g * h / 7), "solve for v"),
        R_(31, 0, "derived", "\\sqrt{5/7}", sp.sqrt((10 * g * h / 7) / (2 * g * h)), sp.sqrt(sp.Rational(5, 7)), "algebra"),
        R_(35, 0, "wrong", "{\\tfrac12 m v^2}", (half * I * w**2) / (half * m * v**2), sp.Rational(2, 7), "ratio is 2/5 (2/7 is of m g h)"),
        R_(39, 0, "derived", "{m g h}", (half * I * w**2) / (m * g * h), sp.Rational(2, 7), "energy equation"),
        R_(47, 0, "given", "m a &=", m * a, m * g * sp.sin(be) - f, "Newton along the slope, introduces f", intro=[f]),
        R_(48, 0, "given", "f r &=", f * r, I * al, "torque equation, introduces alpha", intro=[al]),
        R_(49, 0, "given", "a &= \\alpha r", a, al * r, "no-slip for accelerations, closes the system", intro=[a]),
        R_(55, 1, "derived", "1 + I/(m r^2)", a, g * sp.sin(be) / (1 + I / (m * r**2)), "eliminate f, alpha"),
        R_(55, 2, "derived", "1 + I/(m r^2)", g * sp.sin(be) / (1 + I / (m * r**2)), sp.Rational(5, 7) * g * sp.sin(be), "substitute I"),
        R_(59, 1, "derived", "f = m g", f, m * g * sp.sin(be) - m * a, "from the first force row"),
        R_(59, 2, "wrong", "f = m g", m * g * sp.sin(be) - m * a, sp.Rational(2, 5) * m * g * sp.sin(be), "should be 2/7"),
        R_(63, 0, "derived", "\\frac{f}{N} = \\frac{2}{7}\\tan\\beta", f / N, sp.Rational(2, 7) * sp.tan(be), "N = m g cos beta (inline)"),
        R_(67, 0, "derived", "2 a s", 2 * a * s, sp.Rational(10, 7) * g * h, "s = h/sin beta (inline)"),
        R_(71, 0, "given", "s = \\tfrac12 a t_1^2", s, half * a * t1**2, "uniform acceleration, introduces t_1", intro=[t1]),
        R_(75, 1, "derived", "t_1 = \\sqrt{2 s/a}", t1, sp.sqrt(2 * s / a), "solve"),
        R_(75, 2, "derived", "t_1 = \\sqrt{2 s/a}", sp.sqrt(2 * s / a), sp.sqrt(14 * h / (5 * g * sp.sin(be)**2)), "substitute s and a"),
        R_(79, 1, "derived", "\\sin 30^\\circ", a, sp.Rational(5, 7) * g * sp.sin(30 * deg), "beta = 30 degrees (inline)", world=W30),
        R_(79, 2, "derived", "\\sin 30^\\circ", sp.Rational(5, 7) * g * sp.sin(30 * deg), sp.Rational(5, 14) * g, "sin 30 = 1/2"),
        R_(81, 1, "derived", "\\tan 30^\\circ", f / N, sp.Rational(2, 7) * sp.tan(30 * deg), "beta = 30 degrees (inline)", world=W30),
        R_(81, 2, "wrong", "\\tan 30^\\circ", sp.Rational(2, 7) * sp.tan(30 * deg), 2 * sp.sqrt(3) / 7, "tan 30 = 1/sqrt 3, not sqrt 3"),
    ]
    return dict(name="rolling.md", world=W, rows=rows, known=["N", "s"],
                params={m: (0.1, 3), r: (0.05, 0.5), g: (9, 10), h: (0.5, 5), be: (0.1, 1.2)})


@document
def circuit():
    Ec, R, C, tau, th, T = S("E R C tau t_half T")
    q, I = sp.symbols("q I", cls=sp.Function)
    tp = sp.Symbol("tp", positive=True)
    ex = sp.exp(-t / tau)
    half = sp.Rational(1, 2)
    W = {q: C * Ec * (1 - ex), I: Ec / R * ex, tau: R * C, th: tau * sp.log(2)}
    D = lambda f: sp.Derivative(f, t)
    rows = [
        R_(9, 0, "given", "(2.1)", I(t), D(q(t)), "current defined, introduces I", intro=[I]),
        R_(13, 0, "given", "(2.2)", Ec, R * I(t) + q(t) / C, "Kirchhoff, introduces q", intro=[q]),
        R_(17, 0, "derived", "- \\frac{q}{R C}", D(q(t)), Ec / R - q(t) / (R * C), "(2.1) into (2.2)"),
        R_(21, 0, "given", "\\tau = R C", tau, R * C, "time constant, new symbol", intro=[tau]),
        R_(25, 0, "derived", "(2.3)", q(t), C * Ec * (1 - ex), "solve the ODE with q(0) = 0 (inline)"),
        R_(29, 0, "derived", "I = \\frac", I(t), Ec / R * ex, "differentiate (2.3)"),
        R_(31, 0, "wrong", "\\frac{dI}{dt}", D(I(t)), -Ec / R * ex, "missing 1/tau (units)"),
        R_(35, 0, "approx", "0.632", 1 - sp.exp(-1), sp.Rational(632, 1000), "3 digits", tol=1e-3),
        R_(39, 0, "derived", "\\lim_{t", sp.Limit(q(t), t, sp.oo), C * Ec, "limit of (2.3)"),
        R_(43, 0, "approx", "q \\approx", q(t), Ec * t / R, "first order in t/tau", regime={t: eps * t}),
        R_(47, 0, "given", "e^{-t_{1/2}", sp.exp(-th / tau), half, "half-time condition, introduces t_1/2", intro=[th]),
        R_(51, 0, "wrong", "\\tau / \\ln 2", th, tau / sp.log(2), "should be tau ln 2"),
        R_(57, 0, "derived", "I^2 R", sp.Integral(I(tp)**2 * R, (tp, 0, T)), Ec**2 / R * sp.Integral(sp.exp(-2 * tp / tau), (tp, 0, T)), "substitute I"),
        R_(58, 0, "derived", "{2R}", Ec**2 / R * sp.Integral(sp.exp(-2 * tp / tau), (tp, 0, T)), Ec**2 * tau / (2 * R) * (1 - sp.exp(-2 * T / tau)), "integrate"),
        R_(59, 0, "wrong", "\\tfrac12 C", Ec**2 * tau / (2 * R) * (1 - sp.exp(-2 * T / tau)), half * C * Ec**2 * (1 - sp.exp(-T / tau)), "exponent should stay -2T/tau"),
        R_(65, 0, "derived", "\\mathcal{E} I\\,dt", sp.Integral(Ec * I(tp), (tp, 0, T)), C * Ec**2 * (1 - sp.exp(-T / tau)), "integrate"),
        R_(69, 0, "derived", "{2C}", (C * Ec)**2 / (2 * C), half * C * Ec**2, "algebra"),
    ]
    return dict(name="circuit.md", world=W, rows=rows,
                params={Ec: (1, 12), R: (1, 100), C: (0.01, 1), t: (0.1, 5), T: (0.1, 5)})


@document
def adversarial_macros():
    k, m, g, x0, mu, x, F, U, Ws, v1, D = S("k m g x_0 mu x F U W_s v_1 D")
    xs = sp.Symbol("xs", positive=True)
    half = sp.Rational(1, 2)
    v1v = sp.sqrt(k * x0**2 / m - 2 * mu * g * x0)
    W = {F: -k * x, U: half * k * x**2, Ws: half * k * x0**2, v1: v1v, D: k * x0**2 / (2 * mu * m * g)}
    rows = [
        R_(19, 0, "given", "F=-k", F, -k * x, "Hooke's law, new symbol", intro=[F]),
        R_(23, 0, "given", "U = \\half", U, half * k * x**2, "stored energy, new symbol", intro=[U]),
        R_(27, 1, "derived", "-\\ddx{U}", -sp.Derivative(U, x), -k * x, "differentiate (macro \\ddx)"),
        R_(27, 2, "derived", "-\\ddx{U}", -k * x, F, "Hooke's law"),
        R_(33, 1, "given", "\\Ws \\;=\\;", Ws, sp.Integral(k * xs, (xs, 0, x0)), "spring work defined, new symbol", intro=[Ws]),
        R_(33, 2, "derived", "\\Ws \\;=\\;", sp.Integral(k * xs, (xs, 0, x0)), half * k * x0**2 - half * k * 0**2, "antiderivative, \\left.\\right| bar"),
        R_(33, 3, "derived", "\\Ws \\;=\\;", half * k * x0**2 - half * k * 0**2, half * k * x0**2, "evaluate"),
        R_(40, 0, "derived", "\\left[", half * k * x0**2 - half * k * 0**2, half * k * x0**2, "bracket evaluation"),
        R_(46, 0, "given", "\\half m v_1^2 &", half * m * v1**2, Ws - mu * m * g * x0, "work-energy theorem, introduces v_1", intro=[v1]),
        R_(48, 0, "derived", "& = \\half k x_0^2", Ws - mu * m * g * x0, half * k * x0**2 - mu * m * g * x0, "substitute (eq:Ws)"),
        R_(54, 0, "derived", "v_1=\\sqrt", v1, v1v, "solve for v_1 > 0"),
        R_(58, 0, "wrong", "\\displaystyle", v1**2, k * x0**2 / m - mu * g * x0, "dropped factor 2 on the friction term"),
        R_(62, 0, "derived", "\\lim_{\\mu", sp.Limit(v1, mu, 0), x0 * sp.sqrt(k / m), "limit mu -> 0"),
        R_(66, 0, "approx", "v_1 \\approx", v1, x0 * sp.sqrt(k / m) * (1 - mu * m * g / (k * x0)), "first order in mu", regime={mu: eps * mu}),
        R_(71, 0, "given", "\\mu m g D", half * k * x0**2, mu * m * g * D, "energy balance, introduces D", intro=[D]),
        R_(72, 0, "derived", "D &=", D, k * x0**2 / (2 * mu * m * g), "solve"),
        R_(76, 0, "wrong", "D - x_0", D - x0, v1**2 / (2 * mu * m * g), "extra m: v_1^2/(2 mu g) (units)"),
    ]
    return dict(name="adversarial_macros.tex", world=W, rows=rows,
                params={k: (300, 1000), m: (0.5, 2), g: (9, 10), x0: (0.1, 0.5), mu: (0.05, 0.3), x: (0.01, 0.5)})


@document
def adversarial_ambiguous():
    g, h, e, v, vp, hp, tp_, hpp, mu, u0, ts, d, tau, d2 = S("g h e v v' h' t' h'' mu u_0 t_s d tau d_2")
    w, u, u2 = sp.symbols("w u u_2", cls=sp.Function)
    s = sp.Symbol("s", positive=True)
    half = sp.Rational(1, 2)
    W = {v: sp.sqrt(2 * g * h), vp: e * v, hp: e**2 * h, w: vp - g * t, tp_: 2 * vp / g, hpp: e**4 * h,
         u: u0 - mu * g * t, ts: u0 / (mu * g), d: u0**2 / (2 * mu * g),
         u2: u0 * sp.exp(-t / tau), d2: u0 * tau}
    W8 = dict(W); W8[e] = sp.Rational(4, 5)
    D = lambda f: sp.Derivative(f, t)
    rows = [
        R_(9, 0, "given", "v = \\sqrt", v, sp.sqrt(2 * g * h), "free fall, new symbol", intro=[v]),
        R_(13, 0, "given", "v' = e", vp, e * v, "restitution (e is a coefficient), introduces v'", intro=[vp, e]),
        R_(17, 1, "given", "h' = \\frac", hp, vp**2 / (2 * g), "rise height, new symbol h'", intro=[hp]),
        R_(17, 2, "derived", "h' = \\frac", vp**2 / (2 * g), e**2 * h, "e^2 is restitution squared"),
        R_(21, 0, "given", "\\frac{dw}{dt}", D(w(t)), -g, "gravity on the rising ball, introduces w", intro=[w]),
        R_(25, 0, "given", "t' = ", tp_, 2 * vp / g, "time in the air, new symbol t' (not a derivative)", intro=[tp_]),
        R_(29, 1, "given", "h'' = e^2", hpp, e**2 * hp, "second rise, new symbol h'' (not a 2nd derivative)", intro=[hpp]),
        R_(29, 2, "derived", "h'' = e^2", e**2 * hp, e**4 * h, "substitute h'"),
        R_(33, 0, "derived", "2 \\ln e", sp.log(hp / h), 2 * sp.log(e), "ln of restitution, not 1"),
        R_(37, 0, "derived", "0.4096", e**4 * h, sp.Rational(4096, 10000) * h, "e = 0.8 (inline), restitution", world=W8),
        R_(41, 0, "wrong", "0.64", 1 - e**2, sp.Rational(64, 100), "1 - 0.64 = 0.36", world=W8),
        R_(49, 0, "given", "\\frac{du}{dt}", D(u(t)), -mu * g, "friction, introduces u", intro=[u]),
        R_(53, 0, "derived", "u = u_0", u(t), u0 - mu * g * t, "integrate with u(0) = u_0 (inline)"),
        R_(57, 0, "given", "t_s = 0", u0 - mu * g * ts, 0, "stopping condition, introduces t_s", intro=[ts]),
        R_(61, 1, "given", "d = u_0 t_s", d, u0 * ts - half * mu * g * ts**2, "distance d (not a differential), new symbol", intro=[d]),
        R_(61, 2, "derived", "d = u_0 t_s", u0 * ts - half * mu * g * ts**2, u0**2 / (2 * mu * g), "substitute t_s"),
        R_(65, 0, "derived", "\\frac{d}{t_s}", d / ts, half * u0, "d over t_s (a quotient, not d/dt)"),
        R_(69, 0, "wrong", "\\mu g\\, d", mu * g * d, u0**2, "dropped factor 2"),
        R_(75, 0, "given", "u_2 = u_0", u2(t), u0 * sp.exp(-t / tau), "exponential decay (Euler's e), introduces u_2, tau", intro=[u2, tau]),
        R_(79, 0, "derived", "\\frac{du_2}{dt}", D(u2(t)), -u2(t) / tau, "differentiate"),
        R_(83, 0, "derived", "\\left. u_2", u2(tau), u0 / sp.E, "e here is Euler's number"),
        R_(87, 0, "given", "d_2 = \\int", d2, sp.Integral(u2(s), (s, 0, sp.oo)), "distance defined, new symbol", intro=[d2]),
        R_(89, 0, "wrong", "= u_0/\\tau", sp.Integral(u0 * sp.exp(-s / tau), (s, 0, sp.oo)), u0 / tau, "should be u_0 tau (units)"),
        R_(91, 0, "derived", "d_2 = u_0 \\tau", d2, u0 * tau, "the integral"),
    ]
    return dict(name="adversarial_ambiguous.md", world=W, rows=rows,
                params={g: (9, 10), h: (0.5, 3), e: (0.3, 0.95), mu: (0.02, 0.3), u0: (1, 10), tau: (0.5, 5), t: (0.05, 0.3)})


@document
def work_energy():
    F0, L, m, g, x, xh, WL, v, P, F, Wt = S("F_0 L m g x x_h W_L v P F W")
    v0, th, mu, s, v1, Q, u, y1, t1 = S("v_0 theta mu s v_1 Q u y_1 t_1")
    Fi, dxi = sp.IndexedBase("Fpiece"), sp.IndexedBase("Delta_x")
    i = sp.Symbol("i", integer=True)
    xs = sp.Symbol("xs", positive=True)
    half = sp.Rational(1, 2)
    sq = sp.sqrt(u**2 - 2 * g * y1)
    W = {Wt: sum(Fi[j] * dxi[j] for j in (1, 2, 3)), F: F0 * xs**2 / L**2, WL: F0 * L / 3, xh: L / 2**sp.Rational(1, 3),
         v: sp.sqrt(2 * F0 * x**3 / (3 * m * L**2)), P: F0 * x**2 / L**2 * sp.sqrt(2 * F0 * x**3 / (3 * m * L**2)),
         s: v0**2 / (2 * g * (sp.sin(th) + mu * sp.cos(th))),
         v1: sp.sqrt(2 * g * s * (sp.sin(th) - mu * sp.cos(th))), Q: 2 * mu * m * g * s * sp.cos(th),
         t1: (u - sq) / g}
    Wx = dict(W); Wx[F] = F0 * x**2 / L**2   # the force at the particle's position x
    Wtop = dict(W); Wtop[y1] = u**2 / (2 * g)
    idx = {Fi[j]: (1, 10) for j in (1, 2, 3)}
    idx.update({dxi[j]: (0.1, 3) for j in (1, 2, 3)})
    rows = [
        R_(17, 1, "given", "W = \\sum", Wt, sp.Sum(Fi[i] * dxi[i], (i, 1, 3)), "work of the pieces, new symbol", intro=[Wt]),
        R_(17, 2, "derived", "W = \\sum", sp.Sum(Fi[i] * dxi[i], (i, 1, 3)), Fi[1] * dxi[1] + Fi[2] * dxi[2] + Fi[3] * dxi[3], "finite sum written out"),
        R_(25, 0, "given", "F = F_0", F, F0 * x**2 / L**2, "the force law, new symbol", intro=[F], world=Wx),
        R_(29, 1, "given", "W_L = \\int", WL, sp.Integral(F, (xs, 0, L)), "work over L, new symbol", intro=[WL]),
        R_(29, 2, "derived", "W_L = \\int", sp.Integral(F, (xs, 0, L)), F0 * L / 3, "integrate x^2"),
        R_(33, 0, "given", "x_h^3", F0 * xh**3 / (3 * L**2), F0 * L / 6, "half-work point, introduces x_h", intro=[xh]),
        R_(37, 1, "derived", "\\sqrt[3]{2}", xh, L / 2**sp.Rational(1, 3), "real cube root"),
        R_(37, 2, "approx", "\\sqrt[3]{2}", L / 2**sp.Rational(1, 3), sp.Rational(794, 1000) * L, "3 digits", tol=1e-3),
        R_(41, 0, "wrong", "\\frac{W_L}{4}", sp.Integral(F, (xs, 0, L / 2)), WL / 4, "x^3 law: it is W_L/8"),
        R_(45, 0, "given", "m v^2 = \\frac{F_0 x^3}", half * m * v**2, F0 * x**3 / (3 * L**2), "work-energy theorem, introduces v", intro=[v]),
        R_(49, 0, "derived", "v = x \\sqrt", v, x * sp.sqrt(2 * F0 * x / (3 * m * L**2)), "solve for v > 0"),
        R_(53, 1, "given", "P = F v", P, F * v, "power defined, new symbol", intro=[P], world=Wx),
        R_(53, 2, "wrong", "P = F v", F * v, F0 * x**2 / L**2 * sp.sqrt(2 * F0 * x / (3 * m * L**2)), "lost the factor x of v", world=Wx),
        R_(62, 0, "given", "m g s \\sin\\theta \\\\", half * m * v0**2, m * g * s * sp.sin(th) + mu * m * g * s * sp.cos(th),
           "energy balance on the way up (multline: one row), introduces s", intro=[s]),
        R_(67, 0, "derived", "s = \\frac{v_0^2}", s, v0**2 / (2 * g * (sp.sin(th) + mu * sp.cos(th))), "solve for s"),
        R_(72, 0, "given", "m v_1^2 = m g s", half * m * v1**2, m * g * s * sp.sin(th) - mu * m * g * s * sp.cos(th), "energy on the way down, introduces v_1", intro=[v1]),
        R_(76, 0, "wrong", "\\frac{v_1}{v_0}", v1 / v0, (sp.sin(th) - mu * sp.cos(th)) / (sp.sin(th) + mu * sp.cos(th)), "that is (v_1/v_0)^2: square root missing"),
        R_(81, 0, "given", "Q = 2 \\times", Q, 2 * mu * m * g * s * sp.cos(th), "heat defined, new symbol", intro=[Q]),
        R_(85, 0, "derived", "= Q", half * m * v0**2 - half * m * v1**2, Q, "difference of the two energy rows"),
        R_(92, 0, "given", "y_1 = u t_1", y1, u * t1 - half * g * t1**2, "height condition, introduces t_1", intro=[t1]),
        R_(96, 0, "derived", "\\pm", (t1 - (u + sq) / g) * (t1 - (u - sq) / g), 0, "t_1 is one of the two roots (the \\pm row)"),
        R_(101, 0, "derived", "\\left( u - g t_1", u**2 - 2 * g * y1, (u - g * t1)**2, "from the quadratic"),
        R_(106, 1, "derived", "t_1 = \\frac{u}{g}", t1, u / g, "double root when u^2 = 2 g y_1 (inline)", world=Wtop),
        R_(106, 2, "derived", "t_1 = \\frac{u}{g}", u / g, sp.sqrt(2 * y1 / g), "u^2 = 2 g y_1 (inline)", world=Wtop),
    ]
    params = {F0: (1, 10), L: (0.5, 3), m: (0.5, 3), g: (9, 10), x: (0.1, 3), v0: (1, 10), th: (0.5, 1.2),
              mu: (0.05, 0.4), u: (10, 20), y1: (0.5, 4)}
    params.update(idx)
    return dict(name="work_energy.tex", world=W, rows=rows, params=params,
                known=["Fpiece", "Delta_x", "i", "Fpiece[i]", "Delta_x[i]"] + [str(k) for k in idx])



# ================================================================ main

def main():
    rng = random.Random(20261127)
    only = sys.argv[1:]
    bad = 0
    print(f"{'document':32s} {'rows':>5s} {'rels':>5s} {'derived':>8s} {'given':>6s} {'wrong':>6s} {'approx':>7s}  status")
    tot = {l: 0 for l in LABELS}
    trows = 0
    for fn in DOCS:
        doc = fn()
        if only and doc["name"] not in only:
            continue
        errors, nrows, counts = check_doc(doc, rng)
        trows += nrows
        for l in LABELS:
            tot[l] += counts[l]
        status = "ok" if not errors else f"{len(errors)} MISMATCH"
        print(f"{doc['name']:32s} {nrows:5d} {sum(counts.values()):5d} {counts['derived']:8d} {counts['given']:6d} "
              f"{counts['wrong']:6d} {counts['approx']:7d}  {status}")
        for e in errors:
            print("   ", e)
        bad += len(errors)
    print(f"{'total':32s} {trows:5d} {sum(tot.values()):5d} {tot['derived']:8d} {tot['given']:6d} "
          f"{tot['wrong']:6d} {tot['approx']:7d}  {'ok' if not bad else str(bad) + ' MISMATCH'}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
