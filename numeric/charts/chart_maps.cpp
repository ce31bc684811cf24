// Chart data, second half: stability maps of the closed forms (where a formula as written loses
// its digits, and the stable form that keeps them) and the scenes' work-precision rows.
#include "numeric/charts/chart_data.hpp"
#include "numeric/charts/internal/chart_support.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>

#include "derivations/reader/derivation.hpp"
#include "derivations/symbolic/functions.hpp"
#include "derivations/decide/prove.hpp"
#include "numeric/certified/certified.hpp"
#include "numeric/certified/certified_batch.hpp"
#include "numeric/crosscheck.hpp"
#include "numeric/evaluator.hpp"
#include "numeric/reference/exact.hpp"
#include "numeric/formula_evaluator.hpp"
#include "numeric/reference/reference.hpp"
#include "numeric/scenes/closed_forms.hpp"
#include "numeric/scenes/scenes.hpp"
#include "numeric/scenes/spec.hpp"

namespace dc::chart {

using GiNaC::ex;
using GiNaC::numeric;
using namespace dc::chart::support;

// ---------------------------------------------------------------------------------------------
// stability maps

const std::vector<MapInfo>& closed_form_maps() {
  static const std::vector<MapInfo> maps = {
      {"e_to_1", "energy loss as e -> 1 (05_direct_impact.dc:energy_loss_general)", "1 - e",
       "(1 - e^2)/2 ... as written, evaluator with rewrites off", "stable steps of the file; the evaluator"},
      {"v1_to_v2", "plastic energy loss as v1 - v2 -> 0 (05_direct_impact.dc:energy_loss_plastic)", "(v1 - v2)/v1",
       "T before - T after (first side of the chain)", "1/2 m1 m2/(m1+m2) (v1-v2)^2 (last side)"},
      {"mu_to_0", "tennis ball rebound as mu -> 0 (07_two_ball_bounce.dc:v1p_bounce)", "mu = m1/m2",
       "the formula as written", "the evaluator"},
      {"m2_to_inf", "energy loss as m2 -> oo, m1 = 1e150 kg (05_direct_impact.dc:energy_loss_general)", "m2 [kg]",
       "m1 m2/(m1+m2) as written (m1 m2 overflows)", "the evaluator (m1/(m1+m2) m2)"},
      {"theta_to_0", "ballistic pendulum angle as v0 -> 0 (06_ballistic_pendulum.dc:deflection)", "v0 [m/s]",
       "acos(1 - ...) as written", "half-angle 2 asin(...) (closed_forms.hpp), stable steps of the file"},
      {"mr_to_m0", "rocket velocity as m_r -> m0 (09_rocket.dc:velocity_symbols)", "1 - m_r/m0",
       "-u_e ln(m_r/m0) - g t as written", "-u_e log1p(-mu t/m0) - g t (closed_forms.hpp), stable steps"},
  };
  return maps;
}

namespace {

struct MapCase {
  std::string method;
  std::function<double(const std::vector<double>&)> eval;   // args in `names` order
};

// Evaluate an expression in double through a compiled program with inputs `syms`.
MapCase compiled_case(const std::string& method, const ex& e, const std::vector<GiNaC::symbol>& syms,
                      const num::CompileOptions& o) {
  auto ev = std::make_shared<num::Evaluator<double>>(num::compile(e, syms, o));
  return {method, [ev](const std::vector<double>& x) { return (*ev)(x.data()); }};
}


}  // namespace

std::vector<MapRow> closed_form_map(const std::string& root, const std::string& name, int steps) {
  if (steps < 2) throw std::invalid_argument("chart map: need at least 2 steps");
  const std::string dir = root + "/derivations/handout9/";
  std::vector<MapRow> rows;
  // Each map: the file, the expression(s), symbols in order, the fixed values, and the stress
  // value at step i (as exact doubles).
  std::string file, label;
  std::vector<std::string> names;
  std::function<std::vector<double>(int)> point;   // point at step i
  std::function<double(const std::vector<double>&)> xval;
  if (name == "e_to_1" || name == "m2_to_inf") {
    file = "05_direct_impact.dc", label = "energy_loss_general";
    names = {"m1", "m2", "v1", "v2", "e"};
    if (name == "e_to_1") {
      point = [&](int i) { return std::vector<double>{1, 2, 3, 1, 1 - std::ldexp(1.0, -1 - 51 * i / (steps - 1))}; };
      xval = [](const std::vector<double>& x) { return 1 - x[4]; };
    } else {
      point = [&](int i) { return std::vector<double>{1e150, std::pow(10.0, 140 + 168.0 * i / (steps - 1)), 3, 1, 0.5}; };
      xval = [](const std::vector<double>& x) { return x[1]; };
    }
  } else if (name == "v1_to_v2") {
    file = "05_direct_impact.dc", label = "energy_loss_plastic";
    names = {"m1", "m2", "v1", "v2"};
    point = [&](int i) { return std::vector<double>{1, 2, 3, 3 * (1 - std::ldexp(1.0, -1 - 51 * i / (steps - 1)))}; };
    xval = [](const std::vector<double>& x) { return (x[2] - x[3]) / x[2]; };
  } else if (name == "mu_to_0") {
    file = "07_two_ball_bounce.dc", label = "v1p_bounce";
    names = {"v0", "e2", "e12", "mu"};
    point = [&](int i) { return std::vector<double>{-4, 1, 1, std::ldexp(1.0, -60 * i / (steps - 1))}; };
    xval = [](const std::vector<double>& x) { return x[3]; };
  } else if (name == "theta_to_0") {
    file = "06_ballistic_pendulum.dc", label = "deflection";
    names = {"m", "M", "v0", "L", "g"};
    point = [&](int i) { return std::vector<double>{0.01, 2, 300 * std::pow(10.0, -12.0 * i / (steps - 1)), 1, 9.81}; };
    xval = [](const std::vector<double>& x) { return x[2]; };
  } else if (name == "mr_to_m0") {
    file = "09_rocket.dc", label = "velocity_symbols";
    names = {"u_e", "m0", "mu", "g", "t"};
    // m_r = m0 - mu t: burn fraction mu t/m0 from 1/2 down to 1e-15
    point = [&](int i) { return std::vector<double>{2500, 1000, 10, 9.81, 50 * std::pow(10.0, -14.0 * i / (steps - 1))}; };
    xval = [](const std::vector<double>& x) { return x[2] * x[4] / x[1]; };
  } else {
    throw std::invalid_argument("unknown map '" + name + "'; maps: e_to_1, v1_to_v2, mu_to_0, m2_to_inf, theta_to_0, mr_to_m0");
  }
  const Derivation d = load_derivation(dir + file);
  const Step* st = d.find(label);
  if (!st) throw std::invalid_argument("chart map: " + file + " has no step " + label);
  auto [plain, syms] = plain_symbols(d, names);

  ex ref_expr;
  std::vector<MapCase> cases;
  if (name == "mr_to_m0") {
    // v = -u_e log(m_r/m0) - g t with the prescribed mass m_r = m0 - mu t: the naive double
    // evaluation rounds m_r/m0 first.
    const ex side = claim_sides(d, *st).back().subs(plain);
    ref_expr = side.subs(d.symbols.find("m_r")->sym == syms[1] - syms[2] * syms[4]);
    cases.push_back(compiled_case("naive: -u_e ln(m_r/m0) - g t", ref_expr, syms, naive_options()));
    cases.push_back({"stable: -u_e log1p(-mu t/m0) - g t (closed_forms.hpp)",
                     [](const std::vector<double>& x) { return scenes::cf::rocket_v(x[1], x[2], x[0], x[3], x[4]); }});
  } else if (name == "v1_to_v2") {
    const auto sides = claim_sides(d, *st);
    ref_expr = sides.back().subs(plain);
    cases.push_back(compiled_case("naive: T before - T after", sides.at(1).subs(plain), syms, naive_options()));
    cases.push_back(compiled_case("stable: 1/2 m1 m2/(m1+m2) (v1-v2)^2", ref_expr, syms, {}));
  } else {
    ref_expr = formula(d, label).expr.subs(plain);
    cases.push_back(compiled_case("naive: as written", ref_expr, syms, naive_options()));
    cases.push_back(compiled_case("evaluator (rewrites on)", ref_expr, syms, {}));
    if (name == "theta_to_0")
      cases.push_back({"stable: 2 asin(m v0/((M+m) 2 sqrt(g L))) (closed_forms.hpp)", [](const std::vector<double>& x) {
                         return scenes::cf::pendulum_theta(x[0], x[1], x[2], x[3], x[4]);
                       }});
  }
  for (const Step& s : d.steps)   // (the rocket's stable form takes m_r, not m0 - mu t: its case is above)
    if (s.stable_of && *s.stable_of == label && name != "mr_to_m0") {
      const PlainFormula sf = plain_formula(d, formula(d, s.label).expr);
      auto ev = std::make_shared<num::Evaluator<double>>(num::compile(sf.expr, sf.inputs));
      std::vector<std::size_t> idx;
      for (const auto& p : sf.inputs) {
        auto it = std::find_if(syms.begin(), syms.end(), [&](const GiNaC::symbol& q) { return q.get_name() == p.get_name(); });
        if (it == syms.end()) throw std::invalid_argument("chart map: stable step " + s.label + " uses " + p.get_name());
        idx.push_back(static_cast<std::size_t>(it - syms.begin()));
      }
      cases.push_back({"stable: " + s.label + " (" + file + ")", [ev, idx](const std::vector<double>& x) {
                         std::vector<double> a;
                         for (auto j : idx) a.push_back(x[j]);
                         return (*ev)(a.data());
                       }});
    }

  for (int i = 0; i < steps; ++i) {
    progress("chart map " + name + ": " + std::to_string(i + 1) + "/" + std::to_string(steps));
    const auto x = point(i);
    GiNaC::exmap m;
    for (std::size_t j = 0; j < syms.size(); ++j) m[syms[j]] = num::exact_rational(x[j]);
    const numeric ref = num::reference_value(ref_expr, m, 60);
    for (const auto& c : cases) {
      const double y = c.eval(x);
      rows.push_back({name, xval(x), c.method, y, bits_from_ulps(num::error_in_ulps(y, ref))});
    }
  }
  progress("");
  return rows;
}

Table to_table(const std::vector<MapRow>& rows) {
  Table t{{"map", "stress", "method", "value", "bits_lost"}, {}};
  for (const auto& r : rows) t.rows.push_back({r.map, fmt(r.stress), r.method, fmt(r.value), fmt(r.bits_lost)});
  return t;
}

std::vector<StiffRow> stiff_spring_map(double k, int steps, double omega_h_max) {
  if (!(k > 0) || steps < 2 || !(omega_h_max > 0)) throw std::invalid_argument("stiff_spring_map: k, steps, omega_h_max must be positive");
  const auto& spec = scenes::find_scene("spring");
  scenes::Params p = scenes::defaults(spec);
  p["k"] = k;
  const double omega = std::sqrt(k * (p["m1"] + p["m2"]) / (p["m1"] * p["m2"]));
  p["t_end"] = 200 / omega;   // ~32 periods
  std::vector<StiffRow> rows;
  for (scenes::Method m : {scenes::Method::euler, scenes::Method::rk4, scenes::Method::verlet, scenes::Method::rosenbrock}) {
    for (int i = 0; i < steps; ++i) {
      const double wh = omega_h_max * (0.05 + 0.95 * i / (steps - 1));
      progress("chart stiff " + std::string(scenes::method_name(m)) + " omega h = " + fmt(wh));
      scenes::RunOptions o;
      o.method = m;
      o.h = wh / omega;
      const auto r = scenes::run_scene(spec, p, o);
      rows.push_back({std::string(scenes::method_name(m)), wh, r.metric("max_position_error"), r.metric("max_energy_drift")});
    }
  }
  progress("");
  return rows;
}

Table to_table(const std::vector<StiffRow>& rows) {
  Table t{{"method", "omega_h", "max_position_error", "energy_drift"}, {}};
  for (const auto& r : rows) t.rows.push_back({r.method, fmt(r.omega_h), fmt(r.max_position_error), fmt(r.energy_drift)});
  return t;
}

// ---------------------------------------------------------------------------------------------
// scene work-precision

std::string scene_quantity(const std::string& scene) {
  static const std::map<std::string, std::string> q = {
      {"spring", "x2(t_end)"}, {"pendulum", "theta_max"}, {"rocket", "v_burnout"}, {"ladder", "sin_theta_sep"},
      {"chain", "t_landed"}, {"cannon", "v_ratio"}};
  auto it = q.find(scene);
  if (it == q.end()) throw std::invalid_argument("chart scenes: no work-precision quantity for scene '" + scene + "'");
  return it->second;
}

std::vector<SceneRow> scene_wp(const std::string& scene, const SceneOptions& opt) {
  const auto& spec = scenes::find_scene(scene);
  const std::string quantity = scene_quantity(scene);
  const scenes::Params p = scenes::defaults(spec);
  // largest fixed step: 20x the scene's default (halved down the sweep)
  const double h0 = 20 * spec.default_h;
  std::vector<SceneRow> rows;
  for (scenes::Method m : spec.methods) {
    for (int j = 0; j < opt.sweep; ++j) {
      scenes::RunOptions o;
      o.method = m;
      std::string param;
      if (m == scenes::Method::dopri5) {
        o.tol = std::pow(10.0, -3 - j * 9.0 / std::max(1, opt.sweep - 1));
        o.h = 0;   // output spacing: the scene default
        param = "tol=" + fmt(o.tol);
      } else {
        o.h = h0 * std::ldexp(1.0, -j);
        param = "h=" + fmt(o.h);
      }
      progress("chart scenes " + scene + " " + std::string(scenes::method_name(m)) + " " + param);
      scenes::SceneResult last;
      bool failed = false;
      const Stat t = time_per_op([&] {
        try {
          last = scenes::run_scene(spec, p, o);
        } catch (const std::exception&) {
          failed = true;
        }
      }, 1, opt.repeats);
      if (failed) continue;
      SceneRow r{scene, quantity, std::string(scenes::method_name(m)), param, t, 0, -1, last.rhs_evaluations};
      const auto& c = last.get(quantity);
      r.rel_error = std::isfinite(c.simulated) ? c.rel_error() : HUGE_VAL;
      if (last.metrics.count("max_energy_drift")) r.drift = last.metric("max_energy_drift");
      rows.push_back(r);
    }
  }
  progress("");
  return rows;
}

Table to_table(const std::vector<SceneRow>& rows) {
  Table t{{"scene", "quantity", "method", "param", "seconds_median", "seconds_min", "seconds_max", "rel_error", "drift",
           "rhs_evaluations"}, {}};
  for (const auto& r : rows)
    t.rows.push_back({r.scene, r.quantity, r.method, r.param, fmt(r.seconds.median), fmt(r.seconds.min), fmt(r.seconds.max),
                      fmt(r.rel_error), r.drift < 0 ? "" : fmt(r.drift), std::to_string(r.rhs_evaluations)});
  return t;
}

}  // namespace dc::chart
