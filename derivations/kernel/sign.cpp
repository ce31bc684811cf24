// Signs over the declared domain: Sturm sequences and Arb subdivision (sign.hpp).
#include "derivations/kernel/sign.hpp"

#include <deque>
#include <vector>

#include <cln/rational.h>
#include <cln/real.h>

#include "derivations/kernel/ball_box.hpp"
#include "derivations/symbolic/inspect.hpp"
#include "derivations/symbolic/printer.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace dc::kernel {

using GiNaC::ex;
using GiNaC::numeric;
using GiNaC::symbol;

namespace {

constexpr int kMaxBoxes = 256;   // Arb evaluations one subdivision may spend

// One end of an interval of rationals (inf: -1 for -oo, +1 for +oo).
struct End {
  numeric at;
  int inf = 0;
  bool open = true;
};

int sign_of(const numeric& v) { return v.is_zero() ? 0 : v > 0 ? 1 : -1; }

int sign_at(const ex& s, const symbol& x, const End& t) {
  if (t.inf == 0) return sign_of(GiNaC::ex_to<numeric>(s.subs(x == t.at)));
  const ex e = s.expand();
  const int d = e.degree(x);
  int sg = sign_of(GiNaC::ex_to<numeric>(e.coeff(x, d)));
  if (t.inf < 0 && d % 2 == 1) sg = -sg;
  return sg;
}

bool rational_polynomial(const ex& p, const symbol& x) {
  if (!p.is_polynomial(x)) return false;
  const ex e = p.expand();
  if (e.degree(x) < 1) return false;
  for (int i = e.ldegree(x); i <= e.degree(x); ++i) {
    const ex c = e.coeff(x, i);
    if (!GiNaC::is_a<numeric>(c) || !GiNaC::ex_to<numeric>(c).is_rational()) return false;
  }
  return true;
}

// An outward rational enclosure [lo, hi] of a real constant (pi/2): nullopt when not real.
std::optional<std::pair<numeric, numeric>> enclose_constant(const ex& c) {
  if (GiNaC::is_a<numeric>(c) && GiNaC::ex_to<numeric>(c).is_rational()) {
    const numeric q = GiNaC::ex_to<numeric>(c);
    return std::make_pair(q, q);
  }
  Ball b = enclose(c, 256);
  numeric lo, hi;
  if (b.status != BallStatus::Value || !b.exact_bounds(lo, hi, 4096)) return std::nullopt;
  return std::make_pair(lo, hi);
}

// The declared domain of a symbol as an interval of rationals containing it (an irrational
// end enclosed outward and closed).
std::optional<std::pair<End, End>> domain_interval(const Domain& d) {
  using K = Domain::Kind;
  switch (d.kind) {
    case K::Real: return std::make_pair(End{0, -1}, End{0, +1});
    case K::Positive: return std::make_pair(End{0, 0, true}, End{0, +1});
    case K::Nonnegative: return std::make_pair(End{0, 0, false}, End{0, +1});
    case K::Negative: return std::make_pair(End{0, -1}, End{0, 0, true});
    case K::Interval: {
      const auto lo = enclose_constant(d.lo), hi = enclose_constant(d.hi);
      if (!lo || !hi) return std::nullopt;
      const bool lo_exact = lo->first == lo->second, hi_exact = hi->first == hi->second;
      return std::make_pair(End{lo->first, 0, lo_exact && d.lo_open}, End{hi->second, 0, hi_exact && d.hi_open});
    }
  }
  return std::nullopt;
}

std::string end_text(const End& e, bool lower) {
  if (e.inf) return lower ? "(-oo" : "oo)";
  return lower ? (e.open ? "(" : "[") + detail::exact_text(e.at) : detail::exact_text(e.at) + (e.open ? ")" : "]");
}

// The factors of odd multiplicity of p (where p changes sign), from GiNaC's square-free
// decomposition.
ex odd_part(const ex& p, const symbol& x) {
  const ex f = GiNaC::sqrfree(p.expand(), GiNaC::lst{x});
  ex out = 1;
  auto take = [&](const ex& factor) {
    if (GiNaC::is_a<GiNaC::power>(factor) && GiNaC::is_a<numeric>(factor.op(1))) {
      const numeric k = GiNaC::ex_to<numeric>(factor.op(1));
      if (k.is_integer() && k.is_odd()) out *= factor.op(0);
      return;
    }
    if (factor.has(x)) out *= factor;
  };
  if (GiNaC::is_a<GiNaC::mul>(f))
    for (std::size_t i = 0; i < f.nops(); ++i) take(f.op(i));
  else
    take(f);
  return out.expand();
}

std::optional<std::string> by_sturm(const ex& e, const symbol& x, SignWant want, const SymbolTable& ctx) {
  if (!rational_polynomial(e, x)) return std::nullopt;
  const auto iv = domain_interval(detail::domain_of(x, ctx));
  if (!iv) return std::nullopt;
  const End& lo = iv->first;
  const End& hi = iv->second;
  const ex p = e.expand();
  // the polynomial whose roots must stay out of the open interval: all of p's for > 0 and != 0,
  // those of odd multiplicity for >= 0
  const ex q = want == SignWant::Nonnegative ? odd_part(p, x) : p;
  if (q.degree(x) >= 1 && sturm_root_inside(q, x, lo.at, lo.inf < 0, hi.at, hi.inf > 0)) return std::nullopt;
  if (want != SignWant::Nonnegative)
    for (const End* t : {&lo, &hi})
      if (t->inf == 0 && !t->open && sign_at(p, x, *t) == 0) return std::nullopt;   // a root at a closed end
  // p keeps one sign on the open interval (where nonzero): read it at an interior point
  std::vector<numeric> tries;
  if (lo.inf == 0 && hi.inf == 0) {
    for (int k = 1; k < 8; ++k) tries.push_back(lo.at + (hi.at - lo.at) * numeric(k, 8));
  } else {
    const numeric base = lo.inf == 0 ? lo.at + 1 : hi.inf == 0 ? hi.at - 1 : numeric(0);
    for (int k = 0; k < 7; ++k) tries.push_back(base + numeric(k, 3) * (lo.inf == 0 ? 1 : -1));
  }
  for (const numeric& t : tries) {
    const int s = sign_at(p, x, End{t});
    if (s == 0) continue;
    if (want != SignWant::Nonzero && s < 0) return std::nullopt;
    const std::string dom = end_text(lo, true) + ", " + end_text(hi, false);
    const std::string what = want == SignWant::Nonnegative ? "no real root of odd multiplicity" : "no real root";
    return "Sturm sequence: " + print_text(p, ctx) + " has " + what + " in " + x.get_name() + " " + dom +
           (want == SignWant::Nonzero ? "" : " and is positive at " + x.get_name() + " = " + detail::exact_text(t));
  }
  return std::nullopt;
}

bool sign_ok(const Ball& b, SignWant want) {
  switch (want) {
    case SignWant::Positive: return b.positive();
    case SignWant::Nonnegative: return certainly_nonnegative(b);
    case SignWant::Nonzero: return b.positive() || b.negative();
  }
  return false;
}

std::optional<std::string> by_subdivision(const ex& e, const std::vector<ex>& syms, SignWant want,
                                          const SymbolTable& ctx) {
  Box box;
  std::string dom;
  for (const ex& s : syms) {
    const Domain d = detail::domain_of(s, ctx);
    if (d.kind != Domain::Kind::Interval) return std::nullopt;
    const auto iv = domain_interval(d);
    if (!iv) return std::nullopt;
    box[s] = {iv->first.at, iv->second.at};
    dom += (dom.empty() ? "" : ", ") + GiNaC::ex_to<symbol>(s).get_name() + " " + d.to_string();
  }
  std::deque<Box> todo{box};
  int evaluations = 0, pieces = 0;
  while (!todo.empty()) {
    if (++evaluations > kMaxBoxes) return std::nullopt;
    Box b = std::move(todo.front());
    todo.pop_front();
    if (sign_ok(enclose_box(e, b, 128), want)) {
      ++pieces;
      continue;
    }
    if (b.empty()) return std::nullopt;
    // bisect the widest side
    auto widest = b.begin();
    for (auto it = b.begin(); it != b.end(); ++it)
      if (it->second.second - it->second.first > widest->second.second - widest->second.first) widest = it;
    const numeric mid = (widest->second.first + widest->second.second) / 2;
    Box left = b, right = b;
    left[widest->first].second = mid;
    right[widest->first].first = mid;
    todo.push_back(std::move(left));
    todo.push_back(std::move(right));
  }
  return "Arb interval evaluation on " + std::to_string(pieces) + " piece" + (pieces == 1 ? "" : "s") + " of " + dom;
}

}  // namespace

