#include "derivations/symbolic/integral_atom.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <vector>

#include "derivations/symbolic/functions.hpp"
#include "derivations/symbolic/inspect.hpp"
#include "derivations/symbolic/printer.hpp"

namespace dc {

using GiNaC::ex;

namespace {

// One integrand, up to the name of its variable of integration: `g` in the canonical variable
// `tt`, its parameters (every other symbol of g, in the order of `params`), the ends' kinds.
struct Entry {
  std::string key;
  ex g;
  std::vector<ex> params;
  int a_inf = 0, b_inf = 0;
  std::string tname;                      // the author's name of the variable, for printing
  std::shared_ptr<const SymbolTable> table;   // names the parameters (for keys of derivatives)
};

const GiNaC::symbol& canonical_variable() {
  static const GiNaC::symbol tt("integration_variable");
  return tt;
}

std::map<std::uint64_t, Entry>& registry() {
  static std::map<std::uint64_t, Entry> r;
  return r;
}

// FNV-1a, 48 bits: an identifier that is the same in every process (it is an argument of the
// application, and the probe draws the quantity's value from its arguments).
std::uint64_t id_of(const std::string& key) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : key) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h & ((std::uint64_t{1} << 48) - 1);
}

ex derivative_of(const GiNaC::exvector& args, unsigned i);

// The GiNaC function of the applications with `nparams` parameters (arguments: id, a, b,
// parameters), registered on first use.
unsigned serial_for(std::size_t nparams) {
  static std::map<std::size_t, unsigned> serials;
  auto it = serials.find(nparams);
  if (it != serials.end()) return it->second;
  const std::string name = "dcintegral" + std::to_string(nparams);
  unsigned s = GiNaC::function::register_new(
      GiNaC::function_options(name, static_cast<unsigned>(3 + nparams)).derivative_func(derivative_of));
  serials.emplace(nparams, s);
  return s;
}

bool serial_is_ours(const ex& e) {
  return GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name().rfind("dcintegral", 0) == 0;
}

const Entry* entry_of(const ex& e) {
  if (!GiNaC::is_a<GiNaC::function>(e) || GiNaC::is_a<GiNaC::fderivative>(e)) return nullptr;
  if (!serial_is_ours(e) || e.nops() < 3) return nullptr;
  if (!GiNaC::is_a<GiNaC::numeric>(e.op(0))) return nullptr;
  const auto id = static_cast<std::uint64_t>(GiNaC::ex_to<GiNaC::numeric>(e.op(0)).to_long());
  auto it = registry().find(id);
  return it == registry().end() ? nullptr : &it->second;
}

// g with its parameters replaced by the application's arguments.
ex integrand_at(const Entry& en, const GiNaC::exvector& args) {
  GiNaC::exmap m;
  for (std::size_t k = 0; k < en.params.size() && 3 + k < args.size(); ++k) m[en.params[k]] = args[3 + k];
  return m.empty() ? en.g : en.g.subs(m, GiNaC::subs_options::no_pattern);
}

// The functions of the unknown partial derivatives (arguments: which, id, a, b, parameters),
// registered on first use without a derivative of their own. (An fderivative of the quantity's
// function would not do: GiNaC evaluates it through the registered derivative, which is
// where it came from.)
unsigned partial_serial_for(std::size_t nparams) {
  static std::map<std::size_t, unsigned> serials;
  auto it = serials.find(nparams);
  if (it != serials.end()) return it->second;
  const std::string name = "dcpartial" + std::to_string(nparams);
  unsigned s = GiNaC::function::register_new(GiNaC::function_options(name, static_cast<unsigned>(4 + nparams)));
  serials.emplace(nparams, s);
  return s;
}

bool is_unknown_partial(const ex& e) {
  return GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name().rfind("dcpartial", 0) == 0;
}

ex unknown_derivative(const GiNaC::exvector& args, unsigned i) {
  GiNaC::exvector with{GiNaC::numeric(static_cast<long>(i))};
  with.insert(with.end(), args.begin(), args.end());
  return GiNaC::function(partial_serial_for(args.size() - 3), with);
}

