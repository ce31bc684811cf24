// Scenes of Handout 9 simulated numerically: the one place that declares each scene's model.
//
// A SceneSpec lists the scene's parameters (name, unit, default, bounds), its degrees of
// freedom and its assumptions. The CLI (`derivcheck simulate --list`, `simulate SCENE --help`),
// the validation of user input and docs/scenes.md all read this table, so a parameter is
// declared exactly once.
//
// Bad physical input throws std::domain_error naming the parameter, its value and the bound,
// e.g. "spring: m1 = -1 kg is out of bounds: need m1 > 0". The CLI maps it to exit code 2.
#pragma once
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "numeric/scenes/integrators.hpp"

namespace dc::scenes {

// One scene parameter. Bounds are numbers, or the value of another parameter of the same scene
// (lo_ref / hi_ref name it; e.g. the chain's x is bounded by L). A bound of +-inf means none.
struct ParamSpec {
  std::string name;
  std::string unit;          // "kg", "m/s", "1", "deg"
  double def = 0;            // default (from the handout where it gives one; see `source`)
  double lo = 0, hi = 0;
  bool lo_open = false, hi_open = false;
  std::string lo_ref, hi_ref;
  std::string description;
  bool integer = false;      // e.g. the number of balls of Newton's cradle
};

using Params = std::map<std::string, double>;

// One simulated quantity compared with its closed form.
struct Comparison {
  std::string quantity;      // "v_G", "theta_max"
  std::string unit;
  double simulated = 0;
  double closed_form = 0;
  std::string formula;       // the closed form in words/maths: "m2 v0/(m1+m2)"
  std::string source;        // where the closed form came from: "built-in" or "FILE:LABEL"
  double builtin = 0;        // with a derived closed form (source FILE:LABEL): the hand-typed
                             // value of closed_forms.hpp, for the cross-check; else unused
  double rel_error() const;  // |sim - cf| / |cf| (absolute error when cf == 0)
};

// A table of samples for --csv: named columns, one row per sample.
struct Series {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  std::string to_csv() const;  // header line, then rows with 17 significant digits
};

struct RunOptions {
  Method method = Method::rk4;
  double h = 0;      // step (fixed-step methods) or output spacing (dopri5); 0: scene default
  double tol = 1e-10;  // dopri5 absolute and relative tolerance
  // Directory of the handout's derivation files (derivations/handout9): closed forms are then
  // evaluated from the derived formulas by label (derived.hpp); empty: the built-in copies.
  std::string derivations;
};

struct SceneResult {
  std::vector<Comparison> comparisons;
  Series series;
  std::vector<std::string> notes;   // facts worth printing (events, conserved-quantity drift)
  std::map<std::string, double> metrics;  // named measurements, e.g. "max_energy_drift"
  // Optional figure of `series`: x column and y columns (with pgfplots legend entries).
  struct Figure {
    std::string x, xlabel, ylabel;
    std::vector<std::pair<std::string, std::string>> y;   // column, legend (TeX)
  } figure;
  Method method = Method::rk4;
  double h = 0;
  long rhs_evaluations = 0;

  // The comparison / metric named q; throws std::out_of_range if absent.
  const Comparison& get(const std::string& q) const;
  double metric(const std::string& name) const;
};

struct SceneSpec {
  std::string name;          // CLI name: "spring"
  std::string title;         // "Two masses and a spring"
  std::string handout;       // "Example 9.3"
  std::string dofs;          // degrees of freedom, e.g. "x1, x2 (1-D along the spring)"
  std::vector<std::string> assumptions;
  std::vector<ParamSpec> params;
  std::vector<Method> methods;   // supported integrators; empty: not an ODE scene (exact events / linear algebra)
  Method default_method = Method::rk4;
  double default_h = 0;          // default step [s]
  SceneResult (*run)(const Params&, const RunOptions&) = nullptr;
  // Conditions between parameters beyond the bounds (e.g. the pendulum must not swing above
  // the horizontal); throws std::domain_error. May be null.
  void (*check)(const Params&) = nullptr;
};

const std::vector<SceneSpec>& scene_specs();
// Throws std::invalid_argument("unknown scene 'x'; scenes: spring, pendulum, ...").
const SceneSpec& find_scene(std::string_view name);

// The defaults of every parameter.
Params defaults(const SceneSpec& spec);

// Defaults overridden by `name=value` assignments (value: a decimal number, optionally
// "a/b"). Unknown names or unparsable values throw std::invalid_argument; then validate().
Params resolve(const SceneSpec& spec, const std::vector<std::string>& assignments);

// Bounds of every parameter (and the scene's cross-parameter conditions); throws
// std::domain_error naming scene, parameter, value, unit and bound. NaN and inf are rejected.
void validate(const SceneSpec& spec, const Params& p);

// Step/tolerance checks shared by the scenes: h > 0 finite, tol > 0 finite.
void check_run_options(const SceneSpec& spec, const RunOptions& opt);

// Validate, fill the default step, check the method is supported, then run the scene.
SceneResult run_scene(const SceneSpec& spec, const Params& p, RunOptions opt);

// Human-readable description of the scene (for --help and docs/scenes.md).
std::string describe(const SceneSpec& spec);
// docs/scenes.md's parameter table, in Markdown.
std::string describe_markdown(const SceneSpec& spec);

// The figure of a result as a pgfplots tikzpicture (to \input into a LaTeX document with
// \usepackage{pgfplots}); at most max_points samples per curve. Empty if the result has none.
std::string figure_pgfplots(const SceneResult& r, const std::string& title, std::size_t max_points = 400);
// A gnuplot script drawing the same figure from the CSV file into a PNG file.
std::string figure_gnuplot(const SceneResult& r, const std::string& title, const std::string& csv_path,
                           const std::string& png_path);

// Throws std::domain_error("SCENE: NAME = VALUE UNIT is out of bounds: need COND").
[[noreturn]] void out_of_bounds(const std::string& scene, const std::string& name, double value,
                                const std::string& unit, const std::string& need);

}  // namespace dc::scenes