bool sturm_root_inside(ex p, const symbol& x, const numeric& lo_at, bool lo_inf, const numeric& hi_at, bool hi_inf) {
  const End lo{lo_at, lo_inf ? -1 : 0}, hi{hi_at, hi_inf ? +1 : 0};
  p = p.expand();
  if (p.degree(x) < 1) return false;
  p = GiNaC::quo(p, GiNaC::gcd(p, p.diff(x)), x).expand();   // square-free: roots counted once
  for (const End* e : {&lo, &hi})
    if (e->inf == 0)
      while (p.degree(x) >= 1 && p.subs(x == e->at).is_zero()) p = GiNaC::quo(p, x - e->at, x).expand();
  if (p.degree(x) < 1) return false;
  std::vector<ex> seq = {p, p.diff(x).expand()};
  for (;;) {
    const ex r = (-GiNaC::rem(seq[seq.size() - 2], seq.back(), x)).expand();
    if (r.is_zero()) break;
    seq.push_back(r);
    if (r.degree(x) == 0) break;
  }
  auto variations = [&](const End& t) {
    int v = 0, last = 0;
    for (const ex& s : seq) {
      const int sg = sign_at(s, x, t);
      if (sg == 0) continue;
      if (last != 0 && sg != last) ++v;
      last = sg;
    }
    return v;
  };
  return variations(lo) - variations(hi) > 0;
}

std::optional<std::string> decide_sign_by_sturm(const ex& e, SignWant want, const SymbolTable& ctx) {
  try {
    const std::vector<ex> syms = detail::ordered_symbols(e, ctx);
    if (syms.size() != 1 || !GiNaC::is_a<symbol>(syms[0]) || detail::has_abstract_application(e)) return std::nullopt;
    return by_sturm(e, GiNaC::ex_to<symbol>(syms[0]), want, ctx);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

std::optional<std::string> decide_sign(const ex& e, SignWant want, const SymbolTable& ctx) {
  try {
    if (detail::has_abstract_application(e)) return std::nullopt;
    const std::vector<ex> syms = detail::ordered_symbols(e, ctx);
    if (syms.empty()) return std::nullopt;
    if (syms.size() == 1 && GiNaC::is_a<symbol>(syms[0]))
      if (auto s = by_sturm(e, GiNaC::ex_to<symbol>(syms[0]), want, ctx)) return s;
    return by_subdivision(e, syms, want, ctx);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace dc::kernel
