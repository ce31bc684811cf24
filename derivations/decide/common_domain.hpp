// A claim whose sides are undefined at the same points (issue 23, item 2):
//   1/(sqrt(a^2 - b) + a) = (a - sqrt(a^2 - b))/b   with a, b positive
// is undefined on both sides where b > a^2. A point where every side is undefined as a real is
// not evidence of anything. A violated side condition refutes only at a point where one side is
// defined and another is not; where the sides are undefined on the same set, the identity holds
// on that common domain and the condition is reported with the assumption that makes it hold
// everywhere.
#pragma once
#include <map>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/syntax/expr.hpp"
#include "derivations/symbolic/symbols.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace dc {

// One side of a claim as the author wrote it: every function application, power and quotient
// converted on its own (side_conditions_of_tree's parts) and the side's own conditions.
struct WrittenSide {
  GiNaC::ex value;   // the side converted (for the value shown at a counterexample)
  GiNaC::lst parts;
  std::vector<SideCondition> conditions;
};

// side_conditions_of_tree (prove.hpp) that also hands back the parts it converted (prove.cpp).
std::vector<SideCondition> side_conditions_of_tree_parts(const Node& n, const SymbolTable& ctx,
                                                         const std::string& free_of, GiNaC::lst& parts);

// For each condition text of side_conditions(e): a key that is equal for conditions that are
// the same up to a constant factor which leaves them unchanged (x - 1 > 0 and 2*x - 2 > 0),
// prove.cpp.
std::map<std::string, std::string> side_condition_keys(const GiNaC::ex& e, const SymbolTable& ctx);

// Is a side with these parts defined at p, as side conditions read it? -1: a condition of a
// part is certainly violated there (or a part certainly has no real value); +1: every condition
// certainly holds and every part has a certified real value; 0: not decided (prove.cpp).
// `ctx` (optional) says which symbols are integers (x^n with n integer needs no positive x).
int defined_at_point(const GiNaC::lst& parts, const GiNaC::exmap& p, const SymbolTable* ctx = nullptr);

// For a verdict that holds and has a violated side condition (a point of the declared domain
// where some side is certainly undefined):
//   - at a point where one side is certainly defined and another certainly undefined (the
//     violated condition's point, or one of up to 48 further points of the domain): refuted
//     there, with the defined side's value;
//   - every side certainly undefined at every violating point, and the sides' conditions that
//     the declarations do not guarantee are the same list (then they are defined on the same
//     set) and a point where every side is defined is found (the common domain is not
//     empty): the verdict stands on the common domain; the condition is reported, with the hint
//     to assume it (not for the base of a power with a symbolic exponent: (x^a)^b is real at
//     x = -1, a = 2 although x^a counts as undefined for x < 0);
//   - otherwise undecided: the points seen are not evidence either way.
// With fewer than two sides this is require_defined_on_domain.
void require_defined_on_common_domain(Verdict& v, const std::vector<WrittenSide>& sides, const SymbolTable& ctx);

}  // namespace dc
