// Example 9.3: two masses and a spring, 1-D along the spring.
//   m1 x1'' =  k (x2 - x1 - L0)
//   m2 x2'' = -k (x2 - x1 - L0)
// No external force: P = m1 v1 + m2 v2 is conserved and x_G moves at v_G = m2 v0/(m1 + m2)
// (4/3 m/s for the handout's numbers); E = T + k s²/2 is conserved by the exact flow.
#include <algorithm>
#include <cmath>

#include "numeric/scenes/closed_forms.hpp"
#include "numeric/scenes/derived.hpp"
#include "numeric/scenes/scenes.hpp"

namespace dc::scenes {

SpringState spring_exact(const Params& p, double t) {
  const double m1 = p.at("m1"), m2 = p.at("m2"), k = p.at("k"), L0 = p.at("L0"), v0 = p.at("v0");
  const double M = m1 + m2;
  const double omega = std::sqrt(k * M / (m1 * m2));
  const double vG = cf::v_G(m1, m2, 0, v0);
  const double xG = vG * t + m2 * L0 / M;                 // x_G(0) = m2 L0 / M
  const double s = v0 / omega * std::sin(omega * t);     // extension
  const double sd = v0 * std::cos(omega * t);
  // x1 = x_G - (m2/M)(L0 + s), x2 = x_G + (m1/M)(L0 + s)
  return {xG - m2 / M * (L0 + s), xG + m1 / M * (L0 + s), vG - m2 / M * sd, vG + m1 / M * sd};
}

SceneResult run_spring(const Params& p, const RunOptions& opt) {
  const double m1 = p.at("m1"), m2 = p.at("m2"), k = p.at("k"), L0 = p.at("L0"), v0 = p.at("v0"),
               t_end = p.at("t_end");
  const double M = m1 + m2;

  OdeSystem sys;
  sys.dim = 4;  // x1, x2, v1, v2
  sys.rhs = [=](const State& x, State& d, double) {
    const double f = k * (x[1] - x[0] - L0);  // spring force on m1 (towards m2 when stretched)
    d[0] = x[2];
    d[1] = x[3];
    d[2] = f / m1;
    d[3] = -f / m2;
  };
  sys.jacobian = [=](const State&, std::vector<double>& J, State& dfdt, double) {
    std::fill(J.begin(), J.end(), 0.0);
    J[0 * 4 + 2] = 1;
    J[1 * 4 + 3] = 1;
    J[2 * 4 + 0] = -k / m1, J[2 * 4 + 1] = k / m1;
    J[3 * 4 + 0] = k / m2, J[3 * 4 + 1] = -k / m2;
    std::fill(dfdt.begin(), dfdt.end(), 0.0);
  };
  sys.n_pos = 2;
  sys.accel = [=](const double* q, double* a, double) {
    const double f = k * (q[1] - q[0] - L0);
    a[0] = f / m1;
    a[1] = -f / m2;
  };

  Integrator ig(opt.method, sys, opt.tol);
  State x = {0, L0, 0, v0};
  const double P0 = m2 * v0;
  const double E0 = 0.5 * m2 * v0 * v0;
  double max_dE = 0, max_dP = 0, max_err = 0;
  SceneResult r;
  r.series.columns = {"t", "x1", "x2", "x_G", "v1", "v2", "energy", "momentum"};
  // keep at most ~2000 rows in the CSV
  const long total_steps = static_cast<long>(std::ceil(t_end / opt.h));
  const long every = std::max(1L, total_steps / 2000);
  long step = 0;
  auto observe = [&](const State& s, double t) {
    const double ext = s[1] - s[0] - L0;
    const double E = 0.5 * m1 * s[2] * s[2] + 0.5 * m2 * s[3] * s[3] + 0.5 * k * ext * ext;
    const double P = m1 * s[2] + m2 * s[3];
    // a blown-up run gives inf/NaN: count it as an infinite drift (std::max would drop NaN)
    auto upd = [](double& m, double v) { m = std::isfinite(v) ? std::max(m, v) : HUGE_VAL; };
    upd(max_dE, std::abs(E - E0));
    upd(max_dP, std::abs(P - P0));
    const auto ex = spring_exact(p, t);
    upd(max_err, std::abs(s[0] - ex.x1));
    upd(max_err, std::abs(s[1] - ex.x2));
    if (step++ % every == 0 || t >= t_end)
      r.series.rows.push_back({t, s[0], s[1], (m1 * s[0] + m2 * s[1]) / M, s[2], s[3], E, P});
  };
  integrate(ig, x, 0, t_end, opt.h, nullptr, observe);

  const double xG0 = m2 * L0 / M, xG1 = (m1 * x[0] + m2 * x[1]) / M;
  const double vG_cf = cf::v_G(m1, m2, 0, v0);
  r.comparisons.push_back(closed_form(opt, "v_G", "m/s", (xG1 - xG0) / t_end, vG_cf,
                                      "(m1 v_10 + m2 v0)/(m1 + m2), v_10 = 0; simulated: (x_G(t_end) - x_G(0))/t_end",
                                      "04_system_of_particles.dc", "vG_two", {{"m1", m1}, {"m2", m2}, {"v_10", 0}, {"v0", v0}}));
  r.comparisons.push_back({"P(t_end)", "N s", m1 * x[2] + m2 * x[3], P0, "m2 v0 (conserved, no external force)", "built-in"});
  const double ext = x[1] - x[0] - L0;
  r.comparisons.push_back({"E(t_end)", "J", 0.5 * m1 * x[2] * x[2] + 0.5 * m2 * x[3] * x[3] + 0.5 * k * ext * ext, E0,
                           "m2 v0^2/2 (conserved by the exact flow)", "built-in"});
  const auto ex = spring_exact(p, t_end);
  r.comparisons.push_back({"x2(t_end)", "m", x[1], ex.x2, "exact solution of the linear ODE", "built-in"});
  r.metrics["max_energy_drift"] = E0 > 0 ? max_dE / E0 : max_dE;  // relative
  r.metrics["max_momentum_drift"] = P0 != 0 ? max_dP / std::abs(P0) : max_dP;
  r.metrics["max_position_error"] = max_err;   // [m], against the exact solution
  r.metrics["omega"] = std::sqrt(k * M / (m1 * m2));
  r.rhs_evaluations = ig.rhs_evaluations();
  r.notes.push_back("omega = sqrt(k (m1+m2)/(m1 m2)) = " + std::to_string(r.metrics["omega"]) +
                    " rad/s; explicit steppers need omega h below their stability limit (verlet: 2, rk4: 2.83; euler: none)");
  r.figure = {"t", "$t$ [s]", "position [m]", {{"x1", "$x_1$"}, {"x2", "$x_2$"}, {"x_G", "$x_G$"}}};
  return r;
}

}  // namespace dc::scenes
