// Deterministic text for evidence (printer.hpp): exact numbers, rounded numbers, the
// canonical order of sums and products, and residuals with a fixed sign convention.
#include <algorithm>
#include <climits>
#include <cmath>
#include <sstream>

#include <cln/float.h>
#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/real.h>

#include "derivations/symbolic/inspect.hpp"
#include "derivations/symbolic/integral_atom.hpp"
#include "derivations/symbolic/printer.hpp"

namespace dc::detail {

using GiNaC::ex;
using GiNaC::numeric;

numeric pow10(int k) { return GiNaC::pow(numeric(10), numeric(k)); }

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
    // many digits as its exponent (an allocation of petabytes).
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
  if (auto v = integral_view(e)) {
    auto end = [](const ex& x, int inf) { return inf > 0 ? std::string("oo") : inf < 0 ? std::string("-oo") : canon_text(x); };
    return "integral(" + canon_text(v->f) + ", " + canon_text(v->t) + ", " + end(v->a, v->a_inf) + ", " +
           end(v->b, v->b_inf) + ")";
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
