// Catch2 (v2) matchers for symbolic equality, decided as `derivcheck equal` decides (the claim
// as a one-step derivation, checked by the rule's code).
//
//   #include <derivcheck/catch2.hpp>      // installed package: link derivcheck::catch2
//   // (in this repository also "derivations/catch/derivcheck_catch.hpp")
//   using dc::catch2::EqualsSymbolically;
//
//   GiNaC::symbol k("k"), A("A");
//   GiNaC::ex E = GiNaC::numeric(1, 2) * k * GiNaC::pow(A, 2);
//   REQUIRE_THAT(E, EqualsSymbolically("1/2*k*A^2").assuming("k>0"));        // ex vs string
//   REQUIRE_THAT(lhs_ex, EqualsSymbolically(rhs_ex).assuming("m1>0, e in [0,1]"));  // ex vs ex
//   REQUIRE_THAT("limit((m1 - m2)*v1/(m1 + m2), m2, oo)", EqualsSymbolically("-v1").assuming("m1>0, m2>0"));
//
// Either side is a GiNaC::ex or a string in the derivation-file syntax (docs/format.md). The
// names in the strings and in the assumptions are matched to the GiNaC symbols of the ex sides
// by name (two different GiNaC symbols with the same name are an error). Every symbol is real
// unless an assumption says otherwise; assumption items are those of `derivcheck equal
// --assume`: `x>0`, `x>=0`, `x<0`, `x real`, `x in [a,b]` (and open/half-open), relations
// such as `v1 > v2`.
// On failure the description gives the right side (printed deterministically by
// dc::print_text, never GiNaC's process-dependent order), the verdict, and once each the
// counterexample point and both sides' values there, or the residual and reason when undecided;
// Catch prints the left side before it. A claim that only holds numerically passes.
//
// Header-only; link derivcheck::catch2 (derivcheck_symbolic in this repository). Also makes
// Catch print GiNaC::ex with dc::print_text.
#pragma once
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <catch2/catch.hpp>
#include <ginac/ginac.h>

#include "derivations/calculus/install.hpp"
#include "derivations/claims/claims.hpp"
#include "derivations/syntax/expr.hpp"
#include "derivations/symbolic/printer.hpp"
#include "derivations/decide/prove.hpp"
#include "derivations/symbolic/symbols.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace Catch {
template <>
struct StringMaker<GiNaC::ex> {
  static std::string convert(const GiNaC::ex& e) {
    static const dc::SymbolTable empty;
    try {
      return dc::print_text(e, empty);
    } catch (const std::exception&) {
      return "<expression>";
    }
  }
};
}  // namespace Catch

namespace dc::catch2 {

namespace detail {

// Every GiNaC symbol of `e` by name; two different symbols with one name cannot be told apart
// in the assumptions (or matched to a string), so they are an error.
inline void collect_symbol_names(const GiNaC::ex& e, std::map<std::string, GiNaC::ex>& out) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    const std::string& name = GiNaC::ex_to<GiNaC::symbol>(e).get_name();
    auto [it, inserted] = out.emplace(name, e);
    if (!inserted && !it->second.is_equal(e))
      throw std::invalid_argument("two different GiNaC symbols are both named '" + name +
                                  "'; the matcher matches symbols by name");
    return;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) collect_symbol_names(e.op(i), out);
}

// The symbol table for a claim: every name of `exprs` (plus those the assumptions mention),
// with the domains and constraints of `assume`.
inline SymbolTable table_for(const std::vector<const Node*>& exprs, const std::string& assume) {
  SourcePos where{"<assuming>", 1, 1};
  std::vector<AssumptionItem> items = parse_assumptions(assume, where);
  std::map<std::string, DomainAt> domains;
  for (const auto& it : items) {
    if (it.is_constraint) continue;
    if (domains.count(it.name))
      throw InputError(it.pos, "'" + it.name + "' is given two domains in the assumption list");
    domains[it.name] = DomainAt{it.domain, it.pos};
  }
  return claim_table(exprs, domains, items, where);
}

