// The two calculus values that to_ginac needs inside an expression — limit(f, x, p) and
// integral(f, x, a, b) — come from the calculus library, which sits above this folder (it uses
// the decision kernel). It hands them down through these hooks: dc::calculus::install() sets them,
// and every entry point above the calculus folder (the readers, the claim bank, the CLI, the
// Catch2 matchers) calls it. Without it, a limit or definite integral inside an expression is
// undecided with a reason that says so; nothing is guessed.
#pragma once
#include <string>

#include <ginac/ginac.h>

#include "derivations/symbolic/symbols.hpp"

namespace dc {

struct LimitResult {
  bool ok = false;        // a limit was found: `value`, or an infinity (`infinite`)
  GiNaC::ex value;        // the finite limit (may contain parameters); 0 when infinite
  int infinite = 0;       // +1 / -1: the limit is +infinity / -infinity
  // Certified that the limit does not exist (one-sided limits differ, oscillation, f has no
  // real value near the point). ok is false then (callers that only know ok/value stay safe)
  // and `reason` says why.
  bool does_not_exist = false;
  int dir = 0;            // the direction asked for: +1 from above, -1 from below, 0 two-sided
  std::string method;     // the evidence: "Gruntz (mrv), mu -> 0+", "..., both one-sided limits agree"
  std::string reason;     // when !ok: why it is undecided (or why it does not exist)
  bool confirmed_numerically = false;  // Arb balls along a sequence approaching the point agree
  std::string numeric_note;            // what the sequence showed (also when not confirmed)
};

namespace integrals {

struct Definite {
  enum class Kind { Value, Diverges, DoesNotExist, Unknown } kind = Kind::Unknown;
  GiNaC::ex value;         // Kind::Value
  int infinite = 0;        // Kind::Diverges: +1 / -1 when the sign is known, else 0
  std::string evidence;    // the antiderivative, the conditions and the end limits
  std::string why;         // Kind::Unknown: why not decided
};

}  // namespace integrals

struct CalculusHooks {
  // compute_limit, two-sided (calculus/limit_entry.hpp)
  LimitResult (*limit)(const GiNaC::ex& f, const GiNaC::symbol& x, const GiNaC::ex& point, int at_infinity,
                       const SymbolTable& ctx) = nullptr;
  // integrals::definite_integral (calculus/definite.hpp)
  integrals::Definite (*definite)(const GiNaC::ex& f, const GiNaC::symbol& x, const GiNaC::ex& a, int a_inf,
                                  const GiNaC::ex& b, int b_inf, const SymbolTable& ctx) = nullptr;
};

void set_calculus_hooks(const CalculusHooks& hooks);
const CalculusHooks& calculus_hooks();

}  // namespace dc