// Leibniz's rule where the integrand is continuous; otherwise the derivative stays unknown.
ex derivative_of(const GiNaC::exvector& args, unsigned i) {
  if (i == 0) return 0;
  const Entry* en = nullptr;
  if (!args.empty() && GiNaC::is_a<GiNaC::numeric>(args[0])) {
    auto it = registry().find(static_cast<std::uint64_t>(GiNaC::ex_to<GiNaC::numeric>(args[0]).to_long()));
    if (it != registry().end()) en = &it->second;
  }
  if (!en) return unknown_derivative(args, i);
  const GiNaC::symbol& tt = canonical_variable();
  const ex g = integrand_at(*en, args);
  if (i == 1 || i == 2) {
    if ((i == 1 && en->a_inf) || (i == 2 && en->b_inf)) return 0;   // an infinite end is no variable
    if (!continuous_everywhere(g, tt)) return unknown_derivative(args, i);
    const ex at = g.subs(GiNaC::exmap{{tt, args[i]}}, GiNaC::subs_options::no_pattern);
    return i == 1 ? ex(-at) : at;
  }
  const std::size_t k = i - 3;
  if (k >= en->params.size()) return unknown_derivative(args, i);
  try {
    const ex dg = en->g.diff(GiNaC::ex_to<GiNaC::symbol>(en->params[k]));
    if (dg.is_zero()) return 0;
    // differentiating under the integral sign needs the integrand and its derivative continuous
    // in t (psi(x)/(x - p) is neither)
    if (!continuous_everywhere(en->g, tt) || !continuous_everywhere(dg, tt)) return unknown_derivative(args, i);
    // the parameters of dg are en's: the new application is built in them, then moved to args
    ex q = integral_quantity(IntegralSpec{dg, tt, args[1], args[2], en->a_inf, en->b_inf, en->table.get()},
                             [](const ex&) -> ex { throw std::runtime_error("no closed form"); });
    GiNaC::exmap m;
    for (std::size_t p = 0; p < en->params.size() && 3 + p < args.size(); ++p) m[en->params[p]] = args[3 + p];
    return q.subs(m, GiNaC::subs_options::no_pattern);
  } catch (const std::exception&) {
    return unknown_derivative(args, i);
  }
}

// The application for one integrand that applies a declared function (no constant factor,
// no sum left to split).
ex application(const ex& g_in_t, const ex& t, const IntegralSpec& s) {
  const GiNaC::symbol& tt = canonical_variable();
  const ex g = g_in_t.subs(GiNaC::exmap{{t, tt}}, GiNaC::subs_options::no_pattern);
  std::vector<ex> params = detail::ordered_symbols(g, *s.bound);
  std::erase_if(params, [&](const ex& p) { return p.is_equal(tt); });
  std::string key = print_text(g, *s.bound) + "|" + std::to_string(s.a_inf) + "|" + std::to_string(s.b_inf);
  for (const auto& p : params) key += "|" + print_text(p, *s.bound);
  std::uint64_t id = id_of(key);
  for (std::uint64_t salt = 1;; ++salt) {   // a collision of two keys takes the next identifier
    auto it = registry().find(id);
    if (it == registry().end()) {
      std::string tname = GiNaC::is_a<GiNaC::symbol>(t) ? GiNaC::ex_to<GiNaC::symbol>(t).get_name() : "t";
      registry().emplace(id, Entry{key, g, params, s.a_inf, s.b_inf, tname, std::make_shared<SymbolTable>(*s.bound)});
      break;
    }
    if (it->second.key == key) break;
    id = id_of(key + "#" + std::to_string(salt));
  }
  GiNaC::exvector args{GiNaC::numeric(static_cast<long>(id)), s.a_inf ? ex(0) : s.a, s.b_inf ? ex(0) : s.b};
  for (const auto& p : params) args.push_back(p);
  return GiNaC::function(serial_for(params.size()), args);
}

// g = d^k/dt^k f(t) for a declared function f applied to t itself, k >= 1: its antiderivative
// d^(k-1)/dt^(k-1) f(t); nullopt otherwise.
std::optional<ex> lower_derivative(const ex& g, const ex& t) {
  if (!GiNaC::is_a<GiNaC::fderivative>(g) || pool_function_index(g) < 0 || g.nops() != 1 || !g.op(0).is_equal(t))
    return std::nullopt;
  const int k = pool_derivative_order(g);
  if (k < 1) return std::nullopt;
  ex F = apply_pool_function(pool_function_index(g), t);
  for (int i = 1; i < k; ++i) F = F.diff(GiNaC::ex_to<GiNaC::symbol>(t));
  return F;
}

// g = q(f(t)) * d/dt f(t) for a declared function f applied to t itself and q a polynomial:
// the value Q(f(b)) - Q(f(a)) with Q' = q, exactly (a polynomial is continuous everywhere, so
// the substitution u = f(t) needs nothing more of f than the smoothness declared functions
// have). nullopt otherwise.
std::optional<ex> polynomial_of_function_times_derivative(const ex& g, const ex& t, const ex& a, const ex& b) {
  std::vector<ex> factors;
  if (GiNaC::is_a<GiNaC::mul>(g))
    for (std::size_t i = 0; i < g.nops(); ++i) factors.push_back(g.op(i));
  else
    factors.push_back(g);
  for (std::size_t k = 0; k < factors.size(); ++k) {
    const ex& d = factors[k];
    if (!GiNaC::is_a<GiNaC::fderivative>(d) || pool_derivative_order(d) != 1 || d.nops() != 1 || !d.op(0).is_equal(t))
      continue;
    const ex f = apply_pool_function(pool_function_index(d), t);
    const GiNaC::symbol u("substituted_function_value");
    ex q = 1;
    for (std::size_t i = 0; i < factors.size(); ++i)
      if (i != k) q *= factors[i];
    q = q.subs(GiNaC::exmap{{f, u}}, GiNaC::subs_options::no_pattern);
    if (q.has(t) || !q.is_polynomial(u)) continue;
    const ex fa = f.subs(GiNaC::exmap{{t, a}}, GiNaC::subs_options::no_pattern);
    const ex fb = f.subs(GiNaC::exmap{{t, b}}, GiNaC::subs_options::no_pattern);
    const ex v = GiNaC::integral(u, fa, fb, q).eval_integ();
    bool residual = false;
    for (GiNaC::const_preorder_iterator it = v.preorder_begin(); it != v.preorder_end(); ++it)
      residual = residual || GiNaC::is_a<GiNaC::integral>(*it);
    if (!residual && !v.has(u)) return v;
  }
  return std::nullopt;
}

}  // namespace

