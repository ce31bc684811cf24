// Example 9.6: two-ball bounce with a finite separation s and a finite mass ratio mu = m1/m2.
// Event-driven: between impacts both balls fly on parabolas (exact), the next event time is
// solved in closed form (ball 2 reaching the ground: a quadratic; the balls touching: linear,
// since both have the same acceleration), and impacts are instantaneous — ball 2 with the
// ground (restitution e2), ball 1 with ball 2 (e12, solved as the linear system (9.6)+(9.7)).
// The tennis ball's velocity right after the first ball-ball impact is compared with
//   v'1 = (mu - e2 - e12 (1 + e2))/(mu + 1) v0,
// which the simulation reproduces exactly for s = 0 and approaches linearly in s.
#include <cmath>
#include <stdexcept>

#include "numeric/scenes/closed_forms.hpp"
#include "numeric/scenes/derived.hpp"
#include "numeric/scenes/scenes.hpp"

namespace dc::scenes {

namespace {

struct Ball {
  double y, v;
};

// time for ball 2 (centre y, velocity v, free fall) to reach height r: the positive root of
// (g/2) tau² - v tau - h = 0 with h = y - r >= 0; written without cancellation for v < 0.
double time_to_ground(double h, double v, double g) {
  if (h < 0) h = 0;
  const double root = std::sqrt(v * v + 2 * g * h);
  return v < 0 ? 2 * h / (root - v) : (v + root) / g;
}

}  // namespace

SceneResult run_bounce(const Params& p, const RunOptions& opt) {
  const double m1 = p.at("m1"), m2 = p.at("m2"), r1 = p.at("r1"), r2 = p.at("r2"), y2_0 = p.at("y2"),
               s = p.at("s"), e2 = p.at("e2"), e12 = p.at("e12"), g = p.at("g");
  const double mu = m1 / m2;
  Ball b2{y2_0, 0}, b1{y2_0 + r2 + r1 + s, 0};
  bool b2_resting = false;  // ball 2 lying on the ground (after a landing with e2 = 0)
  double t = 0;
  int ground_impacts = 0;
  double v0_actual = 0;  // ball 2's velocity at its first ground impact
  SceneResult r;
  r.series.columns = {"t", "y1", "v1", "y2", "v2"};
  auto record = [&] { r.series.rows.push_back({t, b1.y, b1.v, b2.y, b2.v}); };
  record();
  auto advance = [&](double tau) {
    // sample the parabolas for the figure (the event times themselves are exact)
    for (int k = 1; k < 40 && tau > 0; ++k) {
      const double u = tau * k / 40;
      const double y2 = b2_resting ? b2.y : b2.y + b2.v * u - 0.5 * g * u * u;
      const double v2s = b2_resting ? 0.0 : b2.v - g * u;
      r.series.rows.push_back({t + u, b1.y + b1.v * u - 0.5 * g * u * u, b1.v - g * u, y2, v2s});
    }
    b1.y += b1.v * tau - 0.5 * g * tau * tau;
    b1.v -= g * tau;
    if (!b2_resting) {
      b2.y += b2.v * tau - 0.5 * g * tau * tau;
      b2.v -= g * tau;
    }
    t += tau;
  };
  const double v0_cf = cf::bounce_v0(y2_0, r2, g);
  for (int events = 0;; ++events) {
    if (events > 10000) throw std::runtime_error("bounce: more than 10000 events before the balls met");
    const double gap = b1.y - b2.y - (r1 + r2);
    const double t_ground = b2_resting ? HUGE_VAL : time_to_ground(b2.y - r2, b2.v, g);
    double t_contact = HUGE_VAL;
    if (b2_resting) {
      // ball 1 falls onto a resting ball 2: gap + v1 tau - g tau²/2 = 0
      t_contact = time_to_ground(gap, b1.v, g);
    } else if (b1.v - b2.v < 0) {
      t_contact = std::max(0.0, gap) / (b2.v - b1.v);  // same acceleration: the gap closes linearly
    }
    if (t_ground < t_contact) {
      advance(t_ground);
      b2.y = r2;  // exactly on the ground
      if (ground_impacts == 0) v0_actual = b2.v;
      b2.v = -e2 * b2.v;
      ++ground_impacts;
      if (b2.v == 0) b2_resting = true;
      record();
      continue;
    }
    advance(t_contact);
    b1.y = b2.y + r1 + r2;  // exactly in contact
    const double v1 = b1.v, v2 = b2.v;
    const DirectImpact imp = solve_direct_impact(m1, m2, v1, v2, e12);
    b1.v = imp.v1p;
    b2.v = imp.v2p;
    b2_resting = false;
    record();
    // the closed forms: from the actual pre-impact velocities (the mu-form of the general
    // impact), and the handout's zero-separation form v2 = -e2 v0, v1 = v0
    const double v1p_mu = (mu * v1 + v2 - e12 * (v1 - v2)) / (mu + 1);
    const std::string file = "07_two_ball_bounce.dc";
    const std::map<std::string, double> at = {{"mu", mu}, {"e2", e2}, {"e12", e12}, {"v0", v0_cf},
                                              {"v1", v1}, {"v2", v2}, {"g", g}, {"y2", y2_0}, {"r2", r2}};
    r.comparisons.push_back(closed_form(opt, "v1p", "m/s", b1.v, cf::bounce_v1p(mu, e2, e12, v0_cf),
                                        "(mu - e2 - e12 (1 + e2))/(mu + 1) v0 (zero separation)", file, "v1p_bounce", at));
    r.comparisons.push_back(closed_form(opt, "v2p", "m/s", b2.v, cf::bounce_v2p(mu, e2, e12, v0_cf),
                                        "(mu - e2 + mu e12 (1 + e2))/(mu + 1) v0 (zero separation)", file, "v2p_bounce", at));
    r.comparisons.push_back(closed_form(opt, "v1p_actual", "m/s", b1.v, v1p_mu,
                                        "(mu v1 + v2 - e12 (v1 - v2))/(mu + 1) at the actual v1, v2", file, "v1p_mu", at));
    r.comparisons.push_back(closed_form(opt, "v0", "m/s", v0_actual, v0_cf, "-sqrt(2 g (y2 - r2)) (ground impact)", file,
                                        "fall_speed", at));
    // the limit mu -> 0: v'1 -> -(e2 + (1 + e2) e12) v0, i.e. -3 v0 for e2 = e12 = 1
    r.metrics["v1p_over_v0"] = b1.v / v0_cf;
    r.metrics["v1p_over_v0_limit_mu0"] = -(e2 + (1 + e2) * e12);
    // rebound height of the tennis ball's bottom above the impact point vs the drop height
    const double apex = b1.v > 0 ? b1.y + b1.v * b1.v / (2 * g) : b1.y;
    r.metrics["v0"] = v0_cf;
    r.metrics["v1_before"] = v1;
    r.metrics["v2_before"] = v2;
    r.metrics["t_contact"] = t;
    r.metrics["ground_impacts"] = ground_impacts;
    r.metrics["height_ratio"] = (apex - b1.y) / (y2_0 - r2);
    r.notes.push_back("first ball-ball impact at t = " + std::to_string(t) + " s after " +
                      std::to_string(ground_impacts) + " ground impact(s); before it v1 = " + std::to_string(v1) +
                      " m/s, v2 = " + std::to_string(v2) + " m/s (closed form assumes v0 = " + std::to_string(v0_cf) +
                      " and -e2 v0)");
    r.notes.push_back("tennis ball rises " + std::to_string(r.metrics["height_ratio"]) +
                      " times the drop height above the contact point ((v'1/v0)^2 = " +
                      std::to_string(std::pow(b1.v / v0_cf, 2)) + ")");
    // for the figure: the flight after the impact, up to the tennis ball's apex (or ball 2's
    // next landing, where the model's story ends)
    if (b1.v > 0) advance(std::min(b1.v / g, time_to_ground(b2.y - r2, b2.v, g)));
    record();
    break;
  }
  r.figure = {"t", "$t$ [s]", "height [m]", {{"y1", "$y_1$"}, {"y2", "$y_2$"}}};
  return r;
}

}  // namespace dc::scenes
