// Symbols, domains, abstract applications and expansion size (inspect.hpp).
#include "derivations/symbolic/inspect.hpp"
#include "derivations/symbolic/verdict.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

namespace dc::detail {

using GiNaC::ex;
using GiNaC::numeric;

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

}  // namespace dc::detail

namespace dc {

using GiNaC::ex;
using GiNaC::numeric;


// ------------------------------------------------------------------ resource estimate

namespace {

// Terms of expand(e), and the worst intermediate (function arguments are expanded too).
double estimate_rec(const ex& e, double& worst) {
  double r = 1;
  if (GiNaC::is_a<GiNaC::add>(e)) {
    r = 0;
    for (std::size_t i = 0; i < e.nops(); ++i) r += estimate_rec(e.op(i), worst);
  } else if (GiNaC::is_a<GiNaC::mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i) r *= estimate_rec(e.op(i), worst);
  } else if (GiNaC::is_a<GiNaC::power>(e)) {
    double k = estimate_rec(e.op(0), worst);
    const ex& x = e.op(1);
    if (GiNaC::is_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_pos_integer()) {
      const numeric& nn = GiNaC::ex_to<numeric>(x);
      double n = nn.to_double();
      if (k > 1) {
        // multinomial: C(n + k - 1, k - 1) monomials, each coefficient with ~n*log10(k) digits
        double log_terms = std::lgamma(n + k) - std::lgamma(k) - std::lgamma(n + 1);
        double digits_weight = std::max(1.0, n * std::log10(k) / 20.0);
        r = std::exp(std::min(log_terms, 700.0)) * digits_weight;
      } else if (GiNaC::is_a<GiNaC::mul>(e.op(0))) {
        r = 1;
        for (std::size_t i = 0; i < e.op(0).nops(); ++i)
          r *= estimate_rec(GiNaC::pow(e.op(0).op(i), x), worst);
      } else {
        r = 1;
      }
    } else {
      r = 1;  // negative or symbolic powers stay unexpanded; the base is expanded
      worst = std::max(worst, k);
    }
  } else if (e.nops() > 0) {
    for (std::size_t i = 0; i < e.nops(); ++i) worst = std::max(worst, estimate_rec(e.op(i), worst));
    r = 1;
  }
  worst = std::max(worst, r);
  return r;
}

}  // namespace

double estimate_expanded_terms(const ex& e) {
  double worst = 1;
  double r = estimate_rec(e, worst);
  return std::max(r, worst);
}

bool names_symbol(const std::string& text, const std::string& name) {
  auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t p = text.find(name); p != std::string::npos; p = text.find(name, p + 1)) {
    const bool before = p == 0 || !ident(text[p - 1]);
    const bool after = p + name.size() >= text.size() || !ident(text[p + name.size()]);
    if (before && after) return true;
  }
  return false;
}

bool continuous_everywhere(const GiNaC::ex& e, const GiNaC::symbol& x) {
  if (!e.has(x)) return true;
  if (e.is_equal(x)) return true;
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!continuous_everywhere(e.op(i), x)) return false;
    return true;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const GiNaC::ex& n = e.op(1);
    if (n.has(x)) {
      // c^(g(x)) with a constant positive base c would do; only exp is accepted (below).
      return false;
    }
    return GiNaC::is_a<GiNaC::numeric>(n) && GiNaC::ex_to<GiNaC::numeric>(n).is_nonneg_integer() &&
           continuous_everywhere(e.op(0), x);
  }
  if (GiNaC::is_a<GiNaC::function>(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if (name != "exp" && name != "sin" && name != "cos" && name != "atan" && !detail::is_abstract_application(e))
      return false;
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!continuous_everywhere(e.op(i), x)) return false;
    return true;
  }
  return false;
}

}  // namespace dc