bool integrand_applies_function(const ex& f, const ex& t) {
  if (detail::is_abstract_application(f) && f.has(t)) return true;
  for (std::size_t i = 0; i < f.nops(); ++i)
    if (integrand_applies_function(f.op(i), t)) return true;
  return false;
}

ex integral_quantity(const IntegralSpec& s, const std::function<ex(const ex&)>& rest) {
  if (estimate_expanded_terms(s.f) > 200) throw std::runtime_error("the integrand is too large to split into its terms");
  const ex fe = s.f.expand();
  std::vector<ex> terms;
  if (GiNaC::is_a<GiNaC::add>(fe))
    for (std::size_t i = 0; i < fe.nops(); ++i) terms.push_back(fe.op(i));
  else
    terms.push_back(fe);
  // terms with the same function part: one quantity, the sum of their constant factors
  std::map<std::string, std::pair<ex, ex>> groups;   // key: the function part's text
  ex other = 0;
  for (const ex& term : terms) {
    ex c = 1, g = 1;
    if (GiNaC::is_a<GiNaC::mul>(term)) {
      for (std::size_t i = 0; i < term.nops(); ++i) (term.op(i).has(s.t) ? g : c) *= term.op(i);
    } else {
      (term.has(s.t) ? g : c) = term;
    }
    if (!integrand_applies_function(g, s.t)) {
      other += term;
      continue;
    }
    auto [it, fresh] = groups.try_emplace(print_text(g, *s.bound), g, c);
    if (!fresh) it->second.second += c;
  }
  ex out = other.is_zero() ? ex(0) : rest(other);
  // a part with a closed form keeps it (integral(diff(psi(x), x), x, 0, L) = psi(L) - psi(0))
  for (const auto& [text, gc] : groups) {
    ex value;
    if (auto F = lower_derivative(gc.first, s.t); F && !s.a_inf && !s.b_inf) {
      // the fundamental theorem: a declared function is taken to be smooth (docs/format.md)
      value = F->subs(GiNaC::exmap{{s.t, s.b}}, GiNaC::subs_options::no_pattern) -
              F->subs(GiNaC::exmap{{s.t, s.a}}, GiNaC::subs_options::no_pattern);
      out += gc.second * value;
      continue;
    }
    if (!s.a_inf && !s.b_inf)
      if (auto v = polynomial_of_function_times_derivative(gc.first, s.t, s.a, s.b)) {
        out += gc.second * *v;
        continue;
      }
    try {
      value = rest(gc.first);
    } catch (const std::exception&) {
      value = application(gc.first, s.t, s);
    }
    out += gc.second * value;
  }
  return out;
}

bool is_integral_quantity(const ex& e) { return entry_of(e) != nullptr; }

bool has_integral_quantity(const ex& e) {
  if (is_integral_quantity(e) || is_unknown_partial(e)) return true;
  if (GiNaC::is_a<GiNaC::fderivative>(e) && serial_is_ours(e)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_integral_quantity(e.op(i))) return true;
  return false;
}

std::optional<std::pair<unsigned, ex>> unknown_partial_of(const ex& e) {
  if (!is_unknown_partial(e) || e.nops() < 4 || !GiNaC::is_a<GiNaC::numeric>(e.op(0))) return std::nullopt;
  GiNaC::exvector args(e.begin() + 1, e.end());
  const auto which = static_cast<unsigned>(GiNaC::ex_to<GiNaC::numeric>(e.op(0)).to_long());
  return std::make_pair(which, ex(GiNaC::function(serial_for(args.size() - 3), args)));
}

std::optional<IntegralView> integral_view(const ex& e) {
  const Entry* en = entry_of(e);
  if (!en) return std::nullopt;
  GiNaC::exvector args(e.begin(), e.end());
  const GiNaC::symbol t(en->tname);
  IntegralView v;
  v.f = integrand_at(*en, args).subs(GiNaC::exmap{{canonical_variable(), t}}, GiNaC::subs_options::no_pattern);
  v.t = t;
  v.a = args[1];
  v.b = args[2];
  v.a_inf = en->a_inf;
  v.b_inf = en->b_inf;
  return v;
}

}  // namespace dc