inline bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// The verdict and its evidence, each fact once: the prover's one-line `detail` restates the
// counterexample ("differs at m1 = ..: lhs = .., rhs = ..") or the reason, so it is printed
// only when it says something the structured fields do not.
inline std::string verdict_description(const Verdict& v) {
  std::ostringstream os;
  os << "verdict: " << to_string(v.kind);
  if (!v.method.empty()) os << " (" << v.method << ")";
  if (v.kind == VerdictKind::HoldsNumerically) {
    os << ", " << v.points << " points at " << v.digits << " digits";
    if (!v.false_accept.empty()) os << ", false accept " << v.false_accept;
  }
  std::string point;
  for (std::size_t i = 0; i < v.point.size(); ++i)
    point += (i ? ", " : "") + v.point[i].first + " = " + v.point[i].second;
  const bool detail_repeats = v.detail.empty() || v.kind == VerdictKind::HoldsNumerically ||
                              starts_with(v.detail, "differs at") || starts_with(v.detail, "the constants differ") ||
                              v.detail == v.reason || v.detail == v.reason + "; residual: " + v.residual;
  if (v.kind == VerdictKind::Refuted) {
    // A side condition's detail ("not defined ...: x != 0 (divisor) fails at x = 0") names the point.
    if (!point.empty() && (detail_repeats || v.detail.find(point) == std::string::npos))
      os << "\n  counterexample: " << point;
    if (!v.function_values.empty()) os << "\n  function values drawn there: " << v.function_values;
    if (!v.lhs_value.empty() || !v.rhs_value.empty()) os << "\n  lhs = " << v.lhs_value << "\n  rhs = " << v.rhs_value;
    if (!v.hint.empty()) os << "\n  hint: " << v.hint;
  }
  if (v.kind == VerdictKind::Undecided) {
    if (!v.residual.empty()) os << "\n  residual: " << v.residual;
    if (!v.reason.empty()) os << "\n  reason: " << v.reason;
  }
  if (!detail_repeats) os << "\n  " << v.detail;
  return os.str();
}

// What a match leaves for the description.
struct MatchOutcome {
  Verdict verdict;
  std::string rhs_text;  // the right side as printed (deterministic)
  std::string error;     // input error (malformed assumption or expression, clashing names)
};

// One side of a claim: a GiNaC expression or a string in the derivation-file syntax.
struct Side {
  bool is_text = false;
  GiNaC::ex ex;
  std::string text;
};

// Does e contain a number that is not an exact rational (a float, or I)?
inline bool has_inexact_number(const GiNaC::ex& e) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) return !GiNaC::ex_to<GiNaC::numeric>(e).is_rational();
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_inexact_number(e.op(i))) return true;
  return false;
}

