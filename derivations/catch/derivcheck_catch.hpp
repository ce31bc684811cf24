// Catch2 (v2) matchers for symbolic equality, decided by dc::prove_equal.
//
//   #include "derivations/catch/derivcheck_catch.hpp"
//   using dc::catch2::EqualsSymbolically;
//
//   GiNaC::symbol m1("m1"), m2("m2"), v1("v1");
//   REQUIRE_THAT(lhs_ex, EqualsSymbolically(rhs_ex).assuming("m1>0, m2>0, e in [0,1]"));
//   REQUIRE_THAT("limit((m1 - m2)*v1/(m1 + m2), m2, oo)", EqualsSymbolically("-v1").assuming("m1>0, m2>0"));
//
// Expressions are GiNaC::ex (symbols matched to the assumptions by name) or strings in the
// derivation-file syntax (docs/format.md). Every symbol is real unless an assumption says
// otherwise; assumption items are those of `derivcheck equal --assume`: `x>0`, `x>=0`, `x<0`,
// `x real`, `x in [a,b]` (and open/half-open), relations such as `v1 > v2`.
// On failure the description prints both sides deterministically (dc::print_text, never
// GiNaC's process-dependent order), the verdict, and the counterexample point with both
// values, or the residual and reason when undecided. A claim that only holds numerically
// passes (the description states the points and digits).
//
// Header-only; link against derivcheck_symbolic. Also makes Catch print GiNaC::ex with
// dc::print_text.
#pragma once
#include <map>
#include <memory>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <ginac/ginac.h>

#include "derivations/core/claims.hpp"
#include "derivations/core/expr.hpp"
#include "derivations/core/printer.hpp"
#include "derivations/core/prove.hpp"
#include "derivations/core/symbols.hpp"
#include "derivations/core/verdict.hpp"

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

inline void collect_symbol_names(const GiNaC::ex& e, std::map<std::string, GiNaC::ex>& out) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    out.emplace(GiNaC::ex_to<GiNaC::symbol>(e).get_name(), e);
    return;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) collect_symbol_names(e.op(i), out);
}

// The symbol table for a claim: every name in `names` (plus those the assumptions mention),
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

inline std::string verdict_description(const Verdict& v) {
  std::ostringstream os;
  os << "verdict: " << to_string(v.kind);
  if (!v.method.empty()) os << " (" << v.method << ")";
  if (v.kind == VerdictKind::HoldsNumerically)
    os << ", " << v.points << " points at " << v.digits << " digits" << (v.false_accept.empty() ? "" : ", false accept " + v.false_accept);
  if (v.kind == VerdictKind::Refuted) {
    os << "\n  counterexample:";
    for (std::size_t i = 0; i < v.point.size(); ++i)
      os << (i ? ", " : " ") << v.point[i].first << " = " << v.point[i].second;
    os << "\n  lhs = " << v.lhs_value << "\n  rhs = " << v.rhs_value;
  }
  if (v.kind == VerdictKind::Undecided) {
    if (!v.residual.empty()) os << "\n  residual: " << v.residual;
    if (!v.reason.empty()) os << "\n  reason: " << v.reason;
  }
  if (!v.detail.empty()) os << "\n  " << v.detail;
  return os.str();
}

// What both matchers share: the claim's assumptions, the verdict, the printed sides.
struct Outcome {
  Verdict verdict;
  std::string lhs_text, rhs_text;
  std::string error;   // input error (malformed assumption, expression)
};

// Both sides printed deterministically, then the verdict of prove_equal: the one decision the
// matchers share.
inline bool decide(const GiNaC::ex& a, const GiNaC::ex& b, const SymbolTable& table, Outcome& out) {
  out.lhs_text = print_text(a, table);
  out.rhs_text = print_text(b, table);
  out.verdict = prove_equal(a, b, table);
  return out.verdict.holds();
}

}  // namespace detail

// lhs (GiNaC::ex) == rhs, decided by prove_equal under the assumptions.
class EqualsSymbolicallyEx : public Catch::MatcherBase<GiNaC::ex> {
 public:
  explicit EqualsSymbolicallyEx(GiNaC::ex rhs, std::string assume = {}) : rhs_(std::move(rhs)), assume_(std::move(assume)) {}
  EqualsSymbolicallyEx assuming(std::string assumptions) const { return EqualsSymbolicallyEx(rhs_, std::move(assumptions)); }

