// Antiderivatives by table and rules, verified by differentiation (see antiderivative.hpp).
#include "derivations/calculus/antiderivative.hpp"

#include <vector>

#include "derivations/decide/prove.hpp"

namespace dc::integrals {
namespace {

using namespace GiNaC;

struct NoRule {};   // thrown inside the rules: the caller tries the next one

constexpr int kMaxDepth = 12;

// u = a x + b with a != 0 free of x.
bool linear_in(const ex& u, const symbol& x, ex* a = nullptr) {
  if (!u.has(x) || !u.is_polynomial(x)) return false;
  const ex e = u.expand();
  if (e.degree(x) != 1) return false;
  const ex c = e.coeff(x, 1);
  if (c.has(x) || c.is_zero()) return false;
  if (a) *a = c;
  return true;
}

bool is_fn(const ex& e, const char* name) {
  return is_a<function>(e) && ex_to<function>(e).get_name() == name;
}

// The table: f is one elementary function (or power) of a linear argument.
std::optional<ex> elementary(const ex& f, const symbol& x) {
  ex a;
  if (is_a<power>(f)) {
    const ex& b = f.op(0);
    const ex& n = f.op(1);
    if (!n.has(x) && linear_in(b, x, &a) && is_a<numeric>(n)) {
      if (n.is_equal(-1)) return log(b) / a;
      return pow(b, n + 1) / ((n + 1) * a);
    }
    if (!b.has(x) && linear_in(n, x, &a)) return f / (a * log(b));   // c^u
    // (A x^2 + B x + C)^(-1/2) with numeric coefficients: asin or log form
    if (n.is_equal(numeric(-1, 2)) && b.is_polynomial(x) && b.expand().degree(x) == 2) {
      const ex e = b.expand();
      const ex A = e.coeff(x, 2), B = e.coeff(x, 1), C = e.coeff(x, 0);
      if (is_a<numeric>(A) && is_a<numeric>(B) && is_a<numeric>(C)) {
        const numeric An = ex_to<numeric>(A), K = ex_to<numeric>(C - B * B / (4 * A));
        const ex shift = x + B / (2 * A);
        if (An < 0 && K > 0) return asin(sqrt(-A / K) * shift) / sqrt(-A);
        if (An > 0) return log(shift + sqrt(b / A)) / sqrt(A);
      }
    }
    return std::nullopt;
  }
  if (!is_a<function>(f) || f.nops() != 1 || !linear_in(f.op(0), x, &a)) return std::nullopt;
  const ex& u = f.op(0);
  if (is_fn(f, "exp")) return exp(u) / a;
  if (is_fn(f, "sin")) return -cos(u) / a;
  if (is_fn(f, "cos")) return sin(u) / a;
  if (is_fn(f, "tan")) return -log(cos(u)) / a;
  if (is_fn(f, "log")) return (u * log(u) - u) / a;
  if (is_fn(f, "atan")) return (u * atan(u) - log(1 + pow(u, 2)) / 2) / a;
  if (is_fn(f, "asin")) return (u * asin(u) + sqrt(1 - pow(u, 2))) / a;
  if (is_fn(f, "acos")) return (u * acos(u) - sqrt(1 - pow(u, 2))) / a;
  if (is_fn(f, "sinh")) return cosh(u) / a;
  if (is_fn(f, "cosh")) return sinh(u) / a;
  return std::nullopt;
}

ex integrate(const ex& f, const symbol& x, int depth);

// Rational functions: polynomial part, then partial fractions over the factors GiNaC's factor()
// finds (linear ones of any multiplicity, quadratic ones to the first power).
std::optional<ex> rational(const ex& f, const symbol& x) {
  const ex nd = f.normal().numer_denom();
  const ex N = nd.op(0).expand(), D = nd.op(1).expand();
  if (!N.is_polynomial(x) || !D.is_polynomial(x) || D.degree(x) < 1) return std::nullopt;
  const ex q = quo(N, D, x), r = rem(N, D, x);
  ex F = integral(x, 0, x, q).eval_integ();
  if (r.is_zero()) return F;
  const ex Df = factor(D);
  // factors p^k (a numeric content aside)
  std::vector<std::pair<ex, int>> factors;
  ex content = 1;
  auto add_factor = [&](const ex& p) {
    if (is_a<power>(p) && is_a<numeric>(p.op(1)) && ex_to<numeric>(p.op(1)).is_pos_integer())
      factors.emplace_back(p.op(0), ex_to<numeric>(p.op(1)).to_int());
    else if (p.has(x))
      factors.emplace_back(p, 1);
    else
      content *= p;
  };
  if (is_a<mul>(Df))
    for (std::size_t i = 0; i < Df.nops(); ++i) add_factor(Df.op(i));
  else
    add_factor(Df);
  lst unknowns;
  ex sum = 0;
  std::vector<ex> terms;
  int counter = 0;
  for (const auto& [p, k] : factors) {
    const int deg = p.expand().degree(x);
    if (deg > 2 || (deg == 2 && k > 1)) return std::nullopt;
    for (int j = 1; j <= k; ++j) {
      const symbol A("pfA" + std::to_string(counter)), B("pfB" + std::to_string(counter));
      ++counter;
      ex numer = A;
      unknowns.append(A);
      if (deg == 2) {
        numer = B * x + A;
        unknowns.append(B);
      }
      terms.push_back(numer / pow(p, j));
      sum += numer * (D / content / pow(p, j)).normal();
    }
  }
  // r / D = sum of terms: compare the coefficients of r and content * sum
  const ex diff = (content * sum - r).expand();
  lst eqs;
  for (int i = 0; i <= diff.degree(x); ++i) eqs.append(diff.coeff(x, i) == 0);
  ex sol;
  try {
    sol = lsolve(eqs, unknowns);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (!is_a<lst>(sol) || sol.nops() != unknowns.nops()) return std::nullopt;
  for (const ex& t : terms) {
    const ex term = t.subs(sol).normal();
    const ex nd2 = t.numer_denom();
    const ex p = is_a<power>(nd2.op(1)) ? nd2.op(1).op(0) : nd2.op(1);
    const int j = is_a<power>(nd2.op(1)) ? ex_to<numeric>(nd2.op(1).op(1)).to_int() : 1;
    const ex numer = nd2.op(0).subs(sol);
    const ex pe = p.expand();
    if (pe.degree(x) == 1) {
      const ex a = pe.coeff(x, 1);
      F += j == 1 ? numer / a * log(p) : numer / (a * (1 - j)) * pow(p, 1 - j);
    } else {
      const ex al = pe.coeff(x, 2), be = pe.coeff(x, 1), ga = pe.coeff(x, 0);
      const ex Bc = numer.expand().coeff(x, 1), Cc = numer.expand().coeff(x, 0);
      const ex disc = 4 * al * ga - be * be;   // > 0 for the atan form
      F += Bc / (2 * al) * log(p);
      const ex rest = Cc - Bc * be / (2 * al);
      if (is_a<numeric>(disc) && ex_to<numeric>(disc) < 0) {
        const ex s = sqrt(-disc);
        F += rest / s * log((2 * al * x + be - s) / (2 * al * x + be + s));
      } else {
        const ex s = sqrt(disc);
        F += rest * 2 / s * atan((2 * al * x + be) / s);
      }
    }
    (void)term;
  }
  return F;
}

// A polynomial p times h (exp / sin / cos of a linear argument): by parts, p H - int p' H.
std::optional<ex> by_parts(const ex& p, const ex& h, const symbol& x, int depth) {
  const auto H = elementary(h, x);
  if (!H) return std::nullopt;
  if (is_fn(h, "log")) {   // p log u: P log u - int P u'/u, a rational function
    const ex P = integral(x, 0, x, p).eval_integ();
    const ex u = h.op(0);
    return P * h - integrate((P * u.diff(x) / u).normal(), x, depth + 1);
  }
  if (!is_fn(h, "exp") && !is_fn(h, "sin") && !is_fn(h, "cos")) return std::nullopt;
  return p * *H - integrate((p.diff(x) * *H).expand(), x, depth + 1);
}

// q(x) as a polynomial in g = c x^k, when every power of x in q is a multiple of k: q(t) with
// x^(k m) -> (t / c)^m. nullopt otherwise.
std::optional<ex> in_terms_of(const ex& q, const ex& g, const symbol& x, const symbol& t) {
  if (!q.is_polynomial(x)) return std::nullopt;
  const ex ge = g.expand();
  if (!is_a<mul>(ge) && !is_a<power>(ge) && !ge.is_equal(x)) return std::nullopt;
  const int k = ge.degree(x);
  if (k < 1 || ge.ldegree(x) != k) return std::nullopt;
  const ex c = ge.coeff(x, k);
  if (c.has(x)) return std::nullopt;
  const ex qe = q.expand();
  ex out = 0;
  for (int i = qe.ldegree(x); i <= qe.degree(x); ++i) {
    const ex ci = qe.coeff(x, i);
    if (ci.is_zero()) continue;
    if (i % k != 0) return std::nullopt;
    out += ci * pow(t / c, i / k);
  }
  return out;
}

// f = q(g) g'(x) h(g(x)) for h in the table, q a constant or (g = c x^k) a polynomial in g:
// substitute t = g and integrate q(t) h(t) dt.
std::optional<ex> derivative_divides(const ex& f, const symbol& x, int depth) {
  const symbol t("dd_t" + std::to_string(depth));
  for (const_preorder_iterator it = f.preorder_begin(); it != f.preorder_end(); ++it) {
    const ex s = *it;
    ex g, st;
    if (is_a<function>(s) && s.nops() == 1 && s.op(0).has(x)) {
      g = s.op(0);
      st = s.subs(g == t);
    } else if (is_a<power>(s) && s.op(0).has(x) && !s.op(1).has(x)) {
      g = s.op(0);
      st = pow(t, s.op(1));
    } else {
      continue;
    }
    // h = identity: f = q g g'  (sin(x) cos(x), log(x)/x)
    for (const ex& gg : {s, g}) {
      if (gg.is_equal(x) || linear_in(gg, x)) continue;
      const ex dg = gg.diff(x);
      if (dg.is_zero()) continue;
      const ex q = (f / (gg * dg)).normal();
      if (!q.has(x)) return q * pow(gg, 2) / 2;
    }
    if (linear_in(g, x) || g.is_equal(x)) continue;
    const ex dg = g.diff(x);
    if (dg.is_zero()) continue;
    const ex q = (f / (s * dg)).normal();
    if (!q.has(x)) {
      if (const auto H = elementary(st, t)) return q * H->subs(t == g);
      continue;
    }
    if (const auto qt = in_terms_of(q, g, x, t)) {
      try {
        return integrate((*qt * st).expand(), t, depth + 1).subs(t == g);
      } catch (const NoRule&) {
      }
    }
  }
  return std::nullopt;
}

// sin(u)^n, cos(u)^n (n = 2, 3) as sums of sin / cos of multiples of u, and products of two
// sines / cosines as sums (exact identities; cubes first, so that cos^3 is not read as cos^2 cos).
ex linearize_trig(const ex& f, const symbol& x) {
  (void)x;
  const ex u = wild(0), v = wild(1);
  ex g = f.subs(lst{pow(sin(u), 3), pow(cos(u), 3)},
                lst{(3 * sin(u) - sin(3 * u)) / 4, (3 * cos(u) + cos(3 * u)) / 4});
  g = g.subs(lst{pow(sin(u), 2), pow(cos(u), 2)}, lst{(1 - cos(2 * u)) / 2, (1 + cos(2 * u)) / 2});
  g = g.expand();
  g = g.subs(lst{sin(u) * cos(v), sin(u) * sin(v), cos(u) * cos(v)},
             lst{(sin(u + v) + sin(u - v)) / 2, (cos(u - v) - cos(u + v)) / 2, (cos(u - v) + cos(u + v)) / 2});
  return g;
}

ex integrate(const ex& f, const symbol& x, int depth) {
  if (depth > kMaxDepth) throw NoRule{};
  if (!f.has(x)) return f * x;
  if (is_a<add>(f)) {
    ex s = 0;
    for (std::size_t i = 0; i < f.nops(); ++i) s += integrate(f.op(i), x, depth + 1);
    return s;
  }
  if (f.is_polynomial(x)) return integral(x, 0, x, f).eval_integ();
  if (is_a<mul>(f)) {
    ex c = 1, rest = 1;
    std::vector<ex> parts;
    for (std::size_t i = 0; i < f.nops(); ++i) {
      if (f.op(i).has(x)) {
        rest *= f.op(i);
        parts.push_back(f.op(i));
      } else {
        c *= f.op(i);
      }
    }
    if (!c.is_equal(1)) return c * integrate(rest, x, depth + 1);
    // polynomial factors times one transcendental factor
    ex poly = 1, other = 1;
    int n_other = 0;
    for (const ex& p : parts) {
      if (p.is_polynomial(x)) poly *= p;
      else other *= p, ++n_other;
    }
    if (n_other == 1 && !poly.is_equal(1))
      if (auto F = by_parts(poly.expand(), other, x, depth)) return *F;
    // exp(alpha x + beta) times sin / cos(gamma x + delta)
    if (parts.size() == 2) {
      ex e = parts[0], t = parts[1];
      if (!is_fn(e, "exp")) std::swap(e, t);
      ex al, ga;
      if (is_fn(e, "exp") && (is_fn(t, "sin") || is_fn(t, "cos")) && linear_in(e.op(0), x, &al) &&
          linear_in(t.op(0), x, &ga)) {
        const ex u = t.op(0);
        const ex den = al * al + ga * ga;
        if (is_fn(t, "sin")) return e * (al * sin(u) - ga * cos(u)) / den;
        return e * (al * cos(u) + ga * sin(u)) / den;
      }
    }
  }
  if (auto F = elementary(f, x)) return *F;
  if (auto F = derivative_divides(f, x, depth)) return *F;
  if (auto F = rational(f, x)) return *F;
  // sin^2, cos^2, sin^3, cos^3 of linear arguments, then the rules again
  if (f.has(sin(wild())) || f.has(cos(wild()))) {
    const ex g = linearize_trig(f, x).expand();
    if (!g.is_equal(f.expand())) return integrate(g, x, depth + 1);
  }
  // a product or power that expands into terms the rules know (sin(x)^2 does not; x (x+1)^3 does)
  const ex e = f.expand();
  if (!e.is_equal(f) && is_a<add>(e) && e.nops() <= 64) return integrate(e, x, depth + 1);
  throw NoRule{};
}

}  // namespace

std::optional<ex> antiderivative(const ex& f, const symbol& x, const SymbolTable& ctx, std::string* why) {
  ex F;
  try {
    F = integrate(f, x, 0);
  } catch (const NoRule&) {
    if (why) *why = "no antiderivative rule applies (table, by parts, partial fractions, derivative divides)";
    return std::nullopt;
  } catch (const std::exception& e) {
    if (why) *why = std::string("no antiderivative: ") + e.what();
    return std::nullopt;
  }
  const ex dF = F.diff(x);
  if ((dF - f).normal().is_zero()) return F;
  // sin^n / cos^n were rewritten by exact identities (linearize_trig): compare with that form
  if ((dF - linearize_trig(f, x).expand()).expand().normal().is_zero()) return F;
  // only a proof counts (Proved: a symbolic method, re-witnessed), never "holds numerically"
  const Verdict v = prove_equal(dF, f, ctx);
  if (v.kind == VerdictKind::Proved) return F;
  if (why) *why = "a candidate antiderivative was found but its derivative was not proved equal to the integrand";
  return std::nullopt;
}

}  // namespace dc::integrals
