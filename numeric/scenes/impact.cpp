// §9.3.1 and §9.3.2: impacts solved as linear systems with Eigen, compared with the closed forms.
#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "numeric/scenes/closed_forms.hpp"
#include "numeric/scenes/derived.hpp"
#include "numeric/scenes/scenes.hpp"

namespace dc::scenes {

namespace {

void require(bool ok, const std::string& name, double v, const std::string& unit, const std::string& need) {
  if (!ok) out_of_bounds("impact", name, v, unit, need);
}

void check_common(double m1, double m2, double e) {
  for (auto [name, v] : {std::pair{"m1", m1}, std::pair{"m2", m2}})
    require(std::isfinite(v) && v > 0, name, v, "kg", std::string(name) + " > 0");
  require(std::isfinite(e) && e >= 0 && e <= 1, "e", e, "1", "0 <= e <= 1");
}

}  // namespace

DirectImpact solve_direct_impact(double m1, double m2, double v1, double v2, double e) {
  check_common(m1, m2, e);
  require(std::isfinite(v1), "v1", v1, "m/s", "v1 finite");
  require(std::isfinite(v2), "v2", v2, "m/s", "v2 finite");
  // unknowns (v'1, v'2):
  //   m1 v'1 + m2 v'2 = m1 v1 + m2 v2      (9.6)
  //  -v'1   +    v'2 = e (v1 - v2)          (9.7)
  Eigen::Matrix2d A;
  A << m1, m2, -1, 1;
  Eigen::Vector2d b(m1 * v1 + m2 * v2, e * (v1 - v2));
  const Eigen::Vector2d x = A.partialPivLu().solve(b);
  return {x(0), x(1)};
}

ObliqueImpact solve_oblique_impact(double m1, double m2, double v1n, double v1t, double v2n, double v2t, double e) {
  check_common(m1, m2, e);
  for (auto [name, v] : {std::pair{"v1n", v1n}, std::pair{"v1t", v1t}, std::pair{"v2n", v2n}, std::pair{"v2t", v2t}})
    require(std::isfinite(v), name, v, "m/s", std::string(name) + " finite");
  // unknowns (v'1n, v'1t, v'2n, v'2t):
  //   m1 v'1n + m2 v'2n = m1 v1n + m2 v2n   momentum in n
  //   m1 v'1t           = m1 v1t            momentum in t, particle 1
  //   m2 v'2t           = m2 v2t            momentum in t, particle 2
  //  -v'1n    + v'2n    = e (v1n - v2n)     restitution in n
  Eigen::Matrix4d A;
  A << m1, 0, m2, 0,
       0, m1, 0, 0,
       0, 0, 0, m2,
       -1, 0, 1, 0;
  Eigen::Vector4d b(m1 * v1n + m2 * v2n, m1 * v1t, m2 * v2t, e * (v1n - v2n));
  const Eigen::Vector4d x = A.partialPivLu().solve(b);
  return {x(0), x(1), x(2), x(3)};
}

SceneResult run_impact(const Params& p, const RunOptions& opt) {
  const double m1 = p.at("m1"), m2 = p.at("m2"), v1 = p.at("v1"), v2 = p.at("v2"), e = p.at("e");
  const DirectImpact s = solve_direct_impact(m1, m2, v1, v2, e);
  SceneResult r;
  const std::map<std::string, double> at = {{"m1", m1}, {"m2", m2}, {"v1", v1}, {"v2", v2}, {"e", e}};
  const std::string file = "05_direct_impact.dc";
  r.comparisons.push_back(closed_form(opt, "v1p", "m/s", s.v1p, cf::v1p_general(m1, m2, v1, v2, e),
                                      "(m1 v1 + m2 v2 - e m2 (v1 - v2))/(m1 + m2)", file, "v1p_general", at));
  r.comparisons.push_back(closed_form(opt, "v2p", "m/s", s.v2p, cf::v2p_general(m1, m2, v1, v2, e),
                                      "(m1 v1 + m2 v2 - e m1 (v2 - v1))/(m1 + m2)", file, "v2p_general", at));
  const double T0 = 0.5 * m1 * v1 * v1 + 0.5 * m2 * v2 * v2;
  const double T1 = 0.5 * m1 * s.v1p * s.v1p + 0.5 * m2 * s.v2p * s.v2p;
  r.comparisons.push_back(closed_form(opt, "dT", "J", T0 - T1, cf::dT_general(m1, m2, v1, v2, e),
                                      "(1 - e^2)/2 m1 m2/(m1 + m2) (v1 - v2)^2", file, "energy_loss_general", at));
  r.series.columns = {"v1", "v2", "v1p", "v2p"};
  r.series.rows.push_back({v1, v2, s.v1p, s.v2p});
  return r;
}

SceneResult run_oblique(const Params& p, const RunOptions& opt) {
  const double m1 = p.at("m1"), m2 = p.at("m2"), v1n = p.at("v1n"), v1t = p.at("v1t"), v2n = p.at("v2n"),
               v2t = p.at("v2t"), e = p.at("e");
  const ObliqueImpact s = solve_oblique_impact(m1, m2, v1n, v1t, v2n, v2t, e);
  SceneResult r;
  const std::map<std::string, double> at = {{"m1", m1}, {"m2", m2}, {"v1n", v1n}, {"v2n", v2n},
                                            {"v1t", v1t}, {"v2t", v2t}, {"e", e}};
  const std::string file = "08_oblique_impact.dc";
  r.comparisons.push_back(closed_form(opt, "v1n_p", "m/s", s.v1n, cf::v1p_general(m1, m2, v1n, v2n, e),
                                      "direct-impact v'1 in n", file, "v1np_sol", at));
  r.comparisons.push_back(closed_form(opt, "v1t_p", "m/s", s.v1t, v1t, "v1t (no impulse along t)", file, "v1tp_sol", at));
  r.comparisons.push_back(closed_form(opt, "v2n_p", "m/s", s.v2n, cf::v2p_general(m1, m2, v1n, v2n, e),
                                      "direct-impact v'2 in n", file, "v2np_sol", at));
  r.comparisons.push_back(closed_form(opt, "v2t_p", "m/s", s.v2t, v2t, "v2t (no impulse along t)", file, "v2tp_sol", at));
  r.series.columns = {"v1n", "v1t", "v2n", "v2t", "v1n_p", "v1t_p", "v2n_p", "v2t_p"};
  r.series.rows.push_back({v1n, v1t, v2n, v2t, s.v1n, s.v1t, s.v2n, s.v2t});
  return r;
}

}  // namespace dc::scenes
