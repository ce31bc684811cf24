#!/usr/bin/python3
"""Build published.jsonl from claims_src.py and check each expectation independently
(SymPy 1.11 + mpmath). Prints any claim whose independent check disagrees with 'expected'."""
import json, sys, signal, random
sys.path.insert(0, __import__('os').path.dirname(__import__('os').path.abspath(__file__)))
import claims_src as C
import sympy as sp, mpmath as mp

def to_sympy(s):
    s = s.replace('^', '**')
    loc = {n: sp.Symbol(n) for n in 'x y z a b c h m n r t w k M C1 C2 dx'.split()}
    loc.update(dict(ln=sp.log, log=sp.log, abs=sp.Abs, exp=sp.exp, sqrt=sp.sqrt, pi=sp.pi, oo=sp.oo, asin=sp.asin, acos=sp.acos, atan=sp.atan))
    return sp.sympify(s, locals=loc, rational=True)

def sample(assume, names, rnd):
    vals = {}
    for n in names:
        dom = (assume or {}).get(n, 'real')
        if dom == 'positive' or dom == 'nonnegative': v = rnd.uniform(0.3, 2.5)
        elif dom == 'negative': v = -rnd.uniform(0.3, 2.5)
        elif dom.startswith('in'):
            lo, hi = [float(to_sympy(p.strip())) for p in dom[3:].strip()[1:-1].split(',')]
            v = rnd.uniform(lo + 0.05*(hi-lo), hi - 0.05*(hi-lo))
        else: v = rnd.uniform(-2, 2)
        vals[n] = mp.mpf(v)
    return vals

class TO(Exception): pass
def _h(*a): raise TO()
signal.signal(signal.SIGALRM, _h)

def numval(e, vals):
    f = sp.lambdify(list(sp.Symbol(n) for n in vals), e, modules='mpmath')
    return f(*vals.values())

def check_limit(d, rnd):
    var = sp.Symbol(d['var']); f = to_sympy(d['lhs']); p = d['point']; rhs = d['rhs']
    params = sorted({str(s) for s in f.free_symbols} - {d['var']})
    dirs = {'+': ['+'], '-': ['-'], '+-': ['+', '-'], None: ['+', '-']}[d.get('dir')]
    if p not in ('oo', '-oo') and (d.get('assumptions') or {}).get(d['var']) == 'positive' and d.get('dir') is None: dirs = ['+']
    results = []
    mp.mp.dps = 60
    for trial in range(2):
        vals = sample(d.get('assumptions'), params, rnd)
        g = f.subs({sp.Symbol(k): sp.Float(v, 30) for k, v in vals.items()})
        for dr in dirs:
            seq = []
            for k in (6, 10, 14):
                if p == 'oo': X = mp.mpf(10)**k
                elif p == '-oo': X = -mp.mpf(10)**k
                else:
                    P = mp.mpf(sp.N(to_sympy(p).subs({sp.Symbol(kk): sp.Float(v, 30) for kk, v in vals.items()}), 50))
                    X = P + (mp.mpf(10)**-k if dr == '+' else -mp.mpf(10)**-k)
                try:
                    val = sp.N(g.subs(var, sp.Float(X, 60)), 40)
                    seq.append(complex(val))
                except Exception:
                    seq.append(None)
            results.append((dr, seq, vals))
    # decide
    def close(a, b): return a is not None and abs(a - b) <= 1e-3 * max(1, abs(b))
    verdicts = []
    for dr, seq, vals in results:
        s = [v for v in seq if v is not None]
        if not s: verdicts.append('unknown'); continue
        last = s[-1]
        if abs(last.imag) > 1e-20 * max(1, abs(last)): verdicts.append('complex'); continue
        lr = last.real
        if rhs == 'oo': ok = lr > 1e4 and (len(s) < 2 or s[-1].real >= s[-2].real)
        elif rhs == '-oo': ok = lr < -1e4 and (len(s) < 2 or s[-1].real <= s[-2].real)
        elif rhs == 'undefined': ok = None
        else:
            R = complex(sp.N(to_sympy(rhs).subs({sp.Symbol(k): sp.Float(v, 30) for k, v in vals.items()}), 30))
            ok = close(last, R)
        verdicts.append(ok)
    if rhs == 'undefined':
        # true iff one-sided limits differ in sign of infinity (our only use: 1/x at 0)
        return None
    if all(v is True for v in verdicts): return True
    if any(v is False for v in verdicts): return False
    return None

def check_limit_sympy(d):
    var = sp.Symbol(d['var']); f = to_sympy(d['lhs']); p = to_sympy(d['point']); rhs = d['rhs']
    dr = d.get('dir') or '+-'
    if (d.get('assumptions') or {}).get(d['var']) == 'positive': dr = '+'
    if d['point'] in ('oo', '-oo'): dr = '+'
    L = sp.limit(f, var, p, dr) if dr != '+-' else None
    if dr == '+-':
        a = sp.limit(f, var, p, '+'); b = sp.limit(f, var, p, '-')
        L = a if sp.simplify(a - b) == 0 or a == b else 'undefined'
    if rhs == 'undefined': return L == 'undefined'
    if L == 'undefined': return False
    R = to_sympy(rhs)
    if R in (sp.oo, -sp.oo) or L in (sp.oo, -sp.oo): return L == R
    diff = sp.simplify(L - R)
    if diff == 0: return True
    try:
        return abs(complex(sp.N(diff.subs({s: sp.Rational(7, 10) for s in diff.free_symbols})))) < 1e-12
    except Exception: return None

