// `derivcheck chart KIND`: work-precision data and stability maps as CSV, PNG, SVG and pgfplots
// (docs/charts.md). All measuring lives in numeric/charts/chart_data.cpp, all drawing in
// numeric/charts/chart_plot.cpp; this file parses options, picks files and names.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "apps/commands.hpp"
#include "derivations/reader/derivation.hpp"
#include "derivations/syntax/io.hpp"
#include "numeric/charts/chart_checker.hpp"
#include "numeric/charts/chart_data.hpp"
#include "numeric/charts/chart_ode_maps.hpp"
#include "numeric/charts/chart_plot.hpp"
#include "numeric/evaluator.hpp"

namespace {

using namespace dc::chart;

struct ChartArgs {
  std::string kind;
  std::vector<std::string> formulas;
  std::string scenes = "spring,pendulum,rocket,ladder";
  std::string maps = "e_to_1,v1_to_v2,mu_to_0,m2_to_inf,theta_to_0,mr_to_m0";
  int points = 12, repeats = 5, sweep = 8, steps = 40;
  std::string out, root = ".", csv;   // out empty: a new directory (fresh_output_dir)
  // evalpoints
  std::vector<std::string> positional;
  std::string inputs, points_file, out_file;
  bool no_figures = false;
  bool serve = false;   // evalpoints: timing requests on stdin (interleaved peers)
  // checker
  std::string corpus, ks = "1,2,4,8", digits = "20,30,50,100";
};

std::vector<std::string> split(const std::string& s, char c = ',') {
  std::vector<std::string> v;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, c))
    if (!cur.empty()) v.push_back(cur);
  return v;
}

