// Cross-check: every formula of a derivation evaluated by each fast method (double, long
// double, and the file's stable form where one is declared with `stable LABEL "regime"`)
// against the CLN reference, at seeded random points in the declared domains plus stress
// points that drive each symbol to the edges of its domain and pairs of like symbols
// towards each other. Errors are in units in the last place of double at the reference
// value, with the reference evaluated at exactly the (rounded) double inputs, so the error is
// the method's own rounding error, not input rounding.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/reader/derivation.hpp"
#include "numeric/compensated.hpp"
#include "numeric/evaluator.hpp"
#include "numeric/formula_evaluator.hpp"

namespace dc::num {

struct CrossCheckOptions {
  std::uint64_t seed = 20261121;
  int points = 200;         // random points per formula (stress points come on top)
  bool stress = true;
  int digits = 40;          // reference precision
  double typical_decades = 2;  // positive symbols: 10^U(-d, d)
  int only_formula = -1;       // >= 0: check only formulas(d)[only_formula] (one worker task)
};

struct MethodStats {
  std::string method;       // "double", "long double", "stable" (the FormulaEvaluator in
                            // EvalMode::Fast: the stable form in its regime, the formula
                            // elsewhere), "compensated" (the same tapes in double-double)
  std::size_t points = 0;
  std::size_t stress_points = 0;
  double median_ulps = 0, max_ulps = 0;
  double max_ulps_random = 0, max_ulps_stress = 0;
  std::size_t non_finite = 0;  // inf/NaN where the reference is finite
  std::vector<std::pair<std::string, std::string>> worst_point;  // name, value (17 digits)
  std::string worst_kind;      // "random" or the stress description
};

struct FormulaReport {
  std::string file, label, target;
  std::string stable_label;    // the step declared `stable <this label>` (empty if none)
  std::string stable_regime;
  std::size_t in_regime = 0;   // points where the stable form was used
  std::string stable_of;       // this formula is itself the stable form of ...
  std::string skipped;         // non-empty: why it is not evaluated (e.g. abstract functions)
  std::size_t rejected = 0;    // candidate points outside constraints or where undefined
  // of those: points where the formula is defined but its value is not a finite double (it
  // overflows): no method can be right there, so they are left out of every summary
  std::size_t reference_not_double = 0;
  std::vector<MethodStats> methods;
};

std::vector<FormulaReport> crosscheck(const Derivation& d, const CrossCheckOptions& opt);

// Why a derivation has no formula crosscheck can evaluate (formulas(d) is empty): its results
// are functions of t (`x(t) = ...`), or no step has the form `y = expression`. format_crosscheck
// prints a report with an empty label and this as `skipped` under the file's name.
std::string no_formula_reason(const Derivation& d);

// The points crosscheck() evaluates one formula at (same seed, domains, constraints and stress
// points), each with its CLN reference at opt.digits. x in the order of f.params; kind is
// "random" or the stress description. Used by the closed-form work-precision charts.
struct SamplePoint {
  std::vector<double> x;
  std::string kind;
  GiNaC::numeric ref;
};
std::vector<SamplePoint> crosscheck_points(const Derivation& d, const Formula& f, const CrossCheckOptions& opt);

// The method with the smallest max error among those that return a double ("double", "stable",
// "compensated"; "long double" is not a double result). nullptr if none was evaluated.
// Regime: over all points, over the random points only, or over the stress points only (a
// method that overflows at one stress point is not the worst everywhere).
enum class Regime { All, Random, Stress };
const MethodStats* best_method(const FormulaReport& r, Regime regime = Regime::All);

// Human-readable table (deterministic for a given seed).
std::string format_crosscheck(const std::vector<FormulaReport>& reports, const CrossCheckOptions& opt);

}  // namespace dc::num
