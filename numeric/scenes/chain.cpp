// Example 9.7: a chain falling on a scale.
//
// The falling part is in free fall. The handout's v = sqrt(2 g x) read as the ODE
// x' = sqrt(2 g x) with x(0) = 0 is not Lipschitz at 0 and has the solution x ≡ 0 besides
// x = g t²/2; a one-step method started at x = 0 evaluates sqrt(0) = 0 at every stage and never
// leaves 0 (chain_first_order_naive shows it). So the scene integrates x'' = g, x(0) = x'(0) = 0,
// which has a unique solution.
//
// The scale force comes from the momentum balance of the whole chain, with the simulated state:
// P = -rho (L - x) v (the hanging part moves down), dP/dt = N - m g, so
//   N = m g + rho v² - rho (L - x) x''.
// The handout's closed form is N = 3 x m g / L (using v² = 2 g x).
#include <cmath>

#include "numeric/scenes/closed_forms.hpp"
#include "numeric/scenes/derived.hpp"
#include "numeric/scenes/scenes.hpp"

namespace dc::scenes {

double chain_first_order_naive(double g, Method m, double h, double t_end) {
  OdeSystem sys;
  sys.dim = 1;
  sys.rhs = [g](const State& x, State& d, double) { d[0] = std::sqrt(2 * g * std::max(0.0, x[0])); };
  Integrator ig(m, sys, 1e-10);
  State x = {0};
  integrate(ig, x, 0, t_end, h);
  return x[0];
}

SceneResult run_chain(const Params& p, const RunOptions& opt) {
  const double m = p.at("m"), L = p.at("L"), g = p.at("g"), x_rep = p.at("x");
  const double rho = m / L;
  OdeSystem sys;
  sys.dim = 2;  // x (fallen length = length on the scale), v = x'
  sys.rhs = [g](const State& s, State& d, double) {
    d[0] = s[1];
    d[1] = g;
  };
  sys.jacobian = [](const State&, std::vector<double>& J, State& dfdt, double) {
    J = {0, 1, 0, 0};
    dfdt[0] = dfdt[1] = 0;
  };
  sys.n_pos = 1;
  sys.accel = [g](const double*, double* a, double) { a[0] = g; };

  auto N_of = [&](const State& s) { return m * g + rho * s[1] * s[1] - rho * (L - s[0]) * g; };
  Integrator ig(opt.method, sys, opt.tol);
  State x = {0, 0};
  SceneResult r;
  r.series.columns = {"t", "x", "v", "N", "N_closed_form"};
  double max_err = 0;
  auto observe = [&](const State& s, double t) {
    const double N = N_of(s), Nc = cf::chain_N(m, L, g, s[0]);
    max_err = std::isfinite(N) ? std::max(max_err, std::abs(N - Nc)) : HUGE_VAL;
    r.series.rows.push_back({t, s[0], s[1], N, Nc});
  };
  const double t_guard = 100 * std::sqrt(2 * L / g);
  // first leg: up to the reporting point x, then on to x = L (whole chain on the scale)
  State at_rep = x;
  double t = 0;
  if (x_rep > 0) {
    auto ev = integrate(ig, x, 0, t_guard, opt.h, [&](const State& s, double) { return x_rep - s[0]; }, observe);
    t = ev.t;
    at_rep = x;
  } else {
    observe(x, 0);
  }
  const double t_rep = t;
  if (x_rep < L) {
    r.series.rows.pop_back();  // the observer repeats the start point
    auto ev = integrate(ig, x, t, t_guard, opt.h, [&](const State& s, double) { return L - s[0]; }, observe);
    t = ev.t;
  }
  const std::string file = "10_falling_chain.dc";
  const std::map<std::string, double> at = {{"m", m}, {"L", L}, {"g", g}, {"x", at_rep[0]}};
  r.comparisons.push_back(closed_form(opt, "N(x)", "N", N_of(at_rep), cf::chain_N(m, L, g, at_rep[0]), "3 x m g / L",
                                      file, "scale_force", at));
  r.comparisons.push_back(closed_form(opt, "v(x)", "m/s", at_rep[1], cf::chain_v(g, at_rep[0]), "sqrt(2 g x)", file,
                                      "fall_speed", at));
  r.comparisons.push_back({"N(L)", "N", N_of(x), cf::chain_N(m, L, g, x[0]), "3 m g: three times the weight", "built-in"});
  r.comparisons.push_back({"t_landed", "s", t, std::sqrt(2 * L / g), "sqrt(2 L/g) (free fall)", "built-in"});
  r.metrics["x_reported"] = at_rep[0];
  r.metrics["t_reported"] = t_rep;
  r.metrics["max_force_error"] = max_err;
  r.rhs_evaluations = ig.rhs_evaluations();
  r.notes.push_back("the last link lands at t = " + std::to_string(t) + " s; then the scale reads m g = " +
                    std::to_string(m * g) + " N (the force drops from 3 m g)");
  r.figure = {"t", "$t$ [s]", "$N$ [N]", {{"N", "momentum balance"}, {"N_closed_form", "$3xmg/L$"}}};
  return r;
}

}  // namespace dc::scenes
