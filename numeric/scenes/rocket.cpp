// §9.4: the ideal rocket with gravity. m_r(t) = m0 - mu t is prescribed; the momentum balance
// m_r dv/dt = u_e mu - m_r g is integrated from rest to burnout (m_r reaching the given dry
// mass) and v(t) is compared with v = -u_e ln(m_r/m0) - g t at every step.
#include <cmath>

#include "numeric/scenes/closed_forms.hpp"
#include "numeric/scenes/scenes.hpp"

namespace dc::scenes {

SceneResult run_rocket(const Params& p, const RunOptions& opt) {
  const double m0 = p.at("m0"), m_end = p.at("m_r"), mu = p.at("mu"), u_e = p.at("u_e"), g = p.at("g");
  const double t_b = (m0 - m_end) / mu;  // burnout: t = (m0 - m_r)/mu

  auto accel = [=](double t) { return u_e * mu / (m0 - mu * t) - g; };  // thrust/m_r - g
  OdeSystem sys;
  sys.dim = 2;  // z, v
  sys.rhs = [=](const State& x, State& d, double t) {
    d[0] = x[1];
    d[1] = accel(t);
  };
  sys.jacobian = [=](const State&, std::vector<double>& J, State& dfdt, double t) {
    J = {0, 1, 0, 0};
    const double mr = m0 - mu * t;
    dfdt[0] = 0;
    dfdt[1] = u_e * mu * mu / (mr * mr);
  };
  sys.n_pos = 1;
  sys.accel = [=](const double*, double* a, double t) { a[0] = accel(t); };

  Integrator ig(opt.method, sys, opt.tol);
  State x = {0, 0};
  SceneResult r;
  r.series.columns = {"t", "m_r", "z", "v", "v_closed_form"};
  double max_err = 0, max_v = 0;
  auto observe = [&](const State& s, double t) {
    const double vc = cf::rocket_v(m0, mu, u_e, g, t);
    max_err = std::isfinite(s[1]) ? std::max(max_err, std::abs(s[1] - vc)) : HUGE_VAL;
    max_v = std::max(max_v, std::abs(vc));
    r.series.rows.push_back({t, m0 - mu * t, s[0], s[1], vc});
  };
  if (t_b > 0) integrate(ig, x, 0, t_b, opt.h, nullptr, observe);
  else observe(x, 0);

  r.comparisons.push_back({"v_burnout", "m/s", x[1], cf::rocket_v(m0, mu, u_e, g, t_b),
                           "-u_e ln(m_r/m0) - g t (evaluated as -u_e log1p(-mu t/m0) - g t)", "built-in"});
  r.metrics["t_burnout"] = t_b;
  r.metrics["max_velocity_error"] = max_err;                          // [m/s] over all steps
  r.metrics["max_relative_velocity_error"] = max_v > 0 ? max_err / max_v : max_err;
  r.rhs_evaluations = ig.rhs_evaluations();
  r.notes.push_back("burnout at t = (m0 - m_r)/mu = " + std::to_string(t_b) + " s; thrust/weight at lift-off = " +
                    std::to_string(u_e * mu / (m0 * g)));
  r.figure = {"t", "$t$ [s]", "$v$ [m/s]", {{"v", "simulated"}, {"v_closed_form", "$-u_e\\ln(m_r/m_0) - g t$"}}};
  return r;
}

}  // namespace dc::scenes
