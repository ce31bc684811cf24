// to_ginac: the author's tree -> GiNaC, with strict symbols and resource limits;
// dimension_of: the SI dimension of the tree.
//
// Both walk left-nested chains (a + b - c + ..., a*b/c*...) in a loop, so recursion follows
// only the nesting the parser already limited (max_depth), never the length of a chain.
//
// Resource limits (design notes §2: 2^(10^8) took 13.6 s in GiNaC, 2^(10^10) runs away,
// (a+b)^100000 expands past 20 s). A power is refused, with the error at the exponent, when
//  * the base is not a number and |exponent| > 1000, or
//  * the base is a rational number, the exponent an integer, and the result would have more
//    than 10000 decimal digits (estimated as |n| * log10(max(|num|, den)) from bit lengths), or
//  * the exponent is a non-integer number with |exponent| > 1000.
// Nested exponents are checked bottom-up, so 2^(10^(10^10)) fails at the inner power.
#include <algorithm>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>
#include <cln/integer.h>
#include <ginac/ginac.h>

#include "derivations/syntax/expr.hpp"
#include "derivations/symbolic/functions.hpp"
#include "derivations/syntax/literal.hpp"
#include "derivations/syntax/source.hpp"
#include "derivations/symbolic/calculus_hooks.hpp"
#include "derivations/symbolic/differential.hpp"
#include "derivations/symbolic/inspect.hpp"
#include "derivations/symbolic/integral_atom.hpp"
#include "derivations/symbolic/symbols.hpp"
#include "derivations/symbolic/vectors.hpp"
#include "derivations/syntax/units.hpp"

