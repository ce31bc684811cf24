"""Minimal reader of derivation files (docs/format.md) for the peer scripts: the formula of a
labelled step `LABEL: y = ... = expr` (last side of the chain) as a SymPy expression, and each
symbol's declared domain.  Formulas are loaded by label from derivations/handout9, never typed
again by hand, so SymPy evaluates exactly what derivcheck evaluates."""
import re

import sympy as sp

_DOMAIN = re.compile(r"^symbol\s+(.+?)\s*:\s*(positive|nonnegative|negative|real|in\s*[\[(][^\])]*[\])])")


def _continued_lines(text):
    """Statements with their indented continuation lines joined (comments stripped)."""
    out = []
    for raw in text.splitlines():
        line = raw.split("#", 1)[0].rstrip()
        if not line.strip():
            continue
        if raw[:1] in (" ", "\t") and out and not line.strip().startswith(("by ", "note ", "erratum ", "stable ")):
            out[-1] += " " + line.strip()
        elif raw[:1] in (" ", "\t"):
            continue
        else:
            out.append(line.strip())
    return out


def symbol_domains(path):
    """name -> (kind, lo, hi) with kind in positive/nonnegative/negative/real/interval."""
    doms = {}
    for st in _continued_lines(open(path).read()):
        m = _DOMAIN.match(st)
        if not m:
            continue
        names = [n.strip() for n in m.group(1).split(",")]
        d = m.group(2)
        if d.startswith("in"):
            body = d[d.index(next(c for c in d if c in "[(")) + 1:-1]
            lo, hi = (float(sp.sympify(x.strip())) for x in body.split(","))
            dom = ("interval", lo, hi)
        else:
            dom = (d, None, None)
        for n in names:
            doms[n] = dom
    return doms


def formula(path, label):
    """(target name, sympy expr, [input symbols in declaration order])."""
    doms = symbol_domains(path)
    for st in _continued_lines(open(path).read()):
        m = re.match(r"^(?:\([^)]*\)\s*)?" + re.escape(label) + r"\s*:\s*(.*)$", st)
        if not m:
            continue
        sides = [s.strip() for s in m.group(1).split("=")]
        if len(sides) < 2:
            raise ValueError(f"{path}:{label} is not an equation")
        syms = {n: sp.Symbol(n, real=True) for n in doms}
        expr = sp.sympify(sides[-1].replace("^", "**"), locals=syms)
        inputs = [syms[n] for n in doms if syms[n] in expr.free_symbols]
        return sides[0], expr, inputs
    raise KeyError(f"{path}: no step labelled {label}")
