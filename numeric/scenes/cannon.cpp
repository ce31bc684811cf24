// Example 9.1: cannon recoil from a finite force pulse. The charge pushes projectile and
// cannon with equal and opposite force F(t) for 0 <= t <= tau; no other horizontal force.
//   m_p x_p'' = F(t),   m_c x_c'' = -F(t)
// For every pulse shape the speeds after the pulse satisfy v_p/v_c = m_c/m_p and
// T_p/T_c = m_c/m_p (Example 9.1), while v_p itself is the pulse's impulse over m_p.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "numeric/scenes/closed_forms.hpp"
#include "numeric/scenes/scenes.hpp"

namespace dc::scenes {

namespace {

struct Pulse {
  const char* name;
  double (*shape)(double u);   // F/F0 at u = t/tau in [0, 1]
  double impulse;              // int_0^1 shape(u) du
};

const Pulse kPulses[] = {
    {"rect", [](double) { return 1.0; }, 1.0},
    {"triangle", [](double u) { return 1 - std::abs(2 * u - 1); }, 0.5},
    {"halfsine", [](double u) { return std::sin(std::numbers::pi * u); }, 2 / std::numbers::pi},
    {"raisedcos", [](double u) { return 0.5 * (1 - std::cos(2 * std::numbers::pi * u)); }, 0.5},
};

}  // namespace

SceneResult run_cannon(const Params& p, const RunOptions& opt) {
  const double m_p = p.at("m_p"), m_c = p.at("m_c"), F0 = p.at("F0"), tau = p.at("tau");
  SceneResult r;
  r.series.columns = {"pulse", "t", "F", "v_p", "v_c"};
  double max_G = 0;
  for (int k = 0; k < 4; ++k) {
    const Pulse& pl = kPulses[k];
    auto F = [=](double t) { return F0 * pl.shape(std::clamp(t / tau, 0.0, 1.0)); };
    OdeSystem sys;
    sys.dim = 4;  // x_p, x_c, v_p, v_c
    sys.rhs = [=](const State& s, State& d, double t) {
      d[0] = s[2];
      d[1] = s[3];
      d[2] = F(t) / m_p;
      d[3] = -F(t) / m_c;
    };
    sys.n_pos = 2;
    sys.accel = [=](const double*, double* a, double t) {
      a[0] = F(t) / m_p;
      a[1] = -F(t) / m_c;
    };
    Integrator ig(opt.method, sys, opt.tol);
    State x = {0, 0, 0, 0};
    integrate(ig, x, 0, tau, opt.h, nullptr, [&](const State& s, double t) {
      r.series.rows.push_back({double(k), t, F(t), s[2], s[3]});
      max_G = std::max(max_G, std::abs(m_p * s[0] + m_c * s[1]) / (m_p + m_c));
    });
    r.rhs_evaluations += ig.rhs_evaluations();
    const std::string n = pl.name;
    const double vp = x[2], vc = -x[3];  // recoil speed
    r.comparisons.push_back({"v_p/v_c[" + n + "]", "1", vp / vc, cf::cannon_velocity_ratio(m_p, m_c), "m_c/m_p", "built-in"});
    r.comparisons.push_back({"T_p/T_c[" + n + "]", "1", (0.5 * m_p * vp * vp) / (0.5 * m_c * vc * vc), m_c / m_p,
                             "m_c/m_p", "built-in"});
    r.comparisons.push_back({"v_p[" + n + "]", "m/s", vp, F0 * tau * pl.impulse / m_p, "int F dt / m_p", "built-in"});
  }
  r.metrics["max_centre_of_mass_shift"] = max_G;  // [m]: the centre of mass stays put
  r.notes.push_back("pulses: rect, triangle, half-sine, raised cosine, all of peak F0 and duration tau");
  return r;
}

}  // namespace dc::scenes