std::string slug(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

// Without -o the charts go to a new directory in the current one (derivcheck-charts, then
// derivcheck-charts-2, ...): a run never overwrites earlier charts, nor the repository's
// committed docs/charts, unless that directory is asked for.
std::string fresh_output_dir() {
  namespace fs = std::filesystem;
  for (int i = 1;; ++i) {
    const std::string name = i == 1 ? "derivcheck-charts" : "derivcheck-charts-" + std::to_string(i);
    std::error_code ec;
    if (fs::create_directory(name, ec)) return name;
    if (ec) throw std::invalid_argument("cannot create the output directory " + name + ": " + ec.message());
  }
}

void prepare_output(ChartArgs& a) {
  if (a.kind == "evalpoints") return;
  const bool one_csv = a.kind == "closed" || a.kind == "scenes" || a.kind == "checker";
  if (one_csv && !a.csv.empty() && a.out.empty()) return;   // --csv names the one file written
  if (a.out.empty()) {
    a.out = fresh_output_dir();
  } else {
    std::error_code ec;
    std::filesystem::create_directories(a.out, ec);
    if (ec) throw std::invalid_argument("cannot create the output directory " + a.out + ": " + ec.message());
  }
  std::cerr << "derivcheck chart: writing to " << a.out << "/\n";
}

void say_written(const std::vector<std::string>& files) {
  for (const auto& f : files) std::cout << "wrote " << f << "\n";
}

// --- closed forms --------------------------------------------------------------------------------
// Every formula of derivations/handout9/*.dc the numeric module evaluates goes into
// wp_closed.csv and the summary chart wp_closed_all; per-formula figures only for kFigures.
const std::vector<std::string> kFigures = {"05_direct_impact.dc:v1p_general", "05_direct_impact.dc:energy_loss_general",
                                           "06_ballistic_pendulum.dc:deflection", "07_two_ball_bounce.dc:v1p_bounce",
                                           "03_ladder.dc:wall_impulse"};

double clamp_err(double e) { return std::min(std::max(e, 1e-110), 10.0); }

int run_closed(const ChartArgs& a) {
  std::vector<std::string> paths;
  std::set<std::string> only;   // --formula FILE:LABEL restricts to those labels
  for (const auto& s : a.formulas) {
    const auto colon = s.rfind(':');
    if (colon == std::string::npos) throw std::invalid_argument("--formula expects FILE:LABEL, got '" + s + "'");
    if (std::find(paths.begin(), paths.end(), s.substr(0, colon)) == paths.end()) paths.push_back(s.substr(0, colon));
    only.insert(s.substr(0, colon).substr(s.substr(0, colon).find_last_of('/') + 1) + ":" + s.substr(colon + 1));
  }
  if (paths.empty())
    for (const char* f : {"01_momentum_particle", "02_cannon", "03_ladder", "04_system_of_particles", "05_direct_impact",
                          "06_ballistic_pendulum", "07_two_ball_bounce", "08_oblique_impact", "09_rocket", "10_falling_chain"})
      paths.push_back(a.root + "/derivations/handout9/" + f + ".dc");
  ClosedAllOptions o;
  o.points = a.points, o.repeats = a.repeats;
  auto res = closed_forms_wp_all(paths, o);
  if (!only.empty())
    res.rows.erase(std::remove_if(res.rows.begin(), res.rows.end(), [&](const WpRow& r) { return !only.count(r.formula); }),
                   res.rows.end());
  for (const auto& s : res.skipped) std::cerr << "chart closed: skipped " << s << "\n";
  if (res.rows.empty()) throw std::invalid_argument("chart closed: no formula evaluated");
  if (!a.no_figures) {
    // per-formula figures: the five (or the --formula ones)
    std::vector<std::string> order;
    std::map<std::string, std::vector<const WpRow*>> by_formula;
    for (const auto& r : res.rows) {
      if (!by_formula.count(r.formula)) order.push_back(r.formula);
      by_formula[r.formula].push_back(&r);
    }
    for (const auto& fname : order) {
      const std::string label = fname.substr(fname.find(':') + 1);
      if (only.empty() && std::find(kFigures.begin(), kFigures.end(), fname) == kFigures.end()) continue;
      Plot p;
      p.title = "Work-precision: " + fname;
      p.xlabel = "max relative error vs 110-digit reference [1] (exact: 1e-110)";
      p.ylabel = "time per evaluation [s]";
      for (const WpRow* r : by_formula[fname])
        p.series.push_back({r->method, {{clamp_err(r->rel_err_max), r->seconds.median, r->seconds.min, r->seconds.max}}, true, false});
      say_written(write_figures(p, a.out + "/wp_closed_" + slug(label)));
    }
    // summary: one point per formula per method family
    std::vector<std::string> fam_order;
    std::map<std::string, PlotSeries> fam;
    std::map<std::string, int> fam_n;
    for (const auto& r : res.rows) {
      const std::string m = method_family(r.method);
      if (!fam.count(m)) fam_order.push_back(m);
      fam[m].points.push_back({clamp_err(r.rel_err_max), r.seconds.median, 0, 0});
      ++fam_n[m];
    }
    Plot p;
    p.title = "Work-precision of " + std::to_string(order.size()) + " handout formulas: one point per formula and method";
    p.xlabel = "max relative error over domain and stress points vs 110-digit reference [1] (exact: 1e-110, garbage: 10)";
    p.ylabel = "median time per evaluation [s]";
    for (const auto& m : fam_order) {
      PlotSeries s = fam[m];
      s.name = m + " (" + std::to_string(fam_n[m]) + ")";
      s.lines = false;
      p.series.push_back(s);
    }
    if (only.empty()) say_written(write_figures(p, a.out + "/wp_closed_all"));
  }
  const std::string csv = a.csv.empty() ? a.out + "/wp_closed.csv" : a.csv;
  dc::write_file_atomic(csv, to_table(res.rows).to_csv());
  say_written({csv});
  return 0;
}

// --- scenes ----------------------------------------------------------------------------------------
int run_scenes(const ChartArgs& a) {
  SceneOptions o;
  o.repeats = a.repeats, o.sweep = a.sweep;
  std::vector<SceneRow> all;
  for (const auto& scene : split(a.scenes)) {
    auto rows = scene_wp(scene, o);
    if (!a.no_figures && a.csv.empty()) {
      std::map<std::string, PlotSeries> by_method, drift;
      for (const auto& r : rows) {
        auto& s = by_method[r.method];
        s.name = r.method, s.bars = true;
        s.points.push_back({r.rel_error, r.seconds.median, r.seconds.min, r.seconds.max});
        if (r.drift >= 0) {
          auto& d = drift[r.method];
          d.name = r.method, d.bars = true;
          d.points.push_back({r.drift, r.seconds.median, r.seconds.min, r.seconds.max});
        }
      }
      Plot p;
      p.title = "Work-precision: scene " + scene + " (" + scene_quantity(scene) + ")";
      p.xlabel = "relative error of " + scene_quantity(scene) + " vs closed form";
      p.ylabel = "wall time per run [s]";
      for (auto& [m, s] : by_method) p.series.push_back(s);
      say_written(write_figures(p, a.out + "/wp_scene_" + scene));
      if (!drift.empty()) {
        Plot q = p;
        q.title = "Work-precision: scene " + scene + ", energy drift";
        q.xlabel = "max relative energy drift";
        q.series.clear();
        for (auto& [m, s] : drift) q.series.push_back(s);
        say_written(write_figures(q, a.out + "/wp_scene_drift_" + scene));
      }
    }
    all.insert(all.end(), rows.begin(), rows.end());
  }
  const std::string csv = a.csv.empty() ? a.out + "/wp_scenes.csv" : a.csv;
  dc::write_file_atomic(csv, to_table(all).to_csv());
  if (a.csv.empty()) say_written({csv});
  return 0;
}

// --- stability maps ------------------------------------------------------------------------------------
int run_maps(const ChartArgs& a) {
  std::vector<MapRow> all;
  for (const auto& name : split(a.maps)) {
    auto rows = closed_form_map(a.root, name, a.steps);
    const auto& infos = closed_form_maps();
    auto info = std::find_if(infos.begin(), infos.end(), [&](const MapInfo& m) { return m.name == name; });
    if (!a.no_figures) {
      std::map<std::string, PlotSeries> by;
      std::vector<std::string> order;
      for (const auto& r : rows) {
        if (!by.count(r.method)) order.push_back(r.method);
        auto& s = by[r.method];
        s.name = r.method;
        s.points.push_back({r.stress, r.bits_lost, 0, 0});
      }
      Plot p;
      p.title = "Stability map: " + info->title;
      p.xlabel = info->xlabel;
      p.ylabel = "bits lost (of 53)";
      p.logy = false;
      double lowest = 0;
      for (const auto& m : order) {
        p.series.push_back(by[m]);
        for (const auto& q : by[m].points) lowest = std::min(lowest, q.y);
      }
      if (lowest >= 0) p.ymin = 0;   // nothing is gained: the axis starts at no loss
      say_written(write_figures(p, a.out + "/map_" + name));
    }
    all.insert(all.end(), rows.begin(), rows.end());
  }
  dc::write_file_atomic(a.out + "/map_closed.csv", to_table(all).to_csv());
  say_written({a.out + "/map_closed.csv"});

  const auto stiff = stiff_spring_map(5000, std::max(2, a.steps / 2), 3.2);
  if (!a.no_figures) {
    std::map<std::string, PlotSeries> by;
    for (const auto& r : stiff) {
      auto& s = by[r.method];
      s.name = r.method;
      s.points.push_back({r.omega_h, std::min(r.max_position_error, 1e300), 0, 0});
    }
    Plot p;
    p.title = "Stability map: stiff spring (k = 5000 N/m, Example 9.3 masses), 32 periods";
    p.xlabel = "omega h (step times angular frequency) [1]";
    p.ylabel = "max position error vs exact solution [m]";
    p.logx = false;
    p.vlines = {{2.0, "verlet limit 2"}, {2.8284, "rk4 limit 2.83"}};
    for (auto& [m, s] : by) p.series.push_back(s);
    say_written(write_figures(p, a.out + "/map_stiff_spring"));
  }
  dc::write_file_atomic(a.out + "/map_stiff_spring.csv", to_table(stiff).to_csv());
  say_written({a.out + "/map_stiff_spring.csv"});

  // the chain's first-order ODE from rest against the second-order model
  const auto chain = chain_from_rest_map(1e-3, std::max(2, a.steps / 2));
  if (!a.no_figures) {
    std::map<std::string, PlotSeries> by;
    std::vector<std::string> order;
    for (const auto& r : chain) {
      const std::string name = (r.model.rfind("first", 0) == 0 ? "first order, " : "second order, ") + r.method;
      if (!by.count(name)) order.push_back(name);
      auto& s = by[name];
      s.name = name;
      s.points.push_back({r.t, std::max(r.abs_error, 1e-18), 0, 0});
    }
    Plot p;
    p.title = "Stability map: chain from rest (h = 1e-3 s): x' = sqrt(2gx) never starts";
    p.xlabel = "time since release t [s]";
    p.ylabel = "error of x(t) vs g t^2/2 [m] (exact: 1e-18)";
    for (const auto& m : order) p.series.push_back(by[m]);
    say_written(write_figures(p, a.out + "/map_chain_from_rest"));
  }
  dc::write_file_atomic(a.out + "/map_chain_from_rest.csv", to_table(chain).to_csv());
  say_written({a.out + "/map_chain_from_rest.csv"});

  // event location in the bounce
  const auto bounce = bounce_event_map(std::max(2, a.steps / 4));
  if (!a.no_figures) {
    std::map<std::string, PlotSeries> by;
    std::vector<std::string> order;
    for (const auto& r : bounce) {
      const std::string name = r.method + ", " + r.location;
      if (!by.count(name)) order.push_back(name);
      auto& s = by[name];
      s.name = name;
      s.points.push_back({r.h, std::max(r.rel_error, 1e-17), 0, 0});
    }
    Plot p;
    p.title = "Stability map: two-ball bounce, events located vs taken at the step end";
    p.xlabel = "step h [s] (dopri5: output spacing, tol 1e-10)";
    p.ylabel = "relative error of the rebound velocity v'1 (exact: 1e-17)";
    for (const auto& m : order) p.series.push_back(by[m]);
    say_written(write_figures(p, a.out + "/map_bounce_events"));
  }
  dc::write_file_atomic(a.out + "/map_bounce_events.csv", to_table(bounce).to_csv());
  say_written({a.out + "/map_bounce_events.csv"});
  return 0;
}

// --- the checker's strategies ------------------------------------------------------------------
std::vector<int> int_list(const std::string& s, const std::string& flag) {
  std::vector<int> v;
  for (const auto& item : split(s)) {
    try {
      std::size_t used = 0;
      v.push_back(std::stoi(item, &used));
      if (used != item.size()) throw std::invalid_argument("");
    } catch (const std::logic_error&) {
      throw std::invalid_argument(flag + ": '" + item + "' is not an integer");
    }
  }
  if (v.empty()) throw std::invalid_argument(flag + ": empty list");
  return v;
}

int run_checker(const ChartArgs& a) {
  CheckerOptions o;
  o.repeats = a.repeats;
  o.ks = int_list(a.ks, "--k");
  o.digits = int_list(a.digits, "--digits");
  const std::string corpus = a.corpus.empty() ? a.root + "/tests/data/corpus.jsonl" : a.corpus;
  const auto rows = checker_wp(corpus, o);
  if (!a.no_figures && a.csv.empty()) {
    // One x position per strategy (no two strategies drawn on top of each other); the series
    // group strategies by their accuracy and false accepts, which the legend states.
    Plot p;
    std::map<std::string, std::size_t> series_of;
    for (const auto& r : rows) {
      const std::string cat = r.family == "symbolic" ? "symbolic only"
                              : r.family == "cascade" ? "full cascade (" + std::to_string(r.k) + " pts, " + std::to_string(r.digits) + " dig.)"
                                                      : r.family + ", k = " + std::to_string(r.k);
      char acc[64];
      std::snprintf(acc, sizeof acc, "accuracy %.3f, %d false accept%s", r.accuracy, r.false_accepts,
                    r.false_accepts == 1 ? "" : "s");
      auto [it, fresh] = series_of.emplace(acc, p.series.size());
      if (fresh) p.series.push_back({acc, {}, true, false});
      const double x = static_cast<double>(p.xcategories.size());
      p.xcategories.push_back(cat);
      p.series[it->second].points.push_back({x, r.seconds.median, r.seconds.min, r.seconds.max});
    }
    p.title = "Work-precision of the checker: " + std::to_string(rows.front().claims) + " labelled claims (tests/data/corpus.jsonl)";
    p.xlabel = "strategy (colour: verdict accuracy, undecided counted as not correct)";
    p.ylabel = "time per claim [s]";
    p.logx = false;
    say_written(write_figures(p, a.out + "/wp_checker"));
  }
  const std::string csv = a.csv.empty() ? a.out + "/wp_checker.csv" : a.csv;
  dc::write_file_atomic(csv, to_table(rows).to_csv());
  say_written({csv});
  return 0;
}

// --- evalpoints: the peers' evaluator timing (bench/peers/peer_eval.py) -----------------------------
int run_evalpoints(const ChartArgs& a) {
  if (a.positional.size() != 2) throw std::invalid_argument("chart evalpoints FILE LABEL --inputs ... --points P --out O");
  const auto d = dc::load_derivation(a.positional[0]);
  const auto f = dc::formula(d, a.positional[1]);
  const auto names = split(a.inputs);
  const PlainFormula pf = plain_formula(d, f.expr);
  std::vector<GiNaC::symbol> syms;
  for (const auto& n : names) {
    auto it = std::find(pf.names.begin(), pf.names.end(), n);
    if (it == pf.names.end()) throw std::invalid_argument("--inputs: " + n + " is not a parameter of " + f.label);
    syms.push_back(pf.inputs[static_cast<std::size_t>(it - pf.names.begin())]);
  }
  if (syms.size() != pf.inputs.size()) throw std::invalid_argument("--inputs must list every parameter of " + f.label);
  dc::refuse_output_over_inputs(a.out_file, {a.points_file, a.positional[0]}, "--out-file");
  std::vector<double> flat;
  {
    // 1e6 points of up to 8 parameters (bench/peers/peer_eval.py) stay under this limit
    const std::string bytes = dc::read_file(a.points_file, std::size_t{256} << 20);
    flat.resize(bytes.size() / sizeof(double));
    std::memcpy(flat.data(), bytes.data(), flat.size() * sizeof(double));
  }
  const std::size_t k = syms.size(), n = flat.size() / k;
  if (n == 0 || flat.size() % k) throw std::invalid_argument("--points: size is not a multiple of " + std::to_string(k) + " doubles");
  std::vector<std::vector<double>> cols(k, std::vector<double>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < k; ++j) cols[j][i] = flat[i * k + j];
  std::vector<const double*> cp;
  for (auto& c : cols) cp.push_back(c.data());
  // The default fast path: Evaluator<double>::eval_batch, i.e. the JIT where available
  // (compiled here, before any timing: a user pays it once per formula), else the tape.
  const dc::num::Program prog = dc::num::compile(pf.expr, syms);
  const dc::num::Evaluator<double> ev(prog);
  std::vector<double> out(n), tout(n), hout(n);
  const auto c0 = std::chrono::steady_clock::now();
  ev.eval_batch(cp.data(), out.data(), 1);
  const double first_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - c0).count();
  const bool has_hw = static_cast<bool>(hand_written(f.label, names));
  const std::map<std::string, std::function<void()>> tools = {
      {"derivcheck", [&] { ev.eval_batch(cp.data(), out.data(), n); }},
      {"tape", [&] { ev.eval_batch_tape(cp.data(), tout.data(), n); }},
      {"handwritten", [&] { hand_written_batch(f.label, names, cp.data(), hout.data(), n); }}};
  nlohmann::json j;
  j["points"] = n;
  j["method"] = ev.jit() ? "Evaluator<double>::eval_batch (JIT, " + ev.jit()->isa() + ")" : "Evaluator<double>::eval_batch (tape)";
  j["jit_isa"] = ev.jit() ? ev.jit()->isa() : "";
  j["jit_width"] = ev.jit() ? ev.jit()->width() : 0;
  j["compile_ms"] = ev.jit() ? ev.jit()->compile_ms() : first_ms;
  j["handwritten"] = has_hw;
  if (a.serve) {
    // Interleaved timing for bench/peers/peer_eval.py: one line per request on stdin
    // ("derivcheck", "tape" or "handwritten"), answered with {"tool":..,"ns_per_eval":..}; the
    // caller times its own peers in between. EOF or "quit" ends (then the results are written).
    std::cout << dc::json_text(j) << std::endl;
    std::string line;
    while (std::getline(std::cin, line) && line != "quit") {
      auto it = tools.find(line);
      if (it == tools.end() || (line == "handwritten" && !has_hw)) {
        std::cout << nlohmann::json{{"tool", line}, {"error", "no such tool"}}.dump() << std::endl;
        continue;
      }
      const auto t0 = std::chrono::steady_clock::now();
      it->second();
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::cout << nlohmann::json{{"tool", line}, {"ns_per_eval", s / static_cast<double>(n) * 1e9}}.dump() << std::endl;
    }
  } else {
    // --repeats R: the tools interleaved (derivcheck, tape, handwritten, derivcheck, ...)
    std::map<std::string, std::vector<double>> ts;
    for (int r = 0; r < a.repeats; ++r)
      for (const char* t : {"derivcheck", "tape", "handwritten"}) {
        if (std::string(t) == "handwritten" && !has_hw) continue;
        const Stat one = time_per_op(tools.at(t), static_cast<long>(n), 1);
        ts[t].push_back(one.median);
      }
    auto put = [&](const std::string& key, std::vector<double> v) {
      const Stat st = stat_of(std::move(v));
      j[key] = {{"median", st.median * 1e9}, {"min", st.min * 1e9}, {"max", st.max * 1e9}};
      return st;
    };
    j["evals_per_s"] = 1 / put("ns_per_eval", ts["derivcheck"]).median;
    put("tape_ns_per_eval", ts["tape"]);
    if (has_hw) j["handwritten_evals_per_s"] = 1 / put("handwritten_ns_per_eval", ts["handwritten"]).median;
  }
  std::string bytes(reinterpret_cast<const char*>(out.data()), out.size() * sizeof(double));
  dc::write_file_atomic(a.out_file, bytes);
  if (!a.serve) std::cout << dc::json_text(j) << "\n";
  return 0;
}

