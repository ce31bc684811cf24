// Helpers for the prove tests: a SymbolTable built from (name, domain) pairs.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/decide/prove.hpp"
#include "derivations/symbolic/symbols.hpp"

namespace dc::test {

struct Table {
  SymbolTable t;
  GiNaC::ex operator[](const std::string& name) const { return t.find(name)->sym; }
  // A reference, never a copy: copying a realsymbol/possymbol into a GiNaC::symbol slices it.
  const GiNaC::symbol& sym(const std::string& name) const { return GiNaC::ex_to<GiNaC::symbol>(t.find(name)->sym); }
  Table& add(const std::string& name, Domain d) {
    SymbolInfo info;
    info.name = name;
    info.domain = std::move(d);
    info.pos = SourcePos{"<test>", 1, 1};
    t.declare(std::move(info));
    return *this;
  }
  Table& assume(GiNaC::ex lhs, Constraint::Op op, GiNaC::ex rhs, std::string text) {
    Constraint c{lhs, rhs, op, std::move(text), SourcePos{"<test>", 1, 1}};
    t.add_constraint(std::move(c));
    return *this;
  }
};

inline Domain unit_interval(bool lo_open = false, bool hi_open = false) {
  return Domain::interval(0, lo_open, 1, hi_open);
}

}  // namespace dc::test

namespace dc::test {

// One line describing a verdict, for CAPTURE and the determinism test.
inline std::string describe(const Verdict& v) {
  std::string s = std::string(to_string(v.kind)) + " | " + v.method + " | " + v.detail;
  if (!v.reason.empty()) s += " | reason: " + v.reason;
  if (!v.residual.empty()) s += " | residual: " + v.residual;
  for (const auto& [name, value] : v.point) s += " | " + name + "=" + value;
  if (!v.false_accept.empty()) s += " | " + v.false_accept;
  return s;
}

}  // namespace dc::test
