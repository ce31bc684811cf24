// Assumptions: can they hold?
//
// Two questions, asked wherever assumptions are read (.dc `assume`, `equal --assume`, the
// `assume` field of a claims line):
//   1. One assumption on its own, decided without any symbol: its two sides differ by a
//      constant after normal() (`1 > 2`, `x > x`, `x != x`, `x < x - 1`). A false one is an
//      input error at its position; a true one (`x >= x`) is accepted and has no effect.
//   2. All of them together over the declared domains (decide_satisfiable). "Unsatisfiable" is
//      only said when it is certain: an empty domain, a constant-false assumption, single-symbol
//      linear constraints that exclude the whole declared interval of their symbol (decided
//      exactly), or two relations whose sum or ratio is a constant that contradicts them
//      (`x > y` and `y > x`). Otherwise a point is searched for: magnitudes 1e-300..1e300 on
//      both signs as the domains allow, plus points just beyond each constraint's boundary
//      (relative and absolute offsets). A point that is found is checked exactly (rational
//      arithmetic) or at two precisions; when none is found the answer is "unknown", and the
//      reason says how hard it looked rather than claiming the assumptions never hold.
#pragma once
#include <cstdint>
#include <string>

#include <ginac/ginac.h>

#include "derivations/symbolic/symbols.hpp"

namespace dc {

enum class ConstantTruth {
  NotConstant,  // the sides differ by an expression with symbols: a real constraint
  True,         // always holds (x >= x): no effect
  False,        // never holds (1 > 2, x > x, x != x), or its sides are not real numbers
  Undecidable,  // a constant, but its sign is not decided at 200 digits
};
ConstantTruth constant_truth(const Constraint& c);

// The one check every assumption passes as it is read: throws InputError at c.pos (underlining
// `length` characters) "the assumption 'x > x' can never hold" when constant_truth is False,
// and "the assumption '...' compares two constants whose order cannot be decided" when
// Undecidable.
void require_possible_assumption(const Constraint& c, int length);

struct Satisfiability {
  enum class Status { Satisfiable, Unsatisfiable, Unknown };
  Status status = Status::Satisfiable;
  std::string reason;   // empty when satisfiable
  int tries = 0;        // points tried
  GiNaC::exmap point;   // a point satisfying every constraint (when found by search)
};
Satisfiability decide_satisfiable(const SymbolTable& ctx, std::uint64_t seed = 20261121);

// The user-facing error text for a result that is not Satisfiable: "the assumptions cannot all
// hold (REASON)" when certain, "no point found that satisfies all assumptions after N tries
// over magnitudes 1e-300..1e300 (...)" otherwise.
std::string unsatisfiable_message(const Satisfiability& s);

}  // namespace dc
