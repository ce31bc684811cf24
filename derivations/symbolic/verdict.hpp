// The outcome of checking one claim. Never a bare yes/no.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace dc {

enum class VerdictKind { Proved, HoldsNumerically, Refuted, Undecided };

// The one spelling of each verdict: to_string for JSON and claim banks ("proved",
// "holds_numerically", "refuted", "undecided"), verdict_words for text and LaTeX ("holds
// numerically").
const char* to_string(VerdictKind k);
const char* verdict_words(VerdictKind k);

// Exit codes of every command (stable; docs/cli.md): 0 everything holds, 1 something refuted
// (or a step in error), 2 an input error, 3 something undecided, 4 an internal error.
constexpr int kExitOk = 0;
constexpr int kExitRefuted = 1;
constexpr int kExitInputError = 2;
constexpr int kExitUndecided = 3;
constexpr int kExitInternal = 4;
// The exit code of one verdict (`derivcheck equal`).
int exit_code_of(VerdictKind k);

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
  // What the two values are, when not the claim's two sides: "limit" and "claimed" for a
  // limit step (the limit of the expression against the written value). Empty: "left side",
  // "right side".
  std::string lhs_label, rhs_label;
  // Refuted where the sides apply declared functions (f(b), diff(theta(t), t)): the values the
  // probe drew for those applications at the point, "f(b) = -0.0465893", without which the
  // point alone does not show why the sides differ.
  std::string function_values;

  // Undecided: residual (deterministic text) and the reason.
  std::string residual;
  std::string reason;

  std::vector<SideCondition> side_conditions;

  // Refuted: the declaration under which the claim would hold, when one was found
  // ("holds if a, b are positive: declare a, b positive").
  std::string hint;

  bool holds() const { return kind == VerdictKind::Proved || kind == VerdictKind::HoldsNumerically; }
};

// How prove_equal and the kernel's probe work: which stages run, how many points must agree,
// at what precision. The defaults are the contract of docs/soundness.md.
struct ProveOptions {
  bool symbolic = true;         // run stages 1-3
  bool numeric = true;          // run stage 4
  int probe_points = 10;        // points that must agree (six ordinary, four at extreme magnitudes or interval ends)
  int digits = 50;              // working precision of the probe
  double rel_tol_exponent = -30;  // agree when |a-b| <= 10^exp * max(|a|,|b|,1e-300)
  std::uint64_t seed = 20261121;  // fixed: verdicts are deterministic
  std::size_t max_terms = 1000000;  // resource limit for expand/normal (estimated first)
  // when an elimination leaves a point that fails a reference, eliminate once more with the
  // references in another order (steps/follows.cpp); a search that tries many sets turns it off
  bool reorder_references = true;
};

// Guards GiNaC::Digits (a process-wide global) for the lifetime of the guard.
class DigitsGuard {
 public:
  explicit DigitsGuard(long digits);
  ~DigitsGuard();
  DigitsGuard(const DigitsGuard&) = delete;
  DigitsGuard& operator=(const DigitsGuard&) = delete;

 private:
  long saved_;
};

}  // namespace dc
