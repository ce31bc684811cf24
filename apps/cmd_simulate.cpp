// derivcheck simulate SCENE [--set NAME=VALUE ...] [--method M] [--step H] [--tol T] [--csv FILE]
// Runs one of Handout 9's scenes (numeric/scenes) and prints the simulated quantities against
// their closed forms. `simulate --list` lists the scenes; `simulate SCENE --describe` lists a
// scene's parameters, units, bounds, degrees of freedom and assumptions.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "derivations/syntax/io.hpp"
#include "numeric/scenes/spec.hpp"

namespace dc::cli {
namespace {

struct SimulateOptions {
  std::string scene;
  std::vector<std::string> sets;
  std::string method;
  double step = 0;
  bool step_given = false;
  double tol = 1e-10;
  std::string csv, pgfplots, gnuplot, png;
  bool list = false, describe = false, markdown = false, time = false;
  std::string derivations = "derivations/handout9";
  bool derivations_given = false;
  double max_rel_error = -1;
};

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

int run(const SimulateOptions& o) {
  using namespace dc::scenes;
  if (o.list || (o.scene.empty() && o.markdown)) {
    for (const auto& s : scene_specs()) {
      if (o.markdown) std::cout << describe_markdown(s);
      else std::printf("%-9s %s (%s)\n", s.name.c_str(), s.title.c_str(), s.handout.c_str());
    }
    return kExitOk;
  }
  if (o.scene.empty()) throw std::invalid_argument("simulate: name a scene (see `derivcheck simulate --list`)");
  const SceneSpec& spec = find_scene(o.scene);
  if (o.describe || o.markdown) {
    std::cout << (o.markdown ? describe_markdown(spec) : describe(spec));
    return kExitOk;
  }
  const Params p = resolve(spec, o.sets);
  RunOptions opt;
  opt.method = o.method.empty() ? spec.default_method : parse_method(o.method);
  opt.h = o.step_given ? o.step : 0;  // 0: the scene's default step
  opt.tol = o.tol;
  // closed forms from the derivation files when they are there (else the built-in copies)
  if (std::filesystem::is_directory(o.derivations)) opt.derivations = o.derivations;
  else if (o.derivations_given) throw std::invalid_argument("simulate: --derivations '" + o.derivations + "' is not a directory");
  if (!o.method.empty() && spec.methods.empty())
    throw std::invalid_argument(spec.name + ": this scene has no integrator (exact events / linear algebra); drop --method");
  if (o.step_given && spec.methods.empty())
    throw std::invalid_argument(spec.name + ": this scene has no time step; drop --step");
  if (!spec.methods.empty()) {
    RunOptions check = opt;
    if (!o.step_given) check.h = spec.default_h;
    check_run_options(spec, check);  // a given step must be > 0: --step 0 is an error, not "default"
  }
  const auto t0 = std::chrono::steady_clock::now();
  const SceneResult r = run_scene(spec, p, opt);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::cout << spec.name << ": " << spec.title << " (" << spec.handout << ")\n";
  std::cout << "  parameters:";
  for (const auto& ps : spec.params)
    std::cout << " " << ps.name << "=" << fmt("%.10g", p.at(ps.name)) << (ps.unit == "1" ? "" : " " + ps.unit) << ";";
  std::cout << "\n";
  if (!spec.methods.empty())
    std::cout << "  method: " << method_name(r.method) << ", h = " << fmt("%.6g", r.h) << " s"
              << (r.method == Method::dopri5 ? ", tol = " + fmt("%.3g", opt.tol) + " (h is the output spacing)" : "")
              << ", " << r.rhs_evaluations << " right-hand-side evaluations\n";
  else
    std::cout << "  method: exact (event times solved in closed form / linear systems)\n";
  std::cout << "  closed forms: "
            << (opt.derivations.empty() ? std::string("built-in copies (no derivations directory; --derivations DIR)")
                                        : "derived formulas from " + opt.derivations + " where labelled, else built-in")
            << "\n";
  std::printf("  %-18s %24s %24s %10s  %s\n", "quantity", "simulated", "closed form", "rel.error", "[source] closed form");
  double worst = 0;
  for (const auto& c : r.comparisons) {
    const double e = c.rel_error();
    worst = std::isfinite(e) ? std::max(worst, e) : HUGE_VAL;
    std::string unit = c.unit == "1" ? "" : " " + c.unit;
    std::printf("  %-18s %24s %24s %10.2e  [%s] %s\n", c.quantity.c_str(), (fmt("%.15g", c.simulated) + unit).c_str(),
                (fmt("%.15g", c.closed_form) + unit).c_str(), e, c.source.c_str(), c.formula.c_str());
  }
  for (const auto& [k, v] : r.metrics) std::printf("  %s = %.6g\n", k.c_str(), v);
  for (const auto& n : r.notes) std::cout << "  note: " << n << "\n";
  if (o.time) std::cerr << "simulate: " << fmt("%.3g", secs * 1e3) << " ms\n";

  if (!o.csv.empty()) write_file_atomic(o.csv, r.series.to_csv());
  const std::string title = spec.title + " (" + spec.handout + ")";
  if (!o.pgfplots.empty()) {
    const std::string tex = figure_pgfplots(r, title);
    if (tex.empty()) throw std::invalid_argument(spec.name + ": this scene has no figure for --pgfplots");
    write_file_atomic(o.pgfplots, tex);
  }
  if (!o.gnuplot.empty()) {
    if (o.csv.empty()) throw std::invalid_argument("simulate: --gnuplot needs --csv (the data it plots)");
    const std::string gp = figure_gnuplot(r, title, o.csv, o.png);
    if (gp.empty()) throw std::invalid_argument(spec.name + ": this scene has no figure for --gnuplot");
    write_file_atomic(o.gnuplot, gp);
  }
  if (o.max_rel_error >= 0 && !(worst <= o.max_rel_error)) {
    std::cerr << "simulate: largest relative error " << fmt("%.3g", worst) << " exceeds --max-rel-error "
              << fmt("%.3g", o.max_rel_error) << "\n";
    return kExitRefuted;
  }
  return kExitOk;
}

const CommandRegistrar registrar{
    "simulate", "simulate a Handout 9 scene and compare it with the closed forms (--list for the scenes)",
    [](CLI::App& sub) -> std::function<int()> {
      auto o = std::make_shared<SimulateOptions>();
      sub.add_option("scene", o->scene, "scene name (see --list)");
      sub.add_flag("--list", o->list, "list the scenes");
      sub.add_flag("--describe", o->describe, "list the scene's parameters (units, defaults, bounds), DOFs and assumptions");
      sub.add_flag("--markdown", o->markdown, "like --describe (or --list) as Markdown, for docs/scenes.md");
      sub.add_option("--set", o->sets, "override a parameter: NAME=VALUE (repeatable; VALUE may be a/b)")->take_all();
      sub.add_option("--method", o->method, "integrator: euler, rk4, dopri5, verlet, rosenbrock (default: the scene's)");
      sub.add_option("--step", o->step, "time step [s] (dopri5: output spacing); default: the scene's")
          ->each([o](const std::string&) { o->step_given = true; });
      sub.add_option("--tol", o->tol, "dopri5 absolute and relative tolerance (default 1e-10)");
      sub.add_option("--derivations", o->derivations,
                     "directory of the handout's derivation files whose formulas are the closed forms "
                     "(default derivations/handout9 if present)")
          ->each([o](const std::string&) { o->derivations_given = true; });
      sub.add_flag("--time", o->time, "print the run's wall time on stderr");
      sub.add_option("--csv", o->csv, "write the time series as CSV (atomically)");
      sub.add_option("--pgfplots", o->pgfplots, "write the scene's figure as a pgfplots tikzpicture (atomically)");
      sub.add_option("--gnuplot", o->gnuplot, "write a gnuplot script drawing the figure from --csv into --png");
      sub.add_option("--png", o->png, "the PNG file the --gnuplot script draws (default: standard output)");
      sub.add_option("--max-rel-error", o->max_rel_error,
                     "exit 1 if any simulated quantity differs from its closed form by more than this");
      sub.footer("Scenes: spring, pendulum, bounce, rocket, chain, ladder, cradle, cannon, impact, oblique.\n"
                 "`derivcheck simulate SCENE --describe` lists a scene's parameters, units, bounds and assumptions.");
      return [o] { return run(*o); };
    }};

}  // namespace
}  // namespace dc::cli
