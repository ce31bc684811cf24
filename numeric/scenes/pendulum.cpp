// Example 9.5: ballistic pendulum. The impact is solved as the linear system (9.6)+(9.7) with
// e = 0 (common velocity v1); then the swing theta'' = -(g/L) sin theta from theta = 0,
// theta' = v1/L is integrated until theta' = 0 (event located by the secant method), and
// theta_max is compared with theta = arccos(1 - (m/(M+m))² v0²/(2Lg)).
#include <cmath>
#include <numbers>

#include "numeric/scenes/closed_forms.hpp"
#include "numeric/scenes/derived.hpp"
#include "numeric/scenes/scenes.hpp"

namespace dc::scenes {

void check_pendulum(const Params& p) {
  const double m = p.at("m"), M = p.at("M"), v0 = p.at("v0"), L = p.at("L"), g = p.at("g");
  // The strings stay taut up to the turning point only if it is at or below the horizontal:
  // (m/(M+m))² v0²/(2Lg) <= 1, i.e. v0 <= (M+m)/m sqrt(2 g L).
  const double v0_max = (M + m) / m * std::sqrt(2 * g * L);
  if (v0 > v0_max) {
    const double arg = 1 - std::pow(m / (M + m), 2) * v0 * v0 / (2 * L * g);
    std::string why = arg >= -1 ? " (theta_max would be " + std::to_string(std::acos(arg)) + " rad > pi/2: the strings go slack before the turning point)"
                                : " (the acos argument " + std::to_string(arg) + " < -1: it would swing over the top)";
    out_of_bounds("pendulum", "v0", v0, "m/s",
                  "v0 <= (M+m)/m sqrt(2 g L) = " + std::to_string(v0_max) + " m/s, so the box swings at most to the horizontal" + why);
  }
}

SceneResult run_pendulum(const Params& p, const RunOptions& opt) {
  const double m = p.at("m"), M = p.at("M"), v0 = p.at("v0"), L = p.at("L"), g = p.at("g");
  // impact: (9.6) m v0 + M 0 = m v'1 + M v'2 and (9.7) with e = 0
  const DirectImpact imp = solve_direct_impact(m, M, v0, 0, 0);
  const double v1 = imp.v2p;

  OdeSystem sys;
  sys.dim = 2;  // theta, theta'
  sys.rhs = [=](const State& x, State& d, double) {
    d[0] = x[1];
    d[1] = -(g / L) * std::sin(x[0]);
  };
  sys.jacobian = [=](const State& x, std::vector<double>& J, State& dfdt, double) {
    J = {0, 1, -(g / L) * std::cos(x[0]), 0};
    dfdt[0] = dfdt[1] = 0;
  };
  sys.n_pos = 1;
  sys.accel = [=](const double* q, double* a, double) { a[0] = -(g / L) * std::sin(q[0]); };

  Integrator ig(opt.method, sys, opt.tol);
  State x = {0, v1 / L};
  SceneResult r;
  r.series.columns = {"t", "theta", "theta_dot"};
  auto observe = [&](const State& s, double t) { r.series.rows.push_back({t, s[0], s[1]}); };
  // the swing to the horizontal takes at most a few periods' worth; bound the run generously
  const double t_max_run = 1000 * std::sqrt(L / g);
  EventResult ev{};
  if (v1 > 0) ev = integrate(ig, x, 0, t_max_run, opt.h, [](const State& s, double) { return s[1]; }, observe);
  else observe(x, 0);

  const std::map<std::string, double> at = {{"m", m}, {"M", M}, {"v0", v0}, {"L", L}, {"g", g}};
  r.comparisons.push_back(closed_form(opt, "v1", "m/s", v1, cf::pendulum_v1(m, M, v0), "m v0/(M+m)",
                                      "06_ballistic_pendulum.dc", "v1_after", at));
  r.comparisons.push_back(closed_form(opt, "theta_max", "rad", x[0], cf::pendulum_theta(m, M, v0, L, g),
                                      "arccos(1 - (m/(M+m))^2 v0^2/(2Lg)) (built-in: 2 asin(m v0/((M+m) 2 sqrt(gL))))",
                                      "06_ballistic_pendulum.dc", "deflection", at));
  const double T1 = 0.5 * (M + m) * v1 * v1;
  const double dT = 0.5 * m * v0 * v0 - T1;
  r.comparisons.push_back(closed_form(opt, "dT_impact", "J", dT, cf::dT_general(m, M, v0, 0, 0),
                                      "(1-e^2)/2 m M/(M+m) v0^2 with e = 0", "05_direct_impact.dc",
                                      "energy_loss_general", {{"m1", m}, {"m2", M}, {"v1", v0}, {"v2", 0}, {"e", 0}}));
  r.metrics["t_turn"] = ev.t;
  r.metrics["theta_max_deg"] = x[0] * 180 / std::numbers::pi;
  r.rhs_evaluations = ig.rhs_evaluations();
  r.notes.push_back("turning point at t = " + std::to_string(ev.t) + " s, theta_max = " +
                    std::to_string(r.metrics["theta_max_deg"]) + " deg; kinetic energy kept by the impact: " +
                    std::to_string(T1 / (0.5 * m * v0 * v0 + 1e-300)));
  r.figure = {"t", "$t$ [s]", "$\\theta$ [rad]", {{"theta", "$\\theta$"}}};
  return r;
}

}  // namespace dc::scenes