const dc::cli::CommandRegistrar reg(
    "chart", "work-precision charts and stability maps: CSV, PNG, SVG, pgfplots (docs/charts.md)",
    [](CLI::App& sub) -> std::function<int()> {
      auto a = std::make_shared<ChartArgs>();
      sub.add_option("kind", a->kind, "closed | scenes | maps | checker | all | evalpoints")
          ->required()
          ->check(CLI::IsMember({"closed", "scenes", "maps", "checker", "all", "evalpoints"}));
      sub.add_option("args", a->positional, "evalpoints: FILE LABEL");
      sub.add_option("--formula", a->formulas, "closed: FILE:LABEL (repeatable; default: every formula of derivations/handout9)");
      sub.add_option("--scenes", a->scenes, "scenes: comma-separated scene names")->capture_default_str();
      sub.add_option("--maps", a->maps, "maps: comma-separated map names")->capture_default_str();
      sub.add_option("--points", a->points, "closed: random points per formula (stress points come on top)")->capture_default_str()->check(CLI::PositiveNumber);
      sub.add_option("--repeats", a->repeats, "timing repeats (median, min, max)")->capture_default_str()->check(CLI::PositiveNumber);
      sub.add_option("--sweep", a->sweep, "scenes: steps/tolerances per integrator")->capture_default_str()->check(CLI::PositiveNumber);
      sub.add_option("--steps", a->steps, "maps: points along the stress axis")->capture_default_str()->check(CLI::Range(2, 100000));
      sub.add_option("-o,--out", a->out, "output directory (created; default: a new directory ./derivcheck-charts[-N])");
      sub.add_option("--root", a->root, "project root (for derivations/handout9)")->capture_default_str();
      sub.add_option("--csv", a->csv, "write only this CSV (no figures)");
      sub.add_option("--corpus", a->corpus, "checker: labelled claim corpus (default ROOT/tests/data/corpus.jsonl)");
      sub.add_option("--k", a->ks, "checker: probe point counts")->capture_default_str();
      sub.add_option("--digits", a->digits, "checker: probe precisions (>= 20)")->capture_default_str();
      sub.add_flag("--no-figures", a->no_figures, "CSV only");
      sub.add_option("--inputs", a->inputs, "evalpoints: parameter order of the points file");
      sub.add_option("--points-file", a->points_file, "evalpoints: raw float64 points, row-major");
      sub.add_option("--out-file", a->out_file, "evalpoints: raw float64 results");
      sub.add_flag("--serve", a->serve, "evalpoints: time one tool per stdin line (derivcheck | tape | handwritten), for interleaved peers");
      return [a]() -> int {
        try {
          prepare_output(*a);
          if (a->kind == "closed") return run_closed(*a);
          if (a->kind == "scenes") return run_scenes(*a);
          if (a->kind == "maps") return run_maps(*a);
          if (a->kind == "evalpoints") return run_evalpoints(*a);
          if (a->kind == "checker") return run_checker(*a);
          run_closed(*a);
          run_scenes(*a);
          run_maps(*a);
          return run_checker(*a);
        } catch (const std::invalid_argument& e) {
          std::cerr << "derivcheck chart: error: " << e.what() << "\n";
          return dc::cli::kExitInputError;
        } catch (const std::domain_error& e) {
          std::cerr << "derivcheck chart: error: " << e.what() << "\n";
          return dc::cli::kExitInputError;
        }
      };
    });

}  // namespace
