// Example 9.2: a ladder (uniform rod, length l, mass m) sliding on a frictionless floor against a
// frictionless wall. theta is the angle from the floor; G = (l/2)(cos theta, sin theta).
// While the top touches the wall there is one DOF; energy (T = m l² theta'²/6 about the
// instantaneous centre) gives theta'' = -(3 g/(2 l)) cos theta. The wall reaction is
// N_w = m x_G'' = -m (l/2)(cos theta theta'² + sin theta theta''); the run stops where it
// vanishes (event) and the wall's impulse J = int N_w dt (integrated alongside) is compared with
// m v_Gx there and with (m/3) sqrt(g l) sin^{3/2} theta0; theta there with asin(2/3 sin theta0).
#include <cmath>
#include <numbers>

#include "numeric/scenes/closed_forms.hpp"
#include "numeric/scenes/derived.hpp"
#include "numeric/scenes/scenes.hpp"

namespace dc::scenes {

SceneResult run_ladder(const Params& p, const RunOptions& opt) {
  const double m = p.at("m"), l = p.at("l"), g = p.at("g");
  const double theta0 = p.at("theta0") * std::numbers::pi / 180;
  auto theta_dd = [=](double th) { return -1.5 * g / l * std::cos(th); };
  auto wall = [=](double th, double om) {
    return -m * 0.5 * l * (std::cos(th) * om * om + std::sin(th) * theta_dd(th));
  };
  auto floor = [=](double th, double om) {  // N_f = m (g + y_G'')
    return m * (g + 0.5 * l * (std::cos(th) * theta_dd(th) - std::sin(th) * om * om));
  };
  OdeSystem sys;
  sys.dim = 3;  // theta, theta', J (the wall's impulse so far)
  sys.rhs = [=](const State& s, State& d, double) {
    d[0] = s[1];
    d[1] = theta_dd(s[0]);
    d[2] = wall(s[0], s[1]);
  };
  Integrator ig(opt.method, sys, opt.tol);
  State x = {theta0, 0, 0};
  SceneResult r;
  r.series.columns = {"t", "theta", "theta_dot", "N_wall", "N_floor", "J"};
  const double E0 = m * g * 0.5 * l * std::sin(theta0);
  double max_dE = 0, min_floor = HUGE_VAL;
  auto observe = [&](const State& s, double t) {
    const double E = m * l * l * s[1] * s[1] / 6 + m * g * 0.5 * l * std::sin(s[0]);
    max_dE = std::isfinite(E) ? std::max(max_dE, std::abs(E - E0) / E0) : HUGE_VAL;
    min_floor = std::min(min_floor, floor(s[0], s[1]));
    r.series.rows.push_back({t, s[0], s[1], wall(s[0], s[1]), floor(s[0], s[1]), s[2]});
  };
  const double t_guard = 1000 * std::sqrt(l / g);
  auto ev = integrate(ig, x, 0, t_guard, opt.h, [&](const State& s, double) { return wall(s[0], s[1]); }, observe);

  const double vGx = -0.5 * l * std::sin(x[0]) * x[1];  // x_G' at separation (x[1] < 0)
  r.comparisons.push_back({"sin_theta_sep", "1", std::sin(x[0]), 2.0 / 3.0 * std::sin(theta0), "(2/3) sin theta0", "built-in"});
  r.comparisons.push_back(closed_form(opt, "J_wall", "N s", x[2], cf::ladder_wall_impulse(m, l, g, theta0),
                                      "(m/3) sqrt(g l) sin^(3/2) theta0", "03_ladder.dc", "wall_impulse",
                                      {{"m", m}, {"l", l}, {"g", g}, {"theta0", theta0}}));
  r.comparisons.push_back({"J_vs_momentum", "N s", x[2], m * vGx, "m v_Gx at separation (impulse = momentum change)", "built-in"});
  r.metrics["t_sep"] = ev.t;
  r.metrics["theta_sep_deg"] = x[0] * 180 / std::numbers::pi;
  r.metrics["max_energy_drift"] = max_dE;
  r.metrics["min_floor_reaction"] = min_floor;
  r.rhs_evaluations = ig.rhs_evaluations();
  r.notes.push_back("the top leaves the wall at t = " + std::to_string(ev.t) + " s, theta = " +
                    std::to_string(r.metrics["theta_sep_deg"]) + " deg; floor reaction stays >= " +
                    std::to_string(min_floor) + " N (> 0: the foot stays on the floor)");
  r.figure = {"t", "$t$ [s]", "force [N]", {{"N_wall", "$N_w$"}, {"N_floor", "$N_f$"}}};
  return r;
}

}  // namespace dc::scenes