  bool match(const GiNaC::ex& lhs) const override {
    out_ = std::make_shared<detail::Outcome>();
    try {
      std::map<std::string, GiNaC::ex> syms;
      detail::collect_symbol_names(lhs, syms);
      detail::collect_symbol_names(rhs_, syms);
      std::vector<Node> nodes;
      for (const auto& [name, s] : syms) {
        Node n;
        n.kind = NodeKind::Symbol;
        n.text = name;
        nodes.push_back(n);
      }
      std::vector<const Node*> ptrs;
      for (const auto& n : nodes) ptrs.push_back(&n);
      SymbolTable table = detail::table_for(ptrs, assume_);
      GiNaC::exmap to_table;
      for (const auto& [name, s] : syms)
        if (const SymbolInfo* info = table.find(name)) to_table[s] = info->sym;
      return detail::decide(lhs.subs(to_table), rhs_.subs(to_table), table, *out_);
    } catch (const InputError& e) {
      out_->error = e.format();
    } catch (const std::exception& e) {
      out_->error = e.what();
    }
    return false;
  }

  std::string describe() const override {
    std::ostringstream os;
    if (out_ && !out_->error.empty()) {
      os << "equals symbolically (not decided: " << out_->error << ")";
      return os.str();
    }
    os << "equals symbolically " << (out_ ? out_->rhs_text : Catch::StringMaker<GiNaC::ex>::convert(rhs_));
    if (!assume_.empty()) os << " assuming " << assume_;
    if (out_) os << "\n  lhs: " << out_->lhs_text << "\n  rhs: " << out_->rhs_text << "\n  "
                 << detail::verdict_description(out_->verdict);
    return os.str();
  }

  // The verdict of the last match (for tests that inspect the evidence).
  const Verdict* verdict() const { return out_ && out_->error.empty() ? &out_->verdict : nullptr; }

 private:
  GiNaC::ex rhs_;
  std::string assume_;
  mutable std::shared_ptr<detail::Outcome> out_;
};

// lhs (an expression in the derivation-file syntax) == rhs (same syntax).
class EqualsSymbolicallyText : public Catch::MatcherBase<std::string> {
 public:
  explicit EqualsSymbolicallyText(std::string rhs, std::string assume = {}) : rhs_(std::move(rhs)), assume_(std::move(assume)) {}
  EqualsSymbolicallyText assuming(std::string assumptions) const { return EqualsSymbolicallyText(rhs_, std::move(assumptions)); }

  bool match(const std::string& lhs) const override {
    out_ = std::make_shared<detail::Outcome>();
    try {
      Node l = parse_expression(lhs, SourcePos{"<lhs>", 1, 1});
      Node r = parse_expression(rhs_, SourcePos{"<rhs>", 1, 1});
      SymbolTable table = detail::table_for({&l, &r}, assume_);
      return detail::decide(to_ginac(l, table), to_ginac(r, table), table, *out_);
    } catch (const InputError& e) {
      out_->error = e.format();
    } catch (const std::exception& e) {
      out_->error = e.what();
    }
    return false;
  }

  std::string describe() const override {
    std::ostringstream os;
    if (out_ && !out_->error.empty()) {
      os << "equals symbolically " << rhs_ << " (not decided: " << out_->error << ")";
      return os.str();
    }
    os << "equals symbolically " << rhs_;
    if (!assume_.empty()) os << " assuming " << assume_;
    if (out_) os << "\n  lhs: " << out_->lhs_text << "\n  rhs: " << out_->rhs_text << "\n  "
                 << detail::verdict_description(out_->verdict);
    return os.str();
  }

  const Verdict* verdict() const { return out_ && out_->error.empty() ? &out_->verdict : nullptr; }

 private:
  std::string rhs_;
  std::string assume_;
  mutable std::shared_ptr<detail::Outcome> out_;
};

inline EqualsSymbolicallyEx EqualsSymbolically(const GiNaC::ex& rhs) { return EqualsSymbolicallyEx(rhs); }
inline EqualsSymbolicallyText EqualsSymbolically(const std::string& rhs) { return EqualsSymbolicallyText(rhs); }
inline EqualsSymbolicallyText EqualsSymbolically(const char* rhs) { return EqualsSymbolicallyText(rhs); }

}  // namespace dc::catch2
