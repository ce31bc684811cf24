// The closed forms of Handout 9 the scenes are compared with (see closed_forms.hpp).
#include "numeric/scenes/closed_forms.hpp"

#include <cmath>

namespace dc::scenes::cf {

// P = m1 v1 + m2 v2 = (m1 + m2) v_G  (§9.2)
double v_G(double m1, double m2, double v1, double v2) { return (m1 * v1 + m2 * v2) / (m1 + m2); }

// v'1 = (m1 v1 + m2 v2 - e m2 (v1 - v2))/(m1 + m2)   (§9.3.1, general impact)
double v1p_general(double m1, double m2, double v1, double v2, double e) {
  return (m1 * v1 + m2 * v2 - e * m2 * (v1 - v2)) / (m1 + m2);
}
// v'2 = (m1 v1 + m2 v2 - e m1 (v2 - v1))/(m1 + m2)
double v2p_general(double m1, double m2, double v1, double v2, double e) {
  return (m1 * v1 + m2 * v2 - e * m1 * (v2 - v1)) / (m1 + m2);
}
// ΔT = (1 - e²)/2 · m1 m2/(m1 + m2) · (v1 - v2)²; (1-e)(1+e) avoids the cancellation of 1 - e².
double dT_general(double m1, double m2, double v1, double v2, double e) {
  const double dv = v1 - v2;
  return 0.5 * (1 - e) * (1 + e) * (m1 / (m1 + m2)) * m2 * dv * dv;
}

// m v0 = (M + m) v1   (Example 9.5)
double pendulum_v1(double m, double M, double v0) { return m * v0 / (M + m); }

double pendulum_theta(double m, double M, double v0, double L, double g) {
  // 1 - cos θ = 2 sin²(θ/2) = (m/(M+m))² v0²/(2Lg)  =>  sin(θ/2) = (m/(M+m)) v0 / (2 sqrt(gL))
  return 2 * std::asin((m / (M + m)) * v0 / (2 * std::sqrt(g * L)));
}
double pendulum_theta_naive(double m, double M, double v0, double L, double g) {
  const double r = m / (M + m);
  return std::acos(1 - r * r * v0 * v0 / (2 * L * g));
}

// v0 = -sqrt(2 g (y2 - r2))   (Example 9.6)
double bounce_v0(double y2, double r2, double g) { return -std::sqrt(2 * g * (y2 - r2)); }
double bounce_v1p(double mu, double e2, double e12, double v0) {
  return (mu - e2 - e12 * (1 + e2)) / (mu + 1) * v0;
}
double bounce_v2p(double mu, double e2, double e12, double v0) {
  return (mu - e2 + mu * e12 * (1 + e2)) / (mu + 1) * v0;
}

// v = -u_e ln(m_r/m0) - g t, m_r/m0 = 1 - mu t/m0   (§9.4)
double rocket_v(double m0, double mu, double u_e, double g, double t) {
  return -u_e * std::log1p(-mu * t / m0) - g * t;
}

// v = sqrt(2 g x); N - (x/L) m g = (m/L) v² => N = 3 x m g / L   (Example 9.7)
double chain_v(double g, double x) { return std::sqrt(2 * g * x); }
double chain_N(double m, double L, double g, double x) { return 3 * x * m * g / L; }

// Example 9.2 with θ from the floor: θ'² = (3g/l)(sin θ0 - sin θ); the wall reaction
// m d²x_G/dt² vanishes where d/dθ[sin θ sqrt(sin θ0 - sin θ)] = 0, i.e. sin θ = 2/3 sin θ0.
double ladder_theta_sep(double theta0) { return std::asin(2.0 / 3.0 * std::sin(theta0)); }
// m v_Gx = m (l/2) sin θs |θ'| = m (l/2)(2/3 sin θ0) sqrt(g sin θ0 / l) = (m/3) sqrt(g l) sin^{3/2} θ0
double ladder_wall_impulse(double m, double l, double g, double theta0) {
  const double s = std::sin(theta0);
  return m / 3 * std::sqrt(g * l) * s * std::sqrt(s);
}

// m_p v_p - m_c v_c = 0  (Example 9.1)
double cannon_velocity_ratio(double m_p, double m_c) { return m_c / m_p; }

const std::map<std::string, std::string>& derivation_labels() {
  static const std::map<std::string, std::string> labels = {
      {"v_G", "derivations/handout9/spring.dc:v_G (Example 9.3: v_G = m2 v0/(m1 + m2))"},
      {"v1p_general", "derivations/handout9/direct_impact.dc:v1p_general"},
      {"v2p_general", "derivations/handout9/direct_impact.dc:v2p_general"},
      {"dT_general", "derivations/handout9/direct_impact.dc:dT_general"},
      {"pendulum_v1", "derivations/handout9/ballistic_pendulum.dc:v1"},
      {"pendulum_theta", "derivations/handout9/ballistic_pendulum.dc:theta"},
      {"bounce_v1p", "derivations/handout9/two_ball_bounce.dc:v1p_zero_separation"},
      {"bounce_v2p", "derivations/handout9/two_ball_bounce.dc:v2p_zero_separation"},
      {"rocket_v", "derivations/handout9/rocket.dc:v (v = -u_e ln(m_r/m0) - g t)"},
      {"chain_N", "derivations/handout9/chain.dc:N (N = 3 x m g/L)"},
      {"ladder_theta_sep", "derivations/handout9/ladder.dc:sin_theta_sep"},
      {"ladder_wall_impulse", "derivations/handout9/ladder.dc:wall_impulse"},
      {"cannon_velocity_ratio", "derivations/handout9/cannon.dc:velocity_ratio"},
  };
  return labels;
}

}  // namespace dc::scenes::cf
