// Internals of the prover: sampling, evaluation, range analysis, deterministic text.
#include "derivations/core/prove_detail.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <set>
#include <sstream>

#include <cln/float.h>
#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/real.h>

#include "derivations/core/printer.hpp"
#include "derivations/core/prove.hpp"

namespace dc::detail {

using GiNaC::ex;
using GiNaC::numeric;

// ---------------------------------------------------------------- random numbers

std::uint64_t Rng::next() {
  // splitmix64 (Steele, Lea, Flood 2014)
  std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double Rng::uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

std::uint64_t Rng::below(std::uint64_t n) { return n == 0 ? 0 : next() % n; }

std::uint64_t hash_text(const std::string& s, std::uint64_t seed) {
  std::uint64_t h = 1469598103934665603ull ^ (seed * 0x9E3779B97F4A7C15ull);
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

// ---------------------------------------------------------------- symbols and domains

namespace {

int decl_index(const ex& s, const SymbolTable& ctx) {
  const auto& all = ctx.all();
  for (std::size_t i = 0; i < all.size(); ++i)
    if (GiNaC::is_a<GiNaC::symbol>(all[i].sym) && all[i].sym.is_equal(s)) return static_cast<int>(i);
  return INT_MAX;
}

}  // namespace

void collect_symbols(const ex& e, GiNaC::exset& out) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    out.insert(e);
    return;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) collect_symbols(e.op(i), out);
}

numeric pow10(int k) { return GiNaC::pow(numeric(10), numeric(k)); }

Domain domain_of(const ex& s, const SymbolTable& ctx) {
  if (!GiNaC::is_a<GiNaC::symbol>(s)) return Domain::real();
  if (const SymbolInfo* info = ctx.find(GiNaC::ex_to<GiNaC::symbol>(s))) return info->domain;
  if (s.info(GiNaC::info_flags::positive)) return Domain::positive();
  return Domain::real();
}

std::vector<ex> ordered_symbols(const ex& e, const SymbolTable& ctx) {
  GiNaC::exset set;
  collect_symbols(e, set);
  std::vector<std::pair<std::pair<int, std::string>, ex>> v;
  for (const ex& s : set) v.push_back({{decl_index(s, ctx), GiNaC::ex_to<GiNaC::symbol>(s).get_name()}, s});
  std::stable_sort(v.begin(), v.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<ex> out;
  for (auto& p : v) out.push_back(p.second);
  return out;
}

// Sampling (sample_value, PointSampler): sampling.cpp.

// ---------------------------------------------------------------- abstract functions

namespace {

bool evaluable_function(const std::string& name) {
  static const std::set<std::string> known = {
      "exp",  "log",   "sin",   "cos",   "tan",    "asin",   "acos",      "atan",
      "atan2", "sinh", "cosh",  "tanh",  "asinh",  "acosh",  "atanh",     "abs",
      "csgn", "step",  "tgamma", "lgamma", "factorial", "binomial", "zeta", "Li2",
      "conjugate", "real_part", "imag_part", "sqrt"};
  return known.count(name) > 0;
}

}  // namespace

bool is_abstract_application(const ex& e) {
  if (GiNaC::is_a<GiNaC::fderivative>(e)) return true;
  if (GiNaC::is_a<GiNaC::function>(e))
    return !evaluable_function(GiNaC::ex_to<GiNaC::function>(e).get_name());
  return false;
}

bool has_abstract_application(const ex& e) {
  if (is_abstract_application(e)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_abstract_application(e.op(i))) return true;
  return false;
}

namespace {

struct AbstractReplacer : GiNaC::map_function {
  std::uint64_t seed;
  explicit AbstractReplacer(std::uint64_t s) : seed(s) {}
  ex operator()(const ex& e) override {
    if (is_abstract_application(e)) {
      const auto& f = GiNaC::ex_to<GiNaC::function>(e);
      std::string key = f.get_name();
      if (GiNaC::is_a<GiNaC::fderivative>(e)) {
        key += "#D";
        for (unsigned d : GiNaC::ex_to<GiNaC::fderivative>(e).derivatives())
          key += "," + std::to_string(d);
      }
      for (std::size_t i = 0; i < e.nops(); ++i) {
        ex a = (*this)(e.op(i));
        RealValue v = eval_real(a, 50);
        key += "|" + (v.ok ? format_number(v.value, 40) : std::string("?"));
      }
      Rng rng(hash_text(key, seed));
      return sample_value(Domain::real(), rng, false);
    }
    if (e.nops() == 0) return e;
    return e.map(*this);
  }
};

}  // namespace

ex replace_abstract(const ex& e, std::uint64_t seed) {
  if (!has_abstract_application(e)) return e;
  AbstractReplacer r(seed);
  return r(e);
}

// ---------------------------------------------------------------- evaluation

RealValue eval_real(const ex& e, long digits) {
  RealValue r;
  try {
    if (GiNaC::is_a<numeric>(e) && GiNaC::ex_to<numeric>(e).is_rational()) {
      r.ok = true;
      r.exact = true;
      r.value = GiNaC::ex_to<numeric>(e);
      return r;
    }
    DigitsGuard g(digits);
    ex v = e.evalf();
    if (!GiNaC::is_a<numeric>(v)) {
      r.why = "not a number (a symbol without a value or an unevaluable function)";
      return r;
    }
    const numeric& n = GiNaC::ex_to<numeric>(v);
    if (n.is_real()) {
      r.ok = true;
      r.exact = n.is_rational();
      r.value = n;
      return r;
    }
    numeric re = n.real(), im = n.imag();
    if (GiNaC::abs(im) <= GiNaC::abs(re) * pow10(static_cast<int>(-(digits - 10)))) {
      r.ok = true;
      r.value = re;
      return r;
    }
    r.why = "not real";
  } catch (const std::exception&) {
    r.why = "undefined (division by zero or a pole)";
  }
  return r;
}

namespace {

constexpr long kMaxExactPowerDigits = 1000000;

// Throws where GiNaC::pow(b, x) would throw (0^0, 0^(negative)) or would compute an exact
// power of more than kMaxExactPowerDigits digits: GiNaC computes c^q exactly for the integer
// part q of the exponent, which has about q * log10(max(|num c|, den c)) digits.
void check_exact_power(const ex& b, const ex& x) {
  if (!GiNaC::is_a<numeric>(b) || !GiNaC::is_a<numeric>(x)) return;
  const numeric& nb = GiNaC::ex_to<numeric>(b);
  const numeric& nx = GiNaC::ex_to<numeric>(x);
  if (nb.is_zero()) {
    if (nx.is_zero()) throw std::domain_error("0^0 is undefined");
    if (!nx.real().is_positive()) throw GiNaC::pole_error("division by zero", 1);
    return;
  }
  // A float exponent of astronomic size (10^(10^12), from a tower of powers at a sample point):
  // GiNaC asks CLN whether it is an integer by rounding it to one, an exact integer of that many
  // bits (855 GB; found by the sanitizer run: ASan aborts, a plain build relied on malloc failing).
  if (nx.is_real() && !nx.is_rational()) {
    cln::cl_F f = cln::the<cln::cl_F>(cln::the<cln::cl_R>(nx.to_cl_N()));
    if (!cln::zerop(f) && cln::float_exponent(f) > (1L << 22))
      throw std::range_error("a power with an exponent of more than a million digits cannot be evaluated at this point");
  }
  if (!nb.is_rational() || !nx.is_rational() || GiNaC::abs(nb) == 1) return;
  long bits = std::max(cln::integer_length(cln::the<cln::cl_I>(nb.numer().to_cl_N())),
                       cln::integer_length(cln::the<cln::cl_I>(nb.denom().to_cl_N())));
  if (GiNaC::abs(nx) * numeric(bits) * numeric(30103, 100000) > numeric(kMaxExactPowerDigits))
    throw std::range_error("an exact power at this point would have more than a million digits");
}

struct PointSubs : GiNaC::map_function {
  const GiNaC::exmap& p;
  explicit PointSubs(const GiNaC::exmap& m) : p(m) {}
  ex operator()(const ex& e) override {
    if (GiNaC::is_a<GiNaC::power>(e)) {
      ex b = (*this)(e.op(0));
      ex x = (*this)(e.op(1));
      check_exact_power(b, x);
      return GiNaC::pow(b, x);
    }
    if (e.nops() == 0) return e.subs(p, GiNaC::subs_options::no_pattern);
    return e.map(*this);
  }
};

}  // namespace

ex subs_point(const ex& e, const GiNaC::exmap& p) {
  PointSubs f(p);
  return f(e);
}

std::string exact_text(const numeric& q) {
  if (!q.is_rational()) return format_number(q, 20);
  std::ostringstream os;
  os << q;
  return os.str();
}

std::string format_number(const numeric& x_in, int sig) {
  if (!x_in.is_real()) {
    std::ostringstream os;
    os << x_in;
    return os.str();
  }
  if (x_in.is_zero()) return "0";
  numeric r;
  long long shift = 0;  // the value is r * 10^shift
  if (x_in.is_rational()) {
    r = x_in;
  } else {
    cln::cl_F f = cln::the<cln::cl_F>(cln::the<cln::cl_R>(x_in.to_cl_N()));
    // A float far outside 10^-1200..10^1200 (a value that overflowed to 10^(10^18) in the probe)
    // is first scaled by a power of ten in float arithmetic: its exact rational would have as
    // many digits as its exponent (an allocation of petabytes, found by fuzz_expr).
    const long long fe = cln::float_exponent(f);
    if (fe > 4096 || fe < -4096) {
      shift = static_cast<long long>(std::floor(static_cast<double>(fe - 1) * 0.30102999566398119521));
      f = f / cln::expt(cln::cl_float(10, f), cln::cl_I(shift));
    }
    r = numeric(cln::cl_N(cln::rational(f)));
  }
  bool neg = r.is_negative();
  r = GiNaC::abs(r);
  // decimal exponent: 10^e10 <= r < 10^(e10+1)
  int bits = static_cast<int>(r.numer().int_length()) - static_cast<int>(r.denom().int_length());
  int e10 = static_cast<int>(std::floor(bits * 0.30102999566398119521));
  while (r >= pow10(e10 + 1)) ++e10;
  while (r < pow10(e10)) --e10;
  numeric scaled = r * pow10(sig - 1 - e10);
  numeric p = scaled.numer(), q = scaled.denom();
  numeric n = GiNaC::iquo(2 * p + q, 2 * q);  // round half up
  if (n >= pow10(sig)) {
    n = pow10(sig - 1);
    ++e10;
  }
  std::ostringstream os;
  os << n;
  std::string digits = os.str();
  while (digits.size() > 1 && digits.back() == '0') digits.pop_back();
  std::string out = neg ? "-" : "";
  if (shift != 0) {
    out += digits.substr(0, 1);
    if (digits.size() > 1) out += "." + digits.substr(1);
    return out + "e" + std::to_string(shift + e10);
  }
  if (e10 >= -5 && e10 < 21) {
    if (e10 >= 0) {
      std::string ip = digits.substr(0, std::min<std::size_t>(digits.size(), e10 + 1));
      while (static_cast<int>(ip.size()) < e10 + 1) ip += '0';
      std::string fp = digits.size() > static_cast<std::size_t>(e10 + 1) ? digits.substr(e10 + 1) : "";
      out += ip + (fp.empty() ? "" : "." + fp);
    } else {
      out += "0." + std::string(-e10 - 1, '0') + digits;
    }
  } else {
    out += digits.substr(0, 1);
    if (digits.size() > 1) out += "." + digits.substr(1);
    out += "e" + std::to_string(e10);
  }
  return out;
}

// ---------------------------------------------------------------- range analysis

bool Range::positive() const { return !lo_inf && (lo.is_positive() || (lo.is_zero() && lo_open)); }
bool Range::negative() const { return !hi_inf && (hi.is_negative() || (hi.is_zero() && hi_open)); }
bool Range::nonnegative() const { return !lo_inf && !lo.is_negative(); }
bool Range::within(const numeric& a, const numeric& b) const {
  return !lo_inf && !hi_inf && lo >= a && hi <= b;
}
std::string Range::to_string() const {
  std::string s = lo_inf ? "(-oo" : std::string(lo_open ? "(" : "[") + exact_text(lo);
  s += ", ";
  s += hi_inf ? "oo)" : exact_text(hi) + (hi_open ? ")" : "]");
  return s;
}

namespace {

Range point_range(const numeric& q) {
  Range r;
  r.lo_inf = r.hi_inf = false;
  r.lo = r.hi = q;
  r.lo_open = r.hi_open = false;
  return r;
}

Range make_range(bool lo_inf, numeric lo, bool lo_open, bool hi_inf, numeric hi, bool hi_open) {
  Range r;
  r.lo_inf = lo_inf;
  r.hi_inf = hi_inf;
  r.lo = lo;
  r.hi = hi;
  r.lo_open = lo_open;
  r.hi_open = hi_open;
  return r;
}

// Outward rational enclosure of a real constant (pi, pi/2, exp(1), ...).
Range constant_range(const ex& c) {
  DigitsGuard g(40);
  ex v = c.evalf();
  if (!GiNaC::is_a<numeric>(v) || !GiNaC::ex_to<numeric>(v).is_real()) return Range::all();
  numeric f = GiNaC::ex_to<numeric>(v);
  cln::cl_R cr = cln::the<cln::cl_R>(f.to_cl_N());
  numeric q = numeric(cln::cl_N(cln::rational(cr)));
  numeric pad = GiNaC::abs(q) * pow10(-30) + pow10(-60);
  return make_range(false, q - pad, false, false, q + pad, false);
}

Range bound_range_of_domain(const Domain& d) {
  using K = Domain::Kind;
  switch (d.kind) {
    case K::Real: return Range::all();
    case K::Positive: return make_range(false, 0, true, true, 0, true);
    case K::Nonnegative: return make_range(false, 0, false, true, 0, true);
    case K::Negative: return make_range(true, 0, true, false, 0, true);
    case K::Interval: {
      Range lo = GiNaC::is_a<numeric>(d.lo) ? point_range(GiNaC::ex_to<numeric>(d.lo)) : constant_range(d.lo);
      Range hi = GiNaC::is_a<numeric>(d.hi) ? point_range(GiNaC::ex_to<numeric>(d.hi)) : constant_range(d.hi);
      if (lo.lo_inf || hi.hi_inf) return Range::all();
      return make_range(false, lo.lo, d.lo_open, false, hi.hi, d.hi_open);
    }
  }
  return Range::all();
}

Range neg_range(const Range& a) {
  return make_range(a.hi_inf, -a.hi, a.hi_open, a.lo_inf, -a.lo, a.lo_open);
}

Range add_range(const Range& a, const Range& b) {
  Range r;
  r.lo_inf = a.lo_inf || b.lo_inf;
  r.hi_inf = a.hi_inf || b.hi_inf;
  if (!r.lo_inf) {
    r.lo = a.lo + b.lo;
    r.lo_open = a.lo_open || b.lo_open;
  }
  if (!r.hi_inf) {
    r.hi = a.hi + b.hi;
    r.hi_open = a.hi_open || b.hi_open;
  }
  return r;
}

bool is_point(const Range& a) { return !a.lo_inf && !a.hi_inf && a.lo == a.hi && !a.lo_open && !a.hi_open; }

// product of two ranges that are both >= 0
Range mul_nonneg(const Range& a, const Range& b) {
  Range r;
  r.lo_inf = false;
  r.lo = a.lo * b.lo;
  r.lo_open = (a.lo_open && b.lo_open) || (a.lo_open && !b.lo.is_zero()) || (b.lo_open && !a.lo.is_zero());
  r.hi_inf = a.hi_inf || b.hi_inf;
  if (!r.hi_inf) {
    r.hi = a.hi * b.hi;
    r.hi_open = (a.hi_open && b.hi_open) || (a.hi_open && !b.hi.is_zero()) || (b.hi_open && !a.hi.is_zero());
  }
  return r;
}

Range mul_range(const Range& a, const Range& b) {
  if (is_point(a) && a.lo.is_zero()) return a;
  if (is_point(b) && b.lo.is_zero()) return b;
  bool a_nn = !a.lo_inf && !a.lo.is_negative(), b_nn = !b.lo_inf && !b.lo.is_negative();
  bool a_np = !a.hi_inf && !a.hi.is_positive(), b_np = !b.hi_inf && !b.hi.is_positive();
  if (a_nn && b_nn) return mul_nonneg(a, b);
  if (a_np && b_nn) return neg_range(mul_nonneg(neg_range(a), b));
  if (a_nn && b_np) return neg_range(mul_nonneg(a, neg_range(b)));
  if (a_np && b_np) return mul_nonneg(neg_range(a), neg_range(b));
  if (a.lo_inf || a.hi_inf || b.lo_inf || b.hi_inf) return Range::all();
  numeric c[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  numeric mn = c[0], mx = c[0];
  for (auto& v : c) {
    if (v < mn) mn = v;
    if (v > mx) mx = v;
  }
  return make_range(false, mn, false, false, mx, false);
}

Range int_power_range(const Range& b, long n) {
  if (n == 0) return point_range(1);
  if (n < 0) {
    Range p = int_power_range(b, -n);
    bool neg = false;
    Range q = p;
    if (p.negative()) {
      q = neg_range(p);
      neg = true;
    } else if (!p.positive()) {
      return Range::all();
    }
    // q > 0: 1/q in [1/hi, 1/lo]
    Range r;
    r.lo_inf = false;
    if (q.hi_inf) {
      r.lo = 0;
      r.lo_open = true;
    } else {
      r.lo = 1 / q.hi;
      r.lo_open = q.hi_open;
    }
    if (q.lo.is_zero()) {
      r.hi_inf = true;
    } else {
      r.hi_inf = false;
      r.hi = 1 / q.lo;
      r.hi_open = q.lo_open;
    }
    return neg ? neg_range(r) : r;
  }
  if (n > 64) {
    // sign only: avoid huge bounds
    if (n % 2 == 0) return make_range(false, 0, b.nonzero(), true, 0, true);
    if (b.positive()) return make_range(false, 0, true, true, 0, true);
    if (b.negative()) return make_range(true, 0, true, false, 0, true);
    return Range::all();
  }
  numeric nn(n);
  auto p = [&](const numeric& x) { return GiNaC::pow(x, nn); };
  bool odd = n % 2 == 1;
  if (odd || b.nonnegative()) {
    return make_range(b.lo_inf, b.lo_inf ? 0 : p(b.lo), b.lo_open, b.hi_inf, b.hi_inf ? 0 : p(b.hi),
                      b.hi_open);
  }
  if (!b.hi_inf && !b.hi.is_positive()) {  // b <= 0, even power
    return make_range(false, p(b.hi), b.hi_open, b.lo_inf, b.lo_inf ? 0 : p(b.lo), b.lo_open);
  }
  // mixed sign, even power
  if (b.lo_inf || b.hi_inf) return make_range(false, 0, false, true, 0, true);
  numeric a = p(b.lo), c = p(b.hi);
  return make_range(false, 0, false, false, a > c ? a : c, false);
}

Range range_rec(const ex& e, const SymbolTable& ctx);

Range function_range(const GiNaC::function& f, const SymbolTable& ctx) {
  const std::string name = f.get_name();
  auto rat = [](long p, long q) { return numeric(p, q); };
  if (name == "exp") return make_range(false, 0, true, true, 0, true);
  if (name == "sin" || name == "cos") {
    // sin > 0 on (0, pi) and cos > 0 on (-pi/2, pi/2): the bounds below are rationals just
    // inside pi and pi/2, so the test is exact and errs on the side of "not evident".
    Range a = range_rec(f.op(0), ctx);
    // Bounds like pi/2 arrive as padded 40-digit enclosures: a bound within 1e-28 of pi/2 counts
    // as pi/2 itself, and then it must be open.
    numeric half_pi;
    {
      DigitsGuard g(40);
      half_pi = GiNaC::ex_to<numeric>((GiNaC::Pi / 2).evalf());
    }
    const numeric eps = pow10(-28);  // wider than constant_range's outward padding (~1e-30 relative)
    auto below = [&](const numeric& x, bool open, const numeric& bound) {
      return x < bound - eps || (GiNaC::abs(x - bound) <= eps && open);
    };
    auto above = [&](const numeric& x, bool open, const numeric& bound) {
      return x > bound + eps || (GiNaC::abs(x - bound) <= eps && open);
    };
    bool pos = false;
    if (!a.lo_inf && !a.hi_inf) {
      if (name == "sin") pos = above(a.lo, a.lo_open, 0) && below(a.hi, a.hi_open, 2 * half_pi);
      else pos = above(a.lo, a.lo_open, -half_pi) && below(a.hi, a.hi_open, half_pi);
    }
    if (pos) return make_range(false, 0, true, false, 1, false);
    return make_range(false, -1, false, false, 1, false);
  }
  if (name == "tanh") return make_range(false, -1, false, false, 1, false);
  if (name == "atan") return make_range(false, rat(-15708, 10000), true, false, rat(15708, 10000), true);
  if (name == "asin") return make_range(false, rat(-15708, 10000), false, false, rat(15708, 10000), false);
  if (name == "acos") return make_range(false, 0, false, false, rat(31416, 10000), false);
  if (name == "cosh") return make_range(false, 1, false, true, 0, true);
  if (name == "abs") {
    Range a = range_rec(f.op(0), ctx);
    return make_range(false, 0, a.nonzero(), true, 0, true);
  }
  if (name == "log") {
    Range a = range_rec(f.op(0), ctx);
    if (!a.lo_inf && a.lo >= 1) return make_range(false, 0, a.lo == 1 && a.lo_open ? true : a.lo > 1, true, 0, true);
    if (a.positive() && !a.hi_inf && a.hi <= 1)
      return make_range(true, 0, true, false, 0, a.hi < 1 || a.hi_open);
    return Range::all();
  }
  return Range::all();
}

Range range_rec(const ex& e, const SymbolTable& ctx) {
  if (GiNaC::is_a<numeric>(e)) {
    const numeric& n = GiNaC::ex_to<numeric>(e);
    if (n.is_rational()) return point_range(n);
    if (n.is_real()) return constant_range(e);
    return Range::all();
  }
  if (GiNaC::is_a<GiNaC::symbol>(e)) return bound_range_of_domain(domain_of(e, ctx));
  if (GiNaC::is_a<GiNaC::constant>(e)) return constant_range(e);
  if (GiNaC::is_a<GiNaC::add>(e)) {
    Range r = point_range(0);
    for (std::size_t i = 0; i < e.nops(); ++i) {
      r = add_range(r, range_rec(e.op(i), ctx));
      if (r.lo_inf && r.hi_inf) return r;
    }
    return r;
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    Range r = point_range(1);
    for (std::size_t i = 0; i < e.nops(); ++i) r = mul_range(r, range_rec(e.op(i), ctx));
    return r;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    Range b = range_rec(e.op(0), ctx);
    const ex& x = e.op(1);
    if (GiNaC::is_a<numeric>(x)) {
      const numeric& n = GiNaC::ex_to<numeric>(x);
      if (n.is_integer()) {
        if (GiNaC::abs(n) > 100000) return Range::all();
        return int_power_range(b, n.to_long());
      }
      if (n.is_rational()) {
        bool pos = n.is_positive();
        if (pos && !b.lo_inf && !b.lo.is_negative() && !b.hi_inf && b.hi <= 1)
          return make_range(false, 0, b.positive(), false, 1, b.hi_open);
        if (b.positive()) return make_range(false, 0, true, true, 0, true);
        if (pos && b.nonnegative()) return make_range(false, 0, false, true, 0, true);
        return Range::all();
      }
    }
    if (b.positive() && provably_real(x, ctx)) return make_range(false, 0, true, true, 0, true);
    return Range::all();
  }
  if (GiNaC::is_a<GiNaC::function>(e) && !is_abstract_application(e))
    return function_range(GiNaC::ex_to<GiNaC::function>(e), ctx);
  return Range::all();
}

}  // namespace

Range range_of(const ex& e, const SymbolTable& ctx) {
  try {
    return range_rec(e, ctx);
  } catch (const std::exception&) {
    return Range::all();
  }
}

bool provably_positive(const ex& e, const SymbolTable& ctx) {
  if (range_of(e, ctx).positive()) return true;
  return e.info(GiNaC::info_flags::positive);
}

bool provably_nonzero(const ex& e, const SymbolTable& ctx) {
  if (GiNaC::is_a<numeric>(e)) return !GiNaC::ex_to<numeric>(e).is_zero();
  if (range_of(e, ctx).nonzero()) return true;
  return e.info(GiNaC::info_flags::positive) || e.info(GiNaC::info_flags::negative);
}

bool provably_real(const ex& e, const SymbolTable& ctx) {
  if (GiNaC::is_a<numeric>(e)) return GiNaC::ex_to<numeric>(e).is_real();
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    if (ctx.find(GiNaC::ex_to<GiNaC::symbol>(e))) return true;  // table symbols are real
    return e.info(GiNaC::info_flags::real);
  }
  if (GiNaC::is_a<GiNaC::constant>(e)) return e.info(GiNaC::info_flags::real);
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!provably_real(e.op(i), ctx)) return false;
    return true;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    if (!provably_real(e.op(0), ctx) || !provably_real(e.op(1), ctx)) return false;
    if (e.op(1).info(GiNaC::info_flags::integer)) return true;
    return range_of(e.op(0), ctx).nonnegative();
  }
  if (GiNaC::is_a<GiNaC::function>(e) && !is_abstract_application(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!provably_real(e.op(i), ctx)) return false;
    static const std::set<std::string> total = {"sin", "cos", "exp", "atan", "sinh", "cosh",
                                                "tanh", "abs", "asinh", "atan2"};
    if (total.count(name)) return true;
    if (name == "log") return provably_positive(e.op(0), ctx);
    if (name == "acos" || name == "asin") return range_of(e.op(0), ctx).within(-1, 1);
    return false;
  }
  return false;
}