// e as the derivation-syntax tree it prints as, when that reads back as e exactly; nullopt
// otherwise.
inline std::optional<Node> as_syntax(const GiNaC::ex& e, const SymbolTable& table, const char* file) {
  if (has_inexact_number(e)) return std::nullopt;
  try {
    Node n = parse_expression(print_text(e, table), SourcePos{file, 1, 1});
    if ((to_ginac(n, table) - e).is_zero()) return n;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

// Both sides in one symbol table (names matched), then the check of `derivcheck equal`: the one
// decision all overloads share. Input errors end up in out.error, never as an exception.
inline bool decide(const Side& lhs, const Side& rhs, const std::string& assume, MatchOutcome& out) {
  calculus::install();
  try {
    std::map<std::string, GiNaC::ex> syms;
    for (const Side* s : {&lhs, &rhs})
      if (!s->is_text) collect_symbol_names(s->ex, syms);
    std::vector<Node> nodes;   // the ex sides' symbols, as identifiers
    nodes.reserve(syms.size() + 2);
    for (const auto& [name, sym] : syms) {
      if (is_reserved_name(name))
        throw std::invalid_argument("a GiNaC symbol is named '" + name + "', a reserved name of the derivation syntax");
      Node n;
      n.kind = NodeKind::Symbol;
      n.text = name;
      nodes.push_back(std::move(n));
    }
    if (lhs.is_text) nodes.push_back(parse_expression(lhs.text, SourcePos{"<lhs>", 1, 1}));
    if (rhs.is_text) nodes.push_back(parse_expression(rhs.text, SourcePos{"<rhs>", 1, 1}));
    std::vector<const Node*> ptrs;
    for (const auto& n : nodes) ptrs.push_back(&n);
    SymbolTable table = table_for(ptrs, assume);
    GiNaC::exmap to_table;
    for (const auto& [name, sym] : syms)
      if (const SymbolInfo* info = table.find(name)) to_table[sym] = info->sym;
    const Node* text_node = nodes.data() + syms.size();
    const Node* lhs_node = lhs.is_text ? text_node++ : nullptr;
    const Node* rhs_node = rhs.is_text ? text_node : nullptr;
    GiNaC::ex l = lhs_node ? to_ginac(*lhs_node, table) : lhs.ex.subs(to_table);
    GiNaC::ex r = rhs_node ? to_ginac(*rhs_node, table) : rhs.ex.subs(to_table);
    out.rhs_text = print_text(r, table);
    // The claim goes the road of `derivcheck equal` and of a one-step derivation (the rule's
    // code), so a matcher and `derivcheck equal` cannot disagree. An expression side goes as
    // the derivation-syntax text it prints as, when that text reads back as the same
    // expression; one that does not (a float, a GiNaC function the syntax has no name for) is
    // decided by prove_equal directly.
    std::optional<Node> lhs_read = lhs_node ? std::optional<Node>(*lhs_node) : as_syntax(l, table, "<lhs>");
    std::optional<Node> rhs_read = rhs_node ? std::optional<Node>(*rhs_node) : as_syntax(r, table, "<rhs>");
    if (lhs_read && rhs_read) out.verdict = check_equal_in(table, *lhs_read, *rhs_read);
    else out.verdict = prove_equal(l, r, table);
    return out.verdict.holds();
  } catch (const InputError& e) {
    out.error = e.format();
  } catch (const std::exception& e) {
    out.error = e.what();
  }
  return false;
}

}  // namespace detail

// lhs == rhs under the assumptions, decided as `derivcheck equal` decides. lhs and rhs are each a GiNaC::ex
// (or anything convertible: a symbol, a number) or a string in the derivation-file syntax.
// A MatcherBase<GiNaC::ex>, so it composes with && || ! for expression arguments.
class EqualsSymbolicallyMatcher : public Catch::MatcherBase<GiNaC::ex> {
 public:
  explicit EqualsSymbolicallyMatcher(const GiNaC::ex& rhs, std::string assume = {}) : assume_(std::move(assume)) {
    rhs_.ex = rhs;
  }
  explicit EqualsSymbolicallyMatcher(std::string rhs, std::string assume = {}) : assume_(std::move(assume)) {
    rhs_.is_text = true;
    rhs_.text = std::move(rhs);
  }
  // The assumption list (replaces an earlier one): "k>0, e in [0,1], v1 > v2".
  EqualsSymbolicallyMatcher assuming(std::string assumptions) const {
    EqualsSymbolicallyMatcher m(*this);
    m.assume_ = std::move(assumptions);
    m.out_.reset();
    return m;
  }

  bool match(const GiNaC::ex& lhs) const override {
    detail::Side l;
    l.ex = lhs;
    return run(l);
  }
  bool match(const std::string& lhs) const {
    detail::Side l;
    l.is_text = true;
    l.text = lhs;
    return run(l);
  }
  bool match(const char* lhs) const { return match(std::string(lhs)); }

  // Catch shows "<lhs> " + this: the right side, the assumptions, then after a match the
  // verdict and its evidence (each once).
  std::string describe() const override {
    std::ostringstream os;
    os << "equals symbolically ";
    if (out_ && out_->error.empty()) os << out_->rhs_text;
    else if (rhs_.is_text) os << rhs_.text;
    else os << Catch::StringMaker<GiNaC::ex>::convert(rhs_.ex);
    if (!assume_.empty()) os << " assuming " << assume_;
    if (!out_) return os.str();
    if (!out_->error.empty()) os << " (not decided: " << out_->error << ")";
    else os << "\n  " << detail::verdict_description(out_->verdict);
    return os.str();
  }
  // Catch's MatcherBase caches its first description; this one is stateful (the last match),
  // so it describes afresh (a matcher reused in two assertions describes the second).
  std::string toString() const { return describe(); }

  // The verdict of the last match (for tests that inspect the evidence), or null after an
  // input error or before any match.
  const Verdict* verdict() const { return out_ && out_->error.empty() ? &out_->verdict : nullptr; }

 private:
  bool run(const detail::Side& lhs) const {
    out_ = std::make_shared<detail::MatchOutcome>();
    return detail::decide(lhs, rhs_, assume_, *out_);
  }

  detail::Side rhs_;
  std::string assume_;
  // Shared with the copy Catch keeps (it matches with the original, describes with the copy).
  mutable std::shared_ptr<detail::MatchOutcome> out_;
};

// Earlier names of the one matcher type.
using EqualsSymbolicallyEx = EqualsSymbolicallyMatcher;
using EqualsSymbolicallyText = EqualsSymbolicallyMatcher;

inline EqualsSymbolicallyMatcher EqualsSymbolically(const GiNaC::ex& rhs) { return EqualsSymbolicallyMatcher(rhs); }
inline EqualsSymbolicallyMatcher EqualsSymbolically(const std::string& rhs) { return EqualsSymbolicallyMatcher(rhs); }
inline EqualsSymbolicallyMatcher EqualsSymbolically(const char* rhs) { return EqualsSymbolicallyMatcher(std::string(rhs)); }
// A number (EqualsSymbolically(0): the literal 0 would otherwise be taken for a null const char*).
template <class T, std::enable_if_t<std::is_arithmetic_v<T>, int> = 0>
EqualsSymbolicallyMatcher EqualsSymbolically(T rhs) { return EqualsSymbolicallyMatcher(GiNaC::ex(rhs)); }

}  // namespace dc::catch2