def check_series(d):
    var = sp.Symbol(d['var']); f = to_sympy(d['lhs']); s = to_sympy(d['rhs']); p = to_sympy(d['point'])
    N = d['order']; dr = d.get('dir') or '+-'
    q = (f - s) / (var - p)**N
    sides = ['+', '-'] if dr == '+-' else [dr]
    # numeric: ratio at h = 1e-4, 1e-6, 1e-8 must not blow up
    mp.mp.dps = 80
    params = sorted({str(x) for x in q.free_symbols} - {d['var']})
    vals = {sp.Symbol(k): sp.Rational(7, 10) for k in params}
    qq = q.subs(vals)
    ok = True
    for sd in sides:
        rs = []
        for k in (4, 8, 12):
            X = p + (sp.Rational(1, 10**k) if sd == '+' else -sp.Rational(1, 10**k))
            rs.append(abs(complex(sp.N(qq.subs(var, X), 60))))
        if rs[-1] > 50 * (rs[0] + 1): ok = False
    return ok

def check_equal(d, rnd):
    f = to_sympy(d['lhs']) - to_sympy(d['rhs'])
    names = sorted(str(s) for s in f.free_symbols)
    for _ in range(5):
        vals = sample(d.get('assumptions'), names, rnd)
        v = complex(sp.N(f.subs({sp.Symbol(k): sp.Float(x, 30) for k, x in vals.items()}), 30))
        if abs(v) > 1e-15: return False
    return True

def check_anti(d, rnd):
    var = sp.Symbol(d['var'])
    f = sp.diff(to_sympy(d['rhs']), var) - to_sympy(d['lhs'])
    names = sorted(str(s) for s in f.free_symbols)
    for _ in range(5):
        vals = sample(d.get('assumptions'), names, rnd)
        v = complex(sp.N(f.subs({sp.Symbol(k): sp.Float(x, 30) for k, x in vals.items()}), 30))
        if abs(v) > 1e-15: return False
    return True

def check_ode(d, rnd):
    var = sp.Symbol(d['var']); sol = to_sympy(d['solution'])
    y, yp, ypp = sp.symbols('y yp ypp')
    res = (to_sympy(d['lhs']) - to_sympy(d['rhs'])).subs({ypp: sp.diff(sol, var, 2), yp: sp.diff(sol, var), y: sol})
    names = sorted(str(s) for s in res.free_symbols | sol.free_symbols)
    for _ in range(5):
        vals = sample(d.get('assumptions'), names, rnd)
        sub = {sp.Symbol(k): sp.Float(x, 30) for k, x in vals.items()}
        v = complex(sp.N(res.subs(sub), 30))
        if abs(v) > 1e-12: return False
    for ic in d.get('initial', []):
        e = sp.diff(sol, var, ic['order']).subs(var, to_sympy(ic['at'])) - to_sympy(ic['value'])
        if abs(complex(sp.N(e.subs({s: sp.Rational(7, 10) for s in e.free_symbols})))) > 1e-12: return False
    return True

def main():
    rnd = random.Random(1)
    out = []
    for group in (C.LIMITS, C.SERIES, C.EQUAL, C.ANTI, C.ODE):
        for d in group:
            w = d.pop('w', None)
            t = dict(d); t['expected'] = 'true'; out.append(t)
            if w:
                f = dict(d); f.update(w); f['id'] = d['id'] + '__wrong'; f['expected'] = 'false'
                f['source'] = d['source'] + ' [wrong variant: ' + ', '.join(f'{k}={v}' for k, v in w.items()) + ']'
                out.append(f)
    with open(__import__('os').path.join(__import__('os').path.dirname(__import__('os').path.abspath(__file__)), '../../tests/data/published/published.jsonl'), 'w') as fh:
        for d in out: fh.write(json.dumps(d) + '\n')
    print('written', len(out), flush=True)
    only = sys.argv[1:]
    bad = []
    for d in out:
        if only and d['id'] not in only: continue
        if not only:
            import subprocess
            try:
                p = subprocess.run(['/usr/bin/python3', __file__, d['id']], capture_output=True, text=True, timeout=60, preexec_fn=lambda: __import__('resource').setrlimit(__import__('resource').RLIMIT_AS, (1<<30, 1<<30)))
                if 'DISAGREE' in p.stdout or p.returncode: print('  ', d['id'], d['expected'], p.stdout.strip()[-200:], p.stderr.strip()[-120:], flush=True)
            except subprocess.TimeoutExpired: print('  ', d['id'], 'timeout', flush=True)
            continue
        signal.alarm(40)
        try:
            k = d['kind']
            if k == 'limit':
                r = check_limit(d, rnd)
                if r is None or r != (d['expected'] == 'true'):
                    try: r2 = check_limit_sympy(d)
                    except Exception as e: r2 = None
                    r = r2 if r2 is not None else r
            elif k == 'series': r = check_series(d)
            elif k == 'equal': r = check_equal(d, rnd)
            elif k == 'antiderivative': r = check_anti(d, rnd)
            elif k == 'solves_ode': r = check_ode(d, rnd)
        except TO: r = 'timeout'
        except Exception as e: r = 'exc:' + repr(e)[:80]
        signal.alarm(0)
        exp = d['expected'] == 'true'
        if r is not exp:
            bad.append((d['id'], d['expected'], r)); print('DISAGREE', d['id'], d['expected'], r)
    if only: return
    from collections import Counter
    print('claims', len(out), Counter((d['kind'], d['expected']) for d in out))
    print('independent-check disagreements:')
    for b in bad: print('  ', b)
main()