// ---------------------------------------------------------------- deterministic text

namespace {

bool needs_parens_as_base(const ex& b) {
  if (GiNaC::is_a<GiNaC::add>(b) || GiNaC::is_a<GiNaC::mul>(b) || GiNaC::is_a<GiNaC::power>(b)) return true;
  if (GiNaC::is_a<numeric>(b)) {
    const numeric& n = GiNaC::ex_to<numeric>(b);
    return !n.is_integer() || n.is_negative();
  }
  return false;
}

std::string strip_sign(const std::string& s) { return (!s.empty() && s[0] == '-') ? s.substr(1) : s; }

std::string factor_text(const ex& f) {
  std::string t = canon_text(f);
  if (GiNaC::is_a<GiNaC::add>(f)) return "(" + t + ")";
  return t;
}

std::string power_text(const ex& base, const ex& expo) {
  if (GiNaC::is_a<numeric>(expo)) {
    const numeric& n = GiNaC::ex_to<numeric>(expo);
    if (n == numeric(1, 2)) return "sqrt(" + canon_text(base) + ")";
    if (n == 1) return canon_text(base);
  }
  std::string b = canon_text(base);
  if (needs_parens_as_base(base)) b = "(" + b + ")";
  std::string x = canon_text(expo);
  bool simple = GiNaC::is_a<GiNaC::symbol>(expo) ||
                (GiNaC::is_a<numeric>(expo) && GiNaC::ex_to<numeric>(expo).is_nonneg_integer());
  if (!simple) x = "(" + x + ")";
  return b + "^" + x;
}

}  // namespace