namespace dc {

namespace {

constexpr long kMaxResultDigits = 10000;
constexpr int kMaxDiffOrder = 100;

const char* kBuiltinList = "sqrt, exp, log, ln, sin, cos, tan, asin, acos, atan, abs, diff, limit, integral";

bool one_arg_builtin(const std::string& name) {
  static const std::set<std::string> names = {"sqrt", "exp", "log", "ln", "sin", "cos",
                                              "tan",  "asin", "acos", "atan", "abs"};
  return names.count(name) > 0;
}

std::string short_text(const Node& n) {
  std::string s = to_text(n);
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

// "10000000000", "1/3", or "with 12345 digits" for huge values.
std::string number_text(const GiNaC::numeric& x) {
  std::ostringstream os;
  os << x;
  std::string s = os.str();
  if (s.size() > 40) return "of " + std::to_string(s.size()) + " characters";
  return s;
}

// O(...) is not a function or symbol of the file: it only ends a series claim (big_o.hpp).
[[noreturn]] void misplaced_order_term(const Node& n) {
  throw InputError(n.pos,
                   "an order term O(...) may only end the last side of a 'by series' step "
                   "('sin(x) = x - x^3/6 + O(x^5)') or the rhs of a series claim",
                   1);
}

// The table's names of one kind (symbols or functions), in declaration order: candidates for
// "did you mean".
std::vector<std::string> names_of(const SymbolTable& table, bool functions) {
  std::vector<std::string> out;
  for (const auto& s : table.all())
    if (s.is_function == functions && !s.is_differential) out.push_back(s.name);
  if (!functions) out.push_back("pi");
  return out;
}

const SymbolInfo& lookup_symbol(const Node& n, const SymbolTable& table) {
  const SymbolInfo* info = table.find(n.text);
  if (!info && n.text == "O") misplaced_order_term(n);
  if (!info)
    throw InputError(n.pos,
                     "undefined symbol '" + n.text + "'" + did_you_mean(n.text, names_of(table, false)) +
                         ": declare it with 'symbol " + n.text +
                         " : DOMAIN [UNIT]' or define it in an earlier step",
                     n.length);
  if (info->is_function) {
    std::string params;
    for (std::size_t i = 0; i < info->params.size(); ++i) params += (i ? ", " : "") + info->params[i];
    throw InputError(n.pos, "'" + n.text + "' is a function of " + params + "; write " + n.text + "(" + params + ")",
                     n.length);
  }
  return *info;
}

[[noreturn]] void bad_arg_count(const Node& n, const std::string& expected) {
  throw InputError(n.pos,
                   n.text + "(...) takes " + expected + ", got " + std::to_string(n.args.size()), n.length);
}

void check_count(const Node& n, std::size_t lo, std::size_t hi, const std::string& expected) {
  if (n.args.size() < lo || n.args.size() > hi) bad_arg_count(n, expected);
}

// The variable of diff/limit/integral: a declared (non-function) symbol written plainly.
const SymbolInfo& variable_arg(const Node& call, const Node& arg, const SymbolTable& table) {
  if (arg.kind != NodeKind::Symbol || arg.text == "pi" || arg.text == "deg" || arg.text == "oo")
    throw InputError(arg.pos, "the second argument of " + call.text + "(...) must be a declared symbol, found '" +
                                  short_text(arg) + "'",
                     arg.length);
  return lookup_symbol(arg, table);
}

int diff_order(const Node& call) {
  if (call.args.size() < 3) return 1;
  const Node& a = call.args[2];
  if (a.kind != NodeKind::Number || a.text.find('.') != std::string::npos)
    throw InputError(a.pos, "the order of diff(f, x, n) must be a positive integer, found '" + short_text(a) + "'",
                     a.length);
  GiNaC::numeric k = exact_literal(a.text);
  if (k < 1 || k > kMaxDiffOrder)
    throw InputError(a.pos,
                     "derivative order " + number_text(k) + " is out of range (1 to " + std::to_string(kMaxDiffOrder) +
                         ")",
                     a.length);
  return static_cast<int>(k.to_int());
}

// +1 / -1 when the node is oo / -oo (possibly parenthesized), else 0.
int infinity_sign(const Node& n) {
  if (n.kind == NodeKind::Symbol && n.text == "oo") return 1;
  if (n.kind == NodeKind::Neg) return -infinity_sign(n.args[0]);
  return 0;
}

const SymbolInfo& declared_function(const Node& n, const SymbolTable& table) {
  const SymbolInfo* info = table.find(n.text);
  if (!info && n.text == "O") misplaced_order_term(n);
  if (!info)
    throw InputError(n.pos,
                     "unknown function '" + n.text + "'" + did_you_mean(n.text, [&] {
                       auto c = names_of(table, true);
                       for (const char* b : {"sqrt", "exp", "log", "ln", "sin", "cos", "tan", "asin", "acos", "atan",
                                             "abs", "diff", "limit", "integral"})
                         c.push_back(b);
                       return c;
                     }()) + ": built-in functions are " + kBuiltinList +
                         "; declare others with 'function " + n.text + "(t) : DOMAIN [UNIT]'",
                     static_cast<int>(n.text.size()));
  if (!info->is_function)
    throw InputError(n.pos, "'" + n.text + "' is a symbol, not a function; write " + n.text + "*(...) for a product",
                     static_cast<int>(n.text.size()));
  if (n.args.size() != info->params.size()) {
    std::string params;
    for (std::size_t i = 0; i < info->params.size(); ++i) params += (i ? ", " : "") + info->params[i];
    bad_arg_count(n, std::to_string(info->params.size()) + " argument" + (info->params.size() == 1 ? "" : "s") +
                         " (" + params + ")");
  }
  return *info;
}

// ---- to_ginac ------------------------------------------------------------------------------

class Converter {
 public:
  explicit Converter(const SymbolTable& table) : table_(table) {}

  GiNaC::ex conv(const Node& n) {
    switch (n.kind) {
      case NodeKind::Number:
        return exact_literal(n.text);
      case NodeKind::Symbol:
        if (n.text == "pi") return GiNaC::Pi;
        if (n.text == "deg") return GiNaC::Pi / 180;   // degrees: 30*deg = pi/6
        if (n.text == "oo")
          throw InputError(n.pos, "'oo' (infinity) may only appear as the point of limit(f, x, oo) or as a limit of integration", n.length);
        return lookup_symbol(n, table_).sym;
      case NodeKind::Add:
      case NodeKind::Sub:
        return sum_chain(n);
      case NodeKind::Mul:
      case NodeKind::Div:
        return product_chain(n);
      case NodeKind::Neg: {
        GiNaC::ex a = conv(n.args[0]);
        return guarded(n, [&] { return -a; });
      }
      case NodeKind::Pow:
        return power(n);
      case NodeKind::Call:
        return call(n);
    }
    throw InputError(n.pos, "malformed expression");
  }

 private:
  static bool is_integral_call(const Node& n) { return n.kind == NodeKind::Call && n.text == "integral"; }

  // The parts of integral(f, t, a, b): f in the fresh variable of integration t (integrand_of),
  // the table t belongs to, a, b.
  struct IntegralParts {
    SymbolTable bound;
    GiNaC::ex f, t, a, b;
    int a_inf = 0, b_inf = 0;   // -1 / +1: that limit of integration is -oo / oo (a, b are 0 then)
    bool negate = false;        // written from oo (or to -oo): the limits were exchanged
  };
  IntegralParts integral_parts(const Node& n) {
    check_count(n, 4, 4, "4 arguments: integral(f, x, a, b)");
    variable_arg(n, n.args[1], table_);
    const int a_inf = infinity_sign(n.args[2]), b_inf = infinity_sign(n.args[3]);
    if (a_inf != 0 && a_inf == b_inf)
      throw UndecidedLimit("'" + short_text(n) + "': both limits of integration are infinite on the same side", n.pos);
    Integrand in = integrand_of(n, table_);
    IntegralParts p{std::move(in.table), in.f, in.x, a_inf ? GiNaC::ex(0) : conv(n.args[2]),
                    b_inf ? GiNaC::ex(0) : conv(n.args[3]), a_inf, b_inf};
    // the potential's integral(F, s, oo, r) is -integral(F, s, r, oo)
    if (a_inf > 0 || b_inf < 0) {
      std::swap(p.a, p.b);
      std::swap(p.a_inf, p.b_inf);
      p.negate = true;
    }
    return p;
  }

  // A definite integral inside an expression: a polynomial integrand on a finite interval exactly
  // (GiNaC; eval_integ would also "integrate" 1/x across 0, so nothing else goes there), any
  // other by an antiderivative proved by differentiation and continuous on (a, b), with the limits
  // at the ends (derivations/calculus/definite.hpp). Otherwise, or when the integral diverges,
  // the claim is undecided with the reason.
  GiNaC::ex integral_value(const Node& n, const IntegralParts& p) {
    // an integrand that applies a declared function: a quantity of its own (integral_atom.hpp)
    if (integrand_applies_function(p.f, p.t)) {
      GiNaC::ex v;
      try {
        v = integral_quantity(IntegralSpec{p.f, p.t, p.a, p.b, p.a_inf, p.b_inf, &p.bound},
                              [&](const GiNaC::ex& part) { return integrand_value(n, p, part); });
      } catch (const UndecidedLimit&) {
        throw;
      } catch (const InputError&) {
        throw;
      } catch (const std::exception& e) {
        throw UndecidedLimit("'" + short_text(n) + "' inside an expression was not evaluated: " + e.what(), n.pos);
      }
      return p.negate ? GiNaC::ex(-v) : v;
    }
    const GiNaC::ex v = integrand_value(n, p, p.f);
    return p.negate ? GiNaC::ex(-v) : v;
  }

  // The value of the integral of `f` (the integrand or a part of it) between p's limits, before
  // p.negate is applied.
  GiNaC::ex integrand_value(const Node& n, const IntegralParts& p, const GiNaC::ex& f) {
    if (f.is_polynomial(p.t) && !p.a_inf && !p.b_inf) {
      GiNaC::ex v = guarded(n, [&] { return GiNaC::integral(p.t, p.a, p.b, f).eval_integ(); });
      bool residual = false;
      for (GiNaC::const_preorder_iterator it = v.preorder_begin(); it != v.preorder_end(); ++it)
        residual = residual || GiNaC::is_a<GiNaC::integral>(*it);
      if (!residual) return v;
    }
    if (!calculus_hooks().definite)
      throw UndecidedLimit("'" + short_text(n) + "' inside an expression was not evaluated: no integral method is installed (dc::calculus::install())", n.pos);
    const integrals::Definite d =
        calculus_hooks().definite(f, GiNaC::ex_to<GiNaC::symbol>(p.t), p.a, p.a_inf, p.b, p.b_inf, p.bound);
    using K = integrals::Definite::Kind;
    if (d.kind == K::Value) return d.value;
    if (d.kind == K::Diverges)
      throw UndecidedLimit("'" + short_text(n) + "' diverges" +
                               (d.infinite > 0 ? " to oo" : d.infinite < 0 ? " to -oo" : "") + " (" + d.evidence + ")",
                           n.pos);
    if (d.kind == K::DoesNotExist)
      throw UndecidedLimit("'" + short_text(n) + "' does not exist (" + d.evidence + ")", n.pos);
    throw UndecidedLimit("'" + short_text(n) + "' inside an expression was not evaluated: " + d.why, n.pos);
  }

  // eval_between(F, x, a, b), the evaluation bar [F]_a^b: F(b) - F(a). x is bound (F is read
  // with x a fresh real symbol, as an integrand is, so nothing declared of the quantity x
  // simplifies F); an end may contain the quantity x (`eval_between(F, t, 0, t)`). An end oo or
  // -oo is the limit of F there (calculus/limit_entry through the hook); a limit that does not
  // exist, is infinite or is not decided leaves the claim undecided with the reason.
  GiNaC::ex eval_between(const Node& n) {
    check_count(n, 4, 4, "4 arguments: eval_between(F, x, a, b), the bar [F] from x = a to x = b");
    const SymbolInfo& x = variable_arg(n, n.args[1], table_);
    const SymbolTable bound = table_.with_bound_variable(x.name);
    const GiNaC::ex xb = bound.find(x.name)->sym;
    const GiNaC::ex F = Converter(bound).conv(n.args[0]);
    auto at = [&](const Node& e) -> GiNaC::ex {
      const int inf = infinity_sign(e);
      if (inf == 0) {
        const GiNaC::ex v = conv(e);
        return guarded(n, [&] { return F.subs(GiNaC::exmap{{xb, v}}); }, &e.pos);
      }
      const std::string what = "'" + short_text(n) + "' at " + x.name + " = " + (inf > 0 ? "oo" : "-oo");
      if (!calculus_hooks().limit)
        throw UndecidedLimit(what + ": no limit method is installed (dc::calculus::install())", n.pos);
      LimitResult r;
      try {
        r = calculus_hooks().limit(F, GiNaC::ex_to<GiNaC::symbol>(xb), 0, inf, bound);
      } catch (const InputError&) {
        throw;
      } catch (const std::exception&) {
        throw UndecidedLimit(what + ": the limit helper could not evaluate it", n.pos);
      }
      if (!r.ok)
        throw UndecidedLimit(what + ": " + (r.reason.empty() ? "the limit is undecided" : r.reason), n.pos);
      if (r.infinite != 0)
        throw UndecidedLimit(what + ": the limit is " + (r.infinite > 0 ? "+" : "-") + "infinity, not a value", n.pos);
      return r.value;
    };
    const GiNaC::ex hi = at(n.args[3]), lo = at(n.args[2]);
    return guarded(n, [&] { return hi - lo; });
  }

  // d/dx of integral(f, t, a, b) = f(b) db/dx - f(a) da/dx (Leibniz's rule) when f does not
  // contain x and is continuous in t on the whole line; nullopt otherwise (then the integral
  // must have a value of its own, and that is differentiated).
  std::optional<GiNaC::ex> leibniz(const Node& in, const IntegralParts& p, const GiNaC::symbol& x) {
    // otherwise the integral's own value (if it has one) is differentiated
    if (p.a_inf || p.b_inf || p.f.has(x) || p.t.is_equal(x) ||
        !continuous_everywhere(p.f, GiNaC::ex_to<GiNaC::symbol>(p.t)))
      return std::nullopt;
    return guarded(in, [&] {
      return p.f.subs(p.t == p.b) * p.b.diff(x) - p.f.subs(p.t == p.a) * p.a.diff(x);
    });
  }

  // GiNaC reports 1/0, 0^0, log(0), tan(pi/2) by exceptions whose texts name its internals;
  // they become positioned input errors in our words.
  template <class F>
  GiNaC::ex guarded(const Node& n, F&& f, const SourcePos* where = nullptr) {
    try {
      return f();
    } catch (const InputError&) {
      throw;
    } catch (const UndecidedLimit&) {
      throw;
    } catch (const std::exception& e) {
      std::string what = e.what();
      std::string msg;
      if (what.find("division by zero") != std::string::npos)
        msg = "division by zero in '" + short_text(n) + "'";
      else if (what.find("0^0") != std::string::npos || what.find("pow(0,0)") != std::string::npos)
        msg = "0^0 is undefined";
      else if (dynamic_cast<const GiNaC::pole_error*>(&e))
        msg = "'" + short_text(n) + "' is undefined (a pole)";
      else
        msg = "cannot evaluate '" + short_text(n) + "'";
      throw InputError(where ? *where : n.pos, msg, where ? 1 : n.length);
    }
  }

  GiNaC::ex sum_chain(const Node& n) {
    std::vector<const Node*> spine;
    const Node* cur = &n;
    while (cur->kind == NodeKind::Add || cur->kind == NodeKind::Sub) {
      spine.push_back(cur);
      cur = &cur->args[0];
    }
    GiNaC::exvector terms;
    terms.reserve(spine.size() + 1);
    terms.push_back(conv(*cur));
    for (auto it = spine.rbegin(); it != spine.rend(); ++it) {
      GiNaC::ex r = conv((*it)->args[1]);
      terms.push_back((*it)->kind == NodeKind::Add ? r : guarded(**it, [&] { return -r; }));
    }
    return guarded(n, [&] { return GiNaC::ex(GiNaC::add(terms)); });
  }

  GiNaC::ex product_chain(const Node& n) {
    std::vector<const Node*> spine;
    const Node* cur = &n;
    while (cur->kind == NodeKind::Mul || cur->kind == NodeKind::Div) {
      spine.push_back(cur);
      cur = &cur->args[0];
    }
    GiNaC::exvector factors;
    factors.reserve(spine.size() + 1);
    factors.push_back(conv(*cur));
    for (auto it = spine.rbegin(); it != spine.rend(); ++it) {
      const Node& op = **it;
      GiNaC::ex r = conv(op.args[1]);
      if (op.kind == NodeKind::Div) {
        if (r.is_zero()) throw InputError(op.op_pos, "division by zero: '" + short_text(op.args[1]) + "' is 0");
        factors.push_back(guarded(op, [&] { return GiNaC::pow(r, -1); }, &op.op_pos));
      } else {
        factors.push_back(r);
      }
    }
    return guarded(n, [&] { return GiNaC::ex(GiNaC::mul(factors)); });
  }

  GiNaC::ex power(const Node& n) {
    GiNaC::ex base = conv(n.args[0]);
    GiNaC::ex expo = conv(n.args[1]);
    const Node& en = n.args[1];
    if (GiNaC::is_a<GiNaC::numeric>(expo)) {
      const GiNaC::numeric ne = GiNaC::ex_to<GiNaC::numeric>(expo);
      const GiNaC::numeric mag = GiNaC::abs(ne);
      if (GiNaC::is_a<GiNaC::numeric>(base) && ne.is_integer()) {
        const GiNaC::numeric nb = GiNaC::ex_to<GiNaC::numeric>(base);
        if (nb.is_rational() && !nb.is_zero() && GiNaC::abs(nb) != 1) {
          // digits(b^n) ~ |n| * log10(max(|num|, den)); bit lengths give log2 within 1.
          long bits = std::max(cln::integer_length(cln::the<cln::cl_I>(nb.numer().to_cl_N())),
                               cln::integer_length(cln::the<cln::cl_I>(nb.denom().to_cl_N())));
          GiNaC::numeric digits = mag * GiNaC::numeric(bits - 1) * GiNaC::numeric(30103, 100000);
          if (digits > kMaxResultDigits)
            throw InputError(en.pos,
                             "exponent " + number_text(ne) + " is too large: the result would have about " +
                                 number_text(GiNaC::iquo(digits.numer(), digits.denom())) +
                                 " digits (limit " + std::to_string(kMaxResultDigits) + ")",
                             en.length);
        }
      }
      // A symbolic base with a huge exponent (x^(10^30)) is a valid expression; what it costs
      // to work with is bounded by the step's time and memory budgets, not by a cap here.
    }
    // 0^0 and 0^(negative) are refused before GiNaC::pow: GiNaC allocates the power object and
    // then throws from its evaluation, and that object is never freed. The messages are the ones
    // guarded() gives for GiNaC's exceptions.
    if (base.is_zero() && GiNaC::is_a<GiNaC::numeric>(expo)) {
      const GiNaC::numeric& ne = GiNaC::ex_to<GiNaC::numeric>(expo);
      if (ne.is_zero()) throw InputError(n.pos, "0^0 is undefined", n.length);
      if (ne.real().is_negative()) throw InputError(n.pos, "division by zero in '" + short_text(n) + "'", n.length);
    }
    return guarded(n, [&] { return GiNaC::pow(base, expo); });
  }

  GiNaC::ex call(const Node& n) {
    const std::string& f = n.text;
    if (is_differential_call(n, table_)) return differential_value(n, table_, n.args[0].kind == NodeKind::Call ? conv(n.args[0]) : 0);
    if (f == "pm" || f == "mp") {
      check_count(n, 1, 2, "1 or 2 arguments");
      const int chosen = plus_minus_sign();
      if (chosen == 0)
        throw InputError(n.pos, std::string("'") + (f == "pm" ? "\u00B1" : "\u2213") +
                                    "' has two values here; only a step's check reads it, once with each sign", n.length);
      const int sign = f == "pm" ? chosen : -chosen;
      const GiNaC::ex b = conv(n.args.back());
      const GiNaC::ex a = n.args.size() == 2 ? conv(n.args[0]) : GiNaC::ex(0);
      return sign > 0 ? a + b : a - b;
    }
    if (one_arg_builtin(f)) {
      check_count(n, 1, 1, "1 argument");
      GiNaC::ex a = conv(n.args[0]);
      return guarded(n, [&]() -> GiNaC::ex {
        if (f == "sqrt") return GiNaC::sqrt(a);
        if (f == "exp") return GiNaC::exp(a);
        if (f == "log" || f == "ln") return GiNaC::log(a);
        if (f == "sin") return GiNaC::sin(a);
        if (f == "cos") return GiNaC::cos(a);
        if (f == "tan") return GiNaC::tan(a);
        if (f == "asin") return GiNaC::asin(a);
        if (f == "acos") return GiNaC::acos(a);
        if (f == "atan") return GiNaC::atan(a);
        return GiNaC::abs(a);
      });
    }
    if (f == "diff") {
      check_count(n, 2, 3, "2 or 3 arguments: diff(f, x) or diff(f, x, n)");
      const SymbolInfo& x = variable_arg(n, n.args[1], table_);
      if (x.domain.integer)
        throw InputError(n.args[1].pos, "cannot differentiate with respect to '" + x.name + "': it is declared " +
                                            x.domain.to_string(), n.args[1].length);
      int order = diff_order(n);
      GiNaC::ex body;
      if (is_integral_call(n.args[0])) {
        const IntegralParts parts = integral_parts(n.args[0]);
        if (order == 1)
          if (auto d = leibniz(n.args[0], parts, GiNaC::ex_to<GiNaC::symbol>(x.sym))) return *d;
        body = integral_value(n.args[0], parts);
      } else {
        body = conv(n.args[0]);
      }
      return guarded(n, [&] { return body.diff(GiNaC::ex_to<GiNaC::symbol>(x.sym), static_cast<unsigned>(order)); });
    }
    if (f == "limit") {
      check_count(n, 3, 3, "3 arguments: limit(f, x, point)");
      const SymbolInfo& x = variable_arg(n, n.args[1], table_);
      const GiNaC::symbol& xs = GiNaC::ex_to<GiNaC::symbol>(x.sym);
      int at_inf = infinity_sign(n.args[2]);
      GiNaC::ex point = 0;
      if (at_inf == 0) {
        point = conv(n.args[2]);
        if (point.has(xs))
          throw InputError(n.args[2].pos, "the limit point must not contain the variable '" + x.name + "'",
                           n.args[2].length);
      }
      GiNaC::ex body = conv(n.args[0]);
      LimitResult r;
      try {
        if (!calculus_hooks().limit)
          throw UndecidedLimit("'" + short_text(n) + "': no limit method is installed (dc::calculus::install())", n.pos);
        r = calculus_hooks().limit(body, xs, point, at_inf, table_);
      } catch (const InputError&) {
        throw;
      } catch (const std::exception&) {
        // The helper reports failures as !ok; anything thrown is GiNaC's, whose text names
        // its internals, so it is not passed on.
        throw UndecidedLimit("the limit helper could not evaluate '" + short_text(n) + "'", n.pos);
      }
      if (!r.ok) throw UndecidedLimit(r.reason.empty() ? "limit undecided" : r.reason, n.pos);
      // not an input error: `limit(1/(1 - x), x, 1) = oo  by limit x -> 1` is a true claim the
      // limit rule checks; as a value inside an expression it leaves the claim undecided
      if (r.infinite != 0)
        throw UndecidedLimit("'" + short_text(n) + "' is " + (r.infinite > 0 ? "+" : "-") +
                                 "infinity and cannot be used as a value",
                             n.pos);
      return r.value;
    }
    if (f == "eval_between") return eval_between(n);
    if (f == "integral" && n.args.size() == 2) {
      variable_arg(n, n.args[1], table_);
      (void)conv(n.args[0]);
      throw UndecidedLimit("'" + short_text(n) + "' is an indefinite integral, defined up to a constant: it has no "
                           "value inside an expression; as a whole side, integral(f, x) = F claims dF/dx = f",
                           n.pos);
    }
    if (f == "integral") return integral_value(n, integral_parts(n));
    const SymbolInfo& info = declared_function(n, table_);
    if (info.params.size() != 1)
      throw InputError(n.pos, "functions of several variables are not supported", n.length);
    int index = table_.function_index(f);
    if (index < 0 || index >= kFunctionPoolSize)
      throw InputError(n.pos,
                       "too many declared functions: at most " + std::to_string(kFunctionPoolSize) + " are supported",
                       n.length);
    GiNaC::ex a = conv(n.args[0]);
    return apply_pool_function(index, a);
  }

  const SymbolTable& table_;
};

// ---- dimension_of --------------------------------------------------------------------------

// The exact value of a constant exponent (numbers with + - * / and parentheses), or false.
bool constant_number(const Node& n, GiNaC::numeric& out) {
  switch (n.kind) {
    case NodeKind::Number:
      out = exact_literal(n.text);
      return true;
    case NodeKind::Neg:
      if (!constant_number(n.args[0], out)) return false;
      out = -out;
      return true;
    case NodeKind::Add:
    case NodeKind::Sub:
    case NodeKind::Mul:
    case NodeKind::Div: {
      GiNaC::numeric a, b;
      if (!constant_number(n.args[0], a) || !constant_number(n.args[1], b)) return false;
      if (n.kind == NodeKind::Add) out = a + b;
      else if (n.kind == NodeKind::Sub) out = a - b;
      else if (n.kind == NodeKind::Mul) out = a * b;
      else if (b.is_zero()) return false;
      else out = a / b;
      return true;
    }
    default:
      return false;
  }
}

class Dimensioner {
 public:
  explicit Dimensioner(const SymbolTable& table) : table_(table) {}

  Dimension dim(const Node& n) {
    switch (n.kind) {
      case NodeKind::Number:
        return {};
      case NodeKind::Symbol: {
        if (n.text == "pi" || n.text == "deg") return {};
        if (n.text == "oo")
          throw InputError(n.pos, "'oo' (infinity) may only appear as the point of limit(f, x, oo) or as a limit of integration", n.length);
        const SymbolInfo& info = lookup_symbol(n, table_);
        return info.has_dimension ? info.dimension : Dimension();
      }
      case NodeKind::Add:
      case NodeKind::Sub:
        return sum_chain(n);
      case NodeKind::Mul:
      case NodeKind::Div:
        return product_chain(n);
      case NodeKind::Neg:
        return dim(n.args[0]);
      case NodeKind::Pow:
        return power(n);
      case NodeKind::Call:
        return call(n);
    }
    throw InputError(n.pos, "malformed expression");
  }

 private:
  // A literal 0 has every dimension (v = 0, x + 0): it adopts its neighbours'.
  Dimension sum_chain(const Node& n) {
    std::vector<const Node*> spine;
    const Node* cur = &n;
    while (cur->kind == NodeKind::Add || cur->kind == NodeKind::Sub) {
      spine.push_back(cur);
      cur = &cur->args[0];
    }
    bool known = !is_literal_zero(*cur);
    Dimension acc = known ? dim(*cur) : Dimension();
    for (auto it = spine.rbegin(); it != spine.rend(); ++it) {
      const Node& op = **it;
      const Node& right = op.args[1];
      if (is_literal_zero(right)) continue;
      Dimension r = dim(right);
      if (!known) {
        acc = r;
        known = true;
      } else if (r != acc) {
        if (op.kind == NodeKind::Add)
          throw InputError(op.op_pos, "cannot add " + acc.to_string() + " and " + r.to_string());
        throw InputError(op.op_pos, "cannot subtract " + r.to_string() + " from " + acc.to_string());
      }
    }
    return acc;
  }

  Dimension product_chain(const Node& n) {
    std::vector<const Node*> spine;
    const Node* cur = &n;
    while (cur->kind == NodeKind::Mul || cur->kind == NodeKind::Div) {
      spine.push_back(cur);
      cur = &cur->args[0];
    }
    Dimension acc = dim(*cur);
    for (auto it = spine.rbegin(); it != spine.rend(); ++it) {
      Dimension r = dim((*it)->args[1]);
      acc = (*it)->kind == NodeKind::Mul ? acc * r : acc / r;
      if (!acc.representable())
        throw InputError((*it)->op_pos, "the dimension of this product is not representable (an exponent's numerator and "
                                        "denominator must stay below 10^6)");
    }
    return acc;
  }

  Dimension power(const Node& n) {
    Dimension b = dim(n.args[0]);
    const Node& en = n.args[1];
    Dimension e = dim(en);
    if (!e.dimensionless())
      throw InputError(en.pos, "an exponent must be dimensionless, got " + e.to_string(), en.length);
    if (b.dimensionless()) return b;
    GiNaC::numeric q;
    if (!constant_number(en, q))
      throw InputError(en.pos,
                       "the exponent of a quantity with dimension " + b.to_string() +
                           " must be a constant number, found '" + short_text(en) + "'",
                       en.length);
    Dimension out;
    bool ok = GiNaC::abs(q.numer()) < 1000000 && q.denom() < 1000000 && b.pow(q.numer().to_int(), q.denom().to_int(), out);
    if (!ok)
      throw InputError(en.pos,
                       b.to_string() + " raised to " + number_text(q) +
                           " is not a dimension (an exponent's numerator and denominator must stay below 10^6)",
                       en.length);
    return out;
  }

  void require_dimensionless(const Node& call, const Node& arg) {
    Dimension d = dim(arg);
    if (!d.dimensionless())
      throw InputError(arg.pos, "argument of " + call.text + " must be dimensionless, got " + d.to_string(), arg.length);
  }

  void require_same(const Node& arg, const Dimension& want, const std::string& what) {
    if (is_literal_zero(arg) || infinity_sign(arg) != 0) return;
    Dimension d = dim(arg);
    if (d != want)
      throw InputError(arg.pos, what + " must have dimension " + want.to_string() + ", got " + d.to_string(),
                       arg.length);
  }

  Dimension call(const Node& n) {
    const std::string& f = n.text;
    if (is_differential_call(n, table_)) return dim(n.args[0]);
    if ((f == "pm" || f == "mp") && (n.args.size() == 1 || n.args.size() == 2)) {   // as a + b, or -b
      Node as = n;
      as.kind = n.args.size() == 2 ? NodeKind::Add : NodeKind::Neg;
      as.text.clear();
      return dim(as);
    }
    if (one_arg_builtin(f)) {
      check_count(n, 1, 1, "1 argument");
      if (f == "sqrt") {
        Dimension a = dim(n.args[0]);
        Dimension out;
        if (!a.pow(1, 2, out))
          throw InputError(n.pos, "the square root of " + a.to_string() + " is not a dimension (an exponent's numerator and denominator must stay below 10^6)",
                           n.length);
        return out;
      }
      if (f == "abs") return dim(n.args[0]);
      require_dimensionless(n, n.args[0]);
      return {};
    }
    if (f == "diff") {
      check_count(n, 2, 3, "2 or 3 arguments: diff(f, x) or diff(f, x, n)");
      const SymbolInfo& x = variable_arg(n, n.args[1], table_);
      int order = diff_order(n);
      Dimension d = dim(n.args[0]);
      Dimension xd = x.has_dimension ? x.dimension : Dimension();
      for (int i = 0; i < order; ++i) d = d / xd;
      return d;
    }
    if (f == "limit") {
      check_count(n, 3, 3, "3 arguments: limit(f, x, point)");
      const SymbolInfo& x = variable_arg(n, n.args[1], table_);
      require_same(n.args[2], x.has_dimension ? x.dimension : Dimension(), "the limit point of " + x.name);
      return dim(n.args[0]);
    }
    if (f == "eval_between") {
      check_count(n, 4, 4, "4 arguments: eval_between(F, x, a, b), the bar [F] from x = a to x = b");
      const SymbolInfo& x = variable_arg(n, n.args[1], table_);
      const Dimension xd = x.has_dimension ? x.dimension : Dimension();
      require_same(n.args[2], xd, "the lower end of eval_between over " + x.name);
      require_same(n.args[3], xd, "the upper end of eval_between over " + x.name);
      return dim(n.args[0]);
    }
    if (f == "integral") {
      check_count(n, 2, 4, "integral(f, x) or integral(f, x, a, b)");
      if (n.args.size() == 3) bad_arg_count(n, "integral(f, x) or integral(f, x, a, b)");
      const SymbolInfo& x = variable_arg(n, n.args[1], table_);
      Dimension xd = x.has_dimension ? x.dimension : Dimension();
      if (n.args.size() == 4) {
        require_same(n.args[2], xd, "the lower bound of the integral over " + x.name);
        require_same(n.args[3], xd, "the upper bound of the integral over " + x.name);
      }
      return dim(n.args[0]) * xd;
    }
    const SymbolInfo& info = declared_function(n, table_);
    for (std::size_t i = 0; i < n.args.size() && i < info.params.size(); ++i) {
      const SymbolInfo* p = table_.find(info.params[i]);
      if (p && p->has_dimension)
        require_same(n.args[i], p->dimension, "the argument of " + f + " (" + info.params[i] + ")");
      else
        dim(n.args[i]);  // still checks the argument itself
    }
    return info.has_dimension ? info.dimension : Dimension();
  }

  const SymbolTable& table_;
};

}  // namespace

GiNaC::ex to_ginac(const Node& n, const SymbolTable& table) {
  return Converter(table).conv(has_vector_notation(n, table) ? scalar_form(n, table) : n);   // vectors.hpp
}

Integrand integrand_of(const Node& n, const SymbolTable& table) {
  check_count(n, 4, 4, "4 arguments: integral(f, x, a, b)");
  const SymbolInfo& x = variable_arg(n, n.args[1], table);
  for (int i : {2, 3})
    if (infinity_sign(n.args[i]) == 0 && Converter(table).conv(n.args[i]).has(x.sym))
      throw InputError(n.pos, "a limit of integration contains the variable of integration", n.length);
  Integrand out{table.with_bound_variable(x.name), GiNaC::ex(), GiNaC::ex()};
  out.x = out.table.find(x.name)->sym;
  out.f = Converter(out.table).conv(n.args[0]);
  return out;
}

Dimension dimension_of(const Node& n, const SymbolTable& table) {
  if (!has_vector_notation(n, table)) return Dimensioner(table).dim(n);
  const int k = vector_shape(n, table);   // a vector's dimension: that of every component
  const Dimension d = Dimensioner(table).dim(k ? vector_component(n, table, 1) : scalar_form(n, table));
  for (int i = 2; i <= k; ++i)
    if (Dimensioner(table).dim(vector_component(n, table, i)) != d)
      throw InputError(n.pos, "the components of a vector must have one dimension (the first is " + d.to_string() + ")", n.length);
  return d;
}

namespace { CalculusHooks g_calculus_hooks; }  // namespace

void set_calculus_hooks(const CalculusHooks& hooks) { g_calculus_hooks = hooks; }
const CalculusHooks& calculus_hooks() { return g_calculus_hooks; }

bool is_literal_zero(const Node& n) {
  if (n.kind == NodeKind::Neg) return is_literal_zero(n.args[0]);
  return n.kind == NodeKind::Number && n.text.find_first_not_of("0.") == std::string::npos;
}

}  // namespace dc
