// The outcome of checking one claim. Never a bare yes/no.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace dc {

enum class VerdictKind { Proved, HoldsNumerically, Refuted, Undecided };

const char* to_string(VerdictKind k);   // "proved", "holds_numerically", "refuted", "undecided"

// A condition a step needs (divisor != 0, log argument > 0, acos argument in [-1,1], ...).
struct SideCondition {
  std::string what;          // "m1 + m2 != 0", text printed deterministically
  std::string reason;        // "divisor", "log argument", "sqrt argument", "acos argument"
  enum class Status { Guaranteed, Violated, Unknown } status = Status::Unknown;
  std::string evidence;      // "m1, m2 positive", or the point where it fails
  std::vector<std::pair<std::string, std::string>> point;   // Violated: the point (name = exact value)
};

struct Verdict {
  VerdictKind kind = VerdictKind::Undecided;
  // Which method decided: "normal", "expand (transcendental)", "side relations",
  // "numeric probe", "lsolve", "series", ... For Undecided: the method that got furthest.
  std::string method;
  // Human-readable evidence, one line, deterministic (no GiNaC print order).
  std::string detail;

  // HoldsNumerically / Refuted: numeric evidence.
  int points = 0;            // sample points that agreed
  int digits = 0;            // working precision (decimal digits)
  double max_rel_diff = 0;   // largest relative difference seen
  std::string false_accept;  // stated chance of a false accept, e.g. "< 1e-40 per point (...)"

  // Refuted: the counterexample (symbol = exact value, in declaration order) and both sides.
  std::vector<std::pair<std::string, std::string>> point;
  std::string lhs_value, rhs_value;

  // Undecided: residual (deterministic text) and the reason.
  std::string residual;
  std::string reason;

  std::vector<SideCondition> side_conditions;

  // Refuted: the declaration under which the claim would hold, when one was found
  // ("holds if a, b are positive: declare a, b positive").
  std::string hint;

  bool holds() const { return kind == VerdictKind::Proved || kind == VerdictKind::HoldsNumerically; }
};

}  // namespace dc
