// Data for the work-precision charts and stability maps (`derivcheck chart KIND`, docs/charts.md).
//
// Everything here measures; nothing is plotted (numeric/charts/chart_plot.cpp writes gnuplot and
// pgfplots from the tables). Timings are medians of repeated runs with their min and max, so a
// chart shows spread as bars. Errors are against a CLN reference of >= 100 correct digits
// (numeric/reference/reference.hpp), never against another double computation.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/reader/derivation.hpp"

namespace dc::chart {

// Median, min and max of repeated measurements (e.g. seconds per evaluation).
struct Stat {
  double median = 0, min = 0, max = 0;
};
Stat stat_of(std::vector<double> v);   // throws std::invalid_argument on an empty vector

// Calls f() `repeats` times; f performs `ops` operations per call. Returns seconds per operation.
Stat time_per_op(const std::function<void()>& f, long ops, int repeats);

// A CSV table: a header and rows of already-formatted cells.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  std::string to_csv() const;
};
std::string fmt(double x);   // 10 significant digits, "inf"/"nan" spelled out

// Progress on stderr, only when stderr is a terminal (long runs; never in pipes or tests).
void progress(const std::string& what);

// A formula with every parameter replaced by a plain GiNaC::symbol of the same name (returned in
// `inputs`, in the formula's parameter order). Formula::params holds the table's symbols as
// GiNaC::symbol copies, which slices possymbols/realsymbols, and a sliced copy no longer
// compares equal to the symbol inside the expression (GiNaC compares the type first); plain
// symbols on both sides avoid that for num::compile and num::reference_value.
struct PlainFormula {
  GiNaC::ex expr;
  std::vector<GiNaC::symbol> inputs;
  std::vector<std::string> names;
};
PlainFormula plain_formula(const Derivation& d, const GiNaC::ex& expr);

// ---------------------------------------------------------------------------------------------
// Work-precision of one closed form: every evaluation method, time per evaluation against the
// error over seeded random points of the declared domain (plus the formula's stress points).
struct ClosedOptions {
  int points = 64;           // random points (errors and timings over all of them)
  int repeats = 5;           // timing repeats (median, min, max)
  std::vector<int> cln_digits = {15, 30, 50, 100};
  int ref_digits = 110;      // reference precision (>= 100 correct digits)
  std::uint64_t seed = 20261121;
};
struct WpRow {
  std::string formula;       // "05_direct_impact.dc:v1p_general"
  std::string method;        // "CLN 15 digits", "double (evaluator)", "hand-written C++", ...
  Stat seconds;              // per evaluation
  double rel_err_median = 0, rel_err_max = 0;   // against the reference (0 when exact)
  double bits_lost_max = 0;  // log2(1 + max error in ulps of the method's own precision)
  int points = 0;
  double ulps_max = -1;      // max error in ulps of double at the reference (-1: CLN rows)
  double rel_err_max_random = -1;   // max over the random points only (-1: not recorded)
};
// `path` a .dc file, `label` a formula step (y = expr). Methods: CLN at each of cln_digits
// (inputs rounded to that precision, arithmetic in CLN floats), the fast evaluator in double
// and long double, the evaluator with every rewrite switched off ("naive"), each `stable`
// step of the file that rewrites this label, and a hand-written C++ function where one is
// known (hand_written()).
std::vector<WpRow> closed_form_wp(const std::string& path, const std::string& label,
                                  const ClosedOptions& opt);
Table to_table(const std::vector<WpRow>& rows);

