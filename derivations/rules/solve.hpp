// Internals of `by solve` shared by solve.cpp and solve_roots.cpp.
#pragma once
#include <string>
#include <vector>

#include "derivations/steps/context.hpp"

namespace dc::rules {

// The unknowns of the rule, each a symbol (expressions such as sin(theta) get stand-ins).
struct Unknowns {
  std::vector<ex> syms;
  GiNaC::exmap standin, standback;
  ex in(StepContext& c, const ex& e) const { return c.atoms(e).subs(standin, GiNaC::subs_options::no_pattern); }
  ex out(StepContext& c, const ex& e) const {
    return c.atoms.restore(e.subs(standback, GiNaC::subs_options::no_pattern));
  }
};

// Is G, the claimed value of the unknown x = u.syms[which], the only value of x in its
// declared domain that the equations `eqs` (stand-in form, with their labels) allow? `elim`: the other unknowns and
// the intermediate quantities, eliminated first. Proved when an equation in x alone is strictly
// monotonic in x on its domain, or when every other root of it (it is polynomial in x: the
// cofactor of x - G) is excluded by the domains or equals G; Refuted with a certified point
// (the parameters, x = the other root, satisfying the references) where another root lies in
// the domain; otherwise Undecided with the reason. `note` says how (for the derived text).
Verdict only_root(StepContext& c, const Unknowns& u, const std::vector<Eq>& eqs, std::size_t which, const ex& G,
                  const std::vector<ex>& elim, std::string& note);

}  // namespace dc::rules