std::string canon_text(const ex& e) {
  if (GiNaC::is_a<numeric>(e)) return exact_text(GiNaC::ex_to<numeric>(e));
  if (GiNaC::is_a<GiNaC::symbol>(e)) return GiNaC::ex_to<GiNaC::symbol>(e).get_name();
  if (GiNaC::is_a<GiNaC::constant>(e)) {
    if (e.is_equal(GiNaC::Pi)) return "pi";
    std::ostringstream os;
    os << e;
    return os.str();
  }
  if (GiNaC::is_a<GiNaC::add>(e)) {
    std::vector<std::string> terms;
    std::string num;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      if (GiNaC::is_a<numeric>(e.op(i)))
        num = canon_text(e.op(i));
      else
        terms.push_back(canon_text(e.op(i)));
    }
    std::sort(terms.begin(), terms.end(), [](const std::string& a, const std::string& b) {
      std::string sa = strip_sign(a), sb = strip_sign(b);
      if (sa != sb) return sa < sb;
      return a < b;
    });
    if (!num.empty()) terms.push_back(num);
    std::string s;
    for (std::size_t i = 0; i < terms.size(); ++i) {
      const std::string& t = terms[i];
      if (i == 0)
        s = t;
      else if (t[0] == '-')
        s += " - " + t.substr(1);
      else
        s += " + " + t;
    }
    return s;
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    numeric c = 1;
    std::vector<std::string> num, den;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const ex& f = e.op(i);
      if (GiNaC::is_a<numeric>(f) && GiNaC::ex_to<numeric>(f).is_rational()) {
        c *= GiNaC::ex_to<numeric>(f);
      } else if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<numeric>(f.op(1)) &&
                 GiNaC::ex_to<numeric>(f.op(1)).is_negative()) {
        ex inv = GiNaC::pow(f.op(0), -f.op(1));
        std::string t = canon_text(inv);
        if (GiNaC::is_a<GiNaC::add>(inv)) t = "(" + t + ")";
        den.push_back(t);
      } else {
        num.push_back(factor_text(f));
      }
    }
    std::sort(num.begin(), num.end());
    std::sort(den.begin(), den.end());
    std::string s = c.is_negative() ? "-" : "";
    numeric cn = GiNaC::abs(c.numer()), cd = c.denom();
    std::vector<std::string> n2;
    if (cn != 1) n2.push_back(exact_text(cn));
    for (auto& t : num) n2.push_back(t);
    std::vector<std::string> d2;
    if (cd != 1) d2.push_back(exact_text(cd));
    for (auto& t : den) d2.push_back(t);
    std::string ns;
    for (std::size_t i = 0; i < n2.size(); ++i) ns += (i ? "*" : "") + n2[i];
    if (ns.empty()) ns = "1";
    s += ns;
    if (!d2.empty()) {
      std::string ds;
      for (std::size_t i = 0; i < d2.size(); ++i) ds += (i ? "*" : "") + d2[i];
      s += "/" + (d2.size() > 1 ? "(" + ds + ")" : ds);
    }
    return s;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const ex& b = e.op(0);
    const ex& x = e.op(1);
    if (GiNaC::is_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_negative()) {
      ex inv = GiNaC::pow(b, -x);
      std::string t = canon_text(inv);
      if (GiNaC::is_a<GiNaC::add>(inv) || GiNaC::is_a<GiNaC::mul>(inv)) t = "(" + t + ")";
      return "1/" + t;
    }
    return power_text(b, x);
  }
  if (GiNaC::is_a<GiNaC::function>(e)) {
    const auto& f = GiNaC::ex_to<GiNaC::function>(e);
    std::string s;
    if (GiNaC::is_a<GiNaC::fderivative>(e)) {
      s = "D[";
      bool first = true;
      for (unsigned d : GiNaC::ex_to<GiNaC::fderivative>(e).derivatives()) {
        s += (first ? "" : ",") + std::to_string(d);
        first = false;
      }
      s += "](" + f.get_name() + ")";
    } else {
      s = f.get_name();
    }
    s += "(";
    for (std::size_t i = 0; i < e.nops(); ++i) s += (i ? ", " : "") + canon_text(e.op(i));
    return s + ")";
  }
  std::ostringstream os;
  os << e;
  return os.str();
}

