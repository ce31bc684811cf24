// Newton's cradle (§9.3.1, elastic impact of equal masses): n equal balls in a row, just
// touching; ball 1 arrives with v0. Sequential pairwise impacts: the approaching pair with the
// lowest index is resolved first, each impact solved as the linear system (9.6)+(9.7), until no
// pair approaches. With e = 1 the velocities are exchanged down the row and the last ball leaves
// with v0; with e < 1 momentum is still conserved and the energy lost equals the sum of the
// per-impact losses (1 - e²)/2 · m1 m2/(m1 + m2) · (v1 - v2)².
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "numeric/scenes/closed_forms.hpp"
#include "numeric/scenes/scenes.hpp"

namespace dc::scenes {

SceneResult run_cradle(const Params& p, const RunOptions&) {
  const int n = static_cast<int>(p.at("n"));
  const double m = p.at("m"), v0 = p.at("v0"), e = p.at("e");
  std::vector<double> v(n, 0.0);
  v[0] = v0;
  double dT_sum = 0;
  long impacts = 0;
  const long max_impacts = 1000000;
  // approach speeds below this are taken as contact at rest (e < 1 gives geometric sequences)
  const double eps = 1e-14 * std::abs(v0);
  for (;;) {
    int i = 0;
    while (i + 1 < n && !(v[i] - v[i + 1] > eps)) ++i;
    if (i + 1 >= n) break;
    if (++impacts > max_impacts) throw std::runtime_error("cradle: more than 1e6 impacts");
    dT_sum += cf::dT_general(m, m, v[i], v[i + 1], e);
    const DirectImpact imp = solve_direct_impact(m, m, v[i], v[i + 1], e);
    v[i] = imp.v1p;
    v[i + 1] = imp.v2p;
  }
  double P = 0, T = 0, max_others = 0;
  for (int i = 0; i < n; ++i) {
    P += m * v[i];
    T += 0.5 * m * v[i] * v[i];
    if (i + 1 < n) max_others = std::max(max_others, std::abs(v[i]));
  }
  const double T0 = 0.5 * m * v0 * v0;
  SceneResult r;
  r.comparisons.push_back({"P", "N s", P, m * v0, "m v0 (momentum conserved)", "built-in"});
  r.comparisons.push_back({"dT", "J", T0 - T, dT_sum, "sum over impacts of (1-e^2)/2 m1 m2/(m1+m2)(v1-v2)^2", "built-in"});
  if (e == 1) {
    r.comparisons.push_back({"v_last", "m/s", v[n - 1], v0, "v0: equal masses exchange velocities (e = 1)", "built-in"});
    r.comparisons.push_back({"max_v_others", "m/s", max_others, 0, "0: all other balls stop", "built-in"});
  }
  r.metrics["impacts"] = static_cast<double>(impacts);
  r.metrics["v_last"] = v[n - 1];
  r.series.columns = {"ball", "v"};
  for (int i = 0; i < n; ++i) r.series.rows.push_back({double(i + 1), v[i]});
  r.notes.push_back(std::to_string(impacts) + " pairwise impacts; the last ball leaves with " + std::to_string(v[n - 1]) +
                    " m/s, the first keeps " + std::to_string(v[0]) + " m/s");
  return r;
}

}  // namespace dc::scenes