// Work-precision of EVERY formula of the given .dc files that the numeric module can compile
// (formulas with abstract functions or derivatives are skipped and listed). Points are those of
// `derivcheck crosscheck` (num::crosscheck_points: seeded random points in the declared
// domains plus stress points), references at ref_digits. Methods: CLN at each of cln_digits,
// "double (evaluator)", "long double (evaluator)", "compensated (double-double)"
// (FormulaEvaluator EvalMode::Compensated: the stable form in its regime, in double-double),
// "stable form LABEL" (FormulaEvaluator EvalMode::Fast) where the file has one, and
// "hand-written C++" where hand_written() knows the label. Fast methods are timed over
// `batch` evaluations (the points tiled), CLN over the points.
struct ClosedAllOptions {
  int points = 12;           // random points per formula (stress points come on top)
  bool stress = true;
  int repeats = 3;
  std::vector<int> cln_digits = {15, 30, 50, 100};
  int ref_digits = 110;
  std::uint64_t seed = 20261121;
  std::size_t batch = 4096;
};
struct ClosedAllResult {
  std::vector<WpRow> rows;
  std::vector<std::string> skipped;   // "file:label: reason"
};
ClosedAllResult closed_forms_wp_all(const std::vector<std::string>& paths, const ClosedAllOptions& opt);
// The method family a row belongs to in the summary chart ("stable form LABEL" -> "stable form").
std::string method_family(const std::string& method);

// Hand-written double versions of handout formulas (the speed limit). Returns an empty
// function if none is known for the label. Arguments in the order of `params` (names); throws
// std::invalid_argument if a name it needs is not among them.
std::function<double(const double*)> hand_written(const std::string& label,
                                                  const std::vector<std::string>& params);
// The same functions as plain inlined loops over columns (cols[i] = values of params[i]); the
// speed limit for timings. Returns false if none is known for the label.
bool hand_written_batch(const std::string& label, const std::vector<std::string>& params,
                        const double* const* cols, double* out, std::size_t n);

// ---------------------------------------------------------------------------------------------
// Stability maps: bits lost (log2(1 + error in ulps of double)) of a naive and a stable
// evaluation as a stress parameter approaches its bad limit.
struct MapRow {
  std::string map;           // "e_to_1"
  double stress = 0;         // value of the stress parameter (or its distance to the limit)
  std::string method;        // "naive: ...", "stable: ..."
  double value = 0;          // the computed double
  double bits_lost = 0;      // 0..53 (53 also for inf/NaN)
};
struct MapInfo {
  std::string name, title, xlabel;  // xlabel with units
  std::string naive, stable;        // descriptions (where each form comes from)
};
const std::vector<MapInfo>& closed_form_maps();
// Rows of one map; `steps` points along the stress axis. Throws std::invalid_argument for an
// unknown map name.
std::vector<MapRow> closed_form_map(const std::string& root, const std::string& name, int steps);
Table to_table(const std::vector<MapRow>& rows);

// Integrator stability on the stiff spring (numeric/scenes spring, Example 9.3 masses with a
// stiff k): max position error against the exact solution and energy drift per method as
// omega*h passes the explicit methods' limits (verlet 2, rk4 2.83; euler unstable for any h).
struct StiffRow {
  std::string method;
  double omega_h = 0;
  double max_position_error = 0;   // [m], inf when the run blew up
  double energy_drift = 0;         // relative, inf when blown up
};
std::vector<StiffRow> stiff_spring_map(double k, int steps, double omega_h_max);
Table to_table(const std::vector<StiffRow>& rows);

// ---------------------------------------------------------------------------------------------
// Scene work-precision: each integrator over a sweep of steps (fixed-step methods) or
// tolerances (dopri5): wall time per run (median/min/max of repeats) against the relative error
// of the scene's compared quantity and its conserved-quantity drift (where it reports one).
struct SceneRow {
  std::string scene, quantity, method, param;   // param "h=1e-3" or "tol=1e-8"
  Stat seconds;
  double rel_error = 0;
  double drift = -1;         // relative conserved-quantity drift, -1 when not reported
  long rhs_evaluations = 0;
};
struct SceneOptions {
  int repeats = 5;
  int sweep = 8;             // steps / tolerances per method
};
// The quantity each scene's work-precision uses (e.g. spring: "x2(t_end)").
std::string scene_quantity(const std::string& scene);
std::vector<SceneRow> scene_wp(const std::string& scene, const SceneOptions& opt);
Table to_table(const std::vector<SceneRow>& rows);

}  // namespace dc::chart