namespace {
// First term of an expanded sum in canon_text order (or the expression itself).
bool leading_term_negative(const ex& e) {
  std::string t = canon_text(e);
  return !t.empty() && t[0] == '-';
}
}  // namespace

std::string residual_text(const ex& e, const SymbolTable& ctx, double max_terms) {
  try {
    ex nd = e.numer_denom();
    ex n = nd.op(0), d = nd.op(1);
    double est = estimate_expanded_terms(n) + estimate_expanded_terms(d);
    if (est > max_terms) {
      std::ostringstream os;
      os << "(residual of about " << static_cast<long long>(est) << " terms, not printed)";
      return os.str();
    }
    n = GiNaC::expand(n);
    d = GiNaC::expand(d);
    if (leading_term_negative(d)) {
      n = GiNaC::expand(-n);
      d = GiNaC::expand(-d);
    }
    if (d.is_equal(1)) return print_text(n, ctx);
    std::string ns = print_text(n, ctx), ds = print_text(d, ctx);
    if (GiNaC::is_a<GiNaC::add>(n)) ns = "(" + ns + ")";
    if (GiNaC::is_a<GiNaC::add>(d) || GiNaC::is_a<GiNaC::mul>(d)) ds = "(" + ds + ")";
    return ns + "/" + ds;
  } catch (const std::exception&) {
    return print_text(e, ctx);
  }
}

}  // namespace dc::detail
