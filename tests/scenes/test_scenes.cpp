// Each scene against its closed form, with convergence where an integrator is involved.
#include <cmath>
#include <random>
#include <string>

#include <catch2/catch.hpp>

#include "numeric/scenes/closed_forms.hpp"
#include "numeric/scenes/scenes.hpp"

using namespace dc::scenes;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

SceneResult run(const std::string& scene, Params over = {}, Method m = Method::rk4, double h = 0, double tol = 1e-10) {
  const SceneSpec& spec = find_scene(scene);
  Params p = defaults(spec);
  for (auto& [k, v] : over) p[k] = v;
  RunOptions o;
  o.method = m;
  o.h = h;
  o.tol = tol;
  return run_scene(spec, p, o);
}

}  // namespace

TEST_CASE("every scene runs with its defaults and agrees with its closed forms", "[scenes]") {
  for (const auto& spec : scene_specs()) {
    CAPTURE(spec.name);
    const auto r = run(spec.name, {}, spec.default_method);
    REQUIRE_FALSE(r.comparisons.empty());
    for (const auto& c : r.comparisons) {
      CAPTURE(c.quantity, c.simulated, c.closed_form);
      // bounce: the default separation of 1 mm makes v'1 differ from the zero-separation form
      const double tol = spec.name == "bounce" ? 0.05 : 1e-6;
      CHECK(c.rel_error() < tol);
    }
  }
}

TEST_CASE("pendulum: theta_max converges to the closed form at RK4's order", "[scenes][pendulum][convergence]") {
  const auto cf_theta = run("pendulum").get("theta_max").closed_form;
  CHECK_THAT(cf_theta, WithinRel(cf::pendulum_theta_naive(0.01, 2, 300, 1, 9.81), 1e-12));
  const double e1 = run("pendulum", {}, Method::rk4, 0.1).get("theta_max").rel_error();
  const double e2 = run("pendulum", {}, Method::rk4, 0.05).get("theta_max").rel_error();
  CAPTURE(e1, e2, e1 / e2);
  // measured ratios 25.6, 29.8, 28.7, 26.6, 24.0 for h = 0.2 ... 0.00625: at least fourth order.
  // Above 16 because theta is stationary at the turning point (the error in the event time enters
  // theta_max only at second order) and the last, partial step's length varies with h.
  CHECK(e1 / e2 > 12);
  CHECK(e1 / e2 < 40);
  CHECK(run("pendulum", {}, Method::dopri5, 0.01, 1e-12).get("theta_max").rel_error() < 1e-10);
  // up to the horizontal exactly: v0 = (M+m)/m sqrt(2 g L)
  const double v0_max = 2.01 / 0.01 * std::sqrt(2 * 9.81);
  const auto r = run("pendulum", {{"v0", v0_max}}, Method::rk4, 1e-3);
  CHECK_THAT(r.get("theta_max").simulated, WithinRel(M_PI / 2, 1e-8));
}

TEST_CASE("pendulum: the half-angle form keeps the digits acos loses at small v0", "[scenes][pendulum]") {
  // theta ~ 2e-8 rad: 1 - theta²/2 rounds to 1 - 2e-16 and acos keeps about half the digits
  const double v0 = 1e-5;
  const double stable = cf::pendulum_theta(0.01, 2, v0, 1, 9.81);
  const double naive = cf::pendulum_theta_naive(0.01, 2, v0, 1, 9.81);
  const double reference = 0.01 / 2.01 * v0 / std::sqrt(9.81);  // theta ≈ v1/sqrt(gL) to O(theta³)
  CAPTURE(stable, naive, reference);
  CHECK_THAT(stable, WithinRel(reference, 1e-14));
  CHECK(std::abs(naive - reference) / reference > 1e-3);  // naive loses more than 3 of 16 digits here
}

TEST_CASE("bounce: zero separation reproduces the closed form exactly", "[scenes][bounce]") {
  for (double e2 : {1.0, 0.8, 0.0}) {
    for (double e12 : {1.0, 0.5, 0.0}) {
      CAPTURE(e2, e12);
      const auto r = run("bounce", {{"s", 0}, {"e2", e2}, {"e12", e12}});
      CHECK(r.get("v1p").rel_error() < 1e-14);
      CHECK(r.get("v2p").rel_error() < 1e-13);
      CHECK(r.get("v1p_actual").rel_error() < 1e-14);
    }
  }
}

TEST_CASE("bounce: the rebound tends to the closed form linearly as the separation -> 0", "[scenes][bounce]") {
  double prev = 1;
  for (double s : {1e-1, 1e-2, 1e-3, 1e-4}) {
    const auto r = run("bounce", {{"s", s}});
    const double err = r.get("v1p").rel_error();
    CAPTURE(s, err, prev / err);
    CHECK(err > 0);
    if (s < 1e-1) {
      CHECK(prev / err > 7);   // ~10x per decade: first order in s
      CHECK(prev / err < 13);
    }
    prev = err;
    CHECK(r.get("v1p_actual").rel_error() < 1e-13);  // the impact itself is exact
  }
}

TEST_CASE("bounce: the tennis ball leaves at -3 v0 as mu -> 0 with e = 1 (9x the height)", "[scenes][bounce]") {
  double prev = 1;
  for (double m1 : {1e-2, 1e-4, 1e-6}) {
    const auto r = run("bounce", {{"m1", m1}, {"m2", 1}, {"s", 0}});
    const double ratio = r.metric("v1p_over_v0");
    CHECK(r.metric("v1p_over_v0_limit_mu0") == -3);
    CAPTURE(m1, ratio);
    const double err = std::abs(ratio + 3);
    CHECK(err < 10 * m1);  // O(mu)
    CHECK(err < prev);
    prev = err;
    CHECK_THAT(r.metric("height_ratio"), WithinRel(ratio * ratio, 1e-12));
  }
  CHECK_THAT(run("bounce", {{"m1", 1e-9}, {"m2", 1}, {"s", 0}}).metric("height_ratio"), WithinRel(9.0, 1e-7));
}

TEST_CASE("rocket: v(t) converges to -u_e ln(m_r/m0) - g t at RK4's order", "[scenes][rocket][convergence]") {
  const double e1 = run("rocket", {}, Method::rk4, 2.0).metric("max_velocity_error");
  const double e2 = run("rocket", {}, Method::rk4, 1.0).metric("max_velocity_error");
  CAPTURE(e1, e2, e1 / e2);
  CHECK(e1 / e2 > 13);
  CHECK(e1 / e2 < 19);
  const double eu1 = run("rocket", {}, Method::euler, 0.1).metric("max_velocity_error");
  const double eu2 = run("rocket", {}, Method::euler, 0.05).metric("max_velocity_error");
  CHECK_THAT(eu1 / eu2, WithinAbs(2.0, 0.2));
  CHECK(run("rocket", {}, Method::dopri5, 1.0, 1e-12).metric("max_relative_velocity_error") < 1e-10);
  // a burn fraction of 1e-12: the closed form is evaluated with log1p
  const auto tiny = run("rocket", {{"m_r", 1000 * (1 - 1e-12)}}, Method::rk4, 1e-12);
  CHECK(tiny.get("v_burnout").rel_error() < 1e-6);
}

TEST_CASE("chain: the naive first-order form x' = sqrt(2gx) never leaves x = 0", "[scenes][chain]") {
  for (Method m : {Method::euler, Method::rk4, Method::dopri5, Method::rosenbrock}) {
    CAPTURE(method_name(m));
    CHECK(chain_first_order_naive(9.81, m, 1e-3, 0.5) == 0.0);
  }
  // the scene's second-order form x'' = g starts, lands at sqrt(2L/g) and matches N = 3xmg/L
  const auto r = run("chain", {}, Method::rk4, 1e-3);
  CHECK_THAT(r.get("t_landed").simulated, WithinRel(std::sqrt(2 / 9.81), 1e-12));
  CHECK(r.get("N(x)").rel_error() < 1e-12);
  CHECK_THAT(r.get("N(L)").closed_form, WithinRel(3 * 9.81, 1e-15));
}

TEST_CASE("chain: explicit Euler's force error is first order in h", "[scenes][chain][convergence]") {
  const double e1 = run("chain", {}, Method::euler, 1e-3).metric("max_force_error");
  const double e2 = run("chain", {}, Method::euler, 5e-4).metric("max_force_error");
  CAPTURE(e1, e2);
  CHECK(e1 > 1e-3);
  CHECK_THAT(e1 / e2, WithinAbs(2.0, 0.3));
}

TEST_CASE("ladder: leaves the wall at sin theta = 2/3 sin theta0 with the wall's impulse m v_Gx", "[scenes][ladder]") {
  for (double th0 : {30.0, 60.0, 85.0}) {
    CAPTURE(th0);
    const auto r = run("ladder", {{"theta0", th0}}, Method::rk4, 1e-3);
    CHECK(r.get("sin_theta_sep").rel_error() < 1e-9);
    CHECK(r.get("J_wall").rel_error() < 1e-9);
    CHECK(r.get("J_vs_momentum").rel_error() < 1e-9);
    CHECK(r.metric("max_energy_drift") < 1e-11);
    CHECK(r.metric("min_floor_reaction") > 0);
  }
  const double e1 = run("ladder", {}, Method::rk4, 0.04).get("J_wall").rel_error();
  const double e2 = run("ladder", {}, Method::rk4, 0.02).get("J_wall").rel_error();
  CAPTURE(e1, e2);
  CHECK(e1 / e2 > 10);
}

TEST_CASE("cradle: e = 1 passes v0 to the last ball, e < 1 conserves momentum and loses the summed dT",
          "[scenes][cradle]") {
  for (double n : {2.0, 3.0, 5.0, 20.0}) {
    CAPTURE(n);
    const auto r = run("cradle", {{"n", n}});
    CHECK_THAT(r.get("v_last").simulated, WithinRel(1.0, 1e-15));
    CHECK(r.get("max_v_others").simulated == 0.0);
    CHECK(r.metric("impacts") == n - 1);
    const auto in = run("cradle", {{"n", n}, {"e", 0.9}});
    CHECK_THAT(in.get("P").simulated, WithinRel(0.1, 1e-14));
    CHECK_THAT(in.get("dT").simulated, WithinRel(in.get("dT").closed_form, 1e-9));
    CHECK(in.get("dT").simulated > 0);
  }
}

TEST_CASE("cannon: v_p/v_c = m_c/m_p whatever the pulse shape", "[scenes][cannon]") {
  for (Method m : {Method::euler, Method::rk4, Method::verlet}) {
    CAPTURE(method_name(m));
    const auto r = run("cannon", {{"m_p", 7}, {"m_c", 900}}, m, 1e-3);  // coarse: 10 steps per pulse
    for (const char* shape : {"rect", "triangle", "halfsine", "raisedcos"}) {
      CAPTURE(shape);
      CHECK(r.get(std::string("v_p/v_c[") + shape + "]").rel_error() < 1e-13);
      CHECK(r.get(std::string("T_p/T_c[") + shape + "]").rel_error() < 1e-12);
    }
  }
  // the velocities themselves depend on the integrator's accuracy; RK4 converges at order 4
  const double e1 = run("cannon", {}, Method::rk4, 2.5e-3).get("v_p[halfsine]").rel_error();
  const double e2 = run("cannon", {}, Method::rk4, 1.25e-3).get("v_p[halfsine]").rel_error();
  CAPTURE(e1, e2);
  CHECK(e1 / e2 > 12);
  CHECK(e1 / e2 < 20);
}

TEST_CASE("impact: Eigen's linear solutions of (9.6)+(9.7) and the oblique system match the closed forms",
          "[scenes][impact]") {
  std::mt19937_64 rng(20240521);
  INFO("seed 20240521");
  std::uniform_real_distribution<double> mass(0.01, 100), vel(-10, 10), rest(0, 1);
  for (int i = 0; i < 1000; ++i) {
    const double m1 = mass(rng), m2 = mass(rng), v1 = vel(rng), v2 = vel(rng), e = rest(rng), t1 = vel(rng),
                 t2 = vel(rng);
    CAPTURE(m1, m2, v1, v2, e);
    const auto d = solve_direct_impact(m1, m2, v1, v2, e);
    const double scale = std::abs(v1) + std::abs(v2);
    CHECK_THAT(d.v1p, WithinAbs(cf::v1p_general(m1, m2, v1, v2, e), 1e-13 * scale));
    CHECK_THAT(d.v2p, WithinAbs(cf::v2p_general(m1, m2, v1, v2, e), 1e-13 * scale));
    const auto o = solve_oblique_impact(m1, m2, v1, t1, v2, t2, e);
    CHECK_THAT(o.v1n, WithinAbs(d.v1p, 1e-13 * scale));
    CHECK_THAT(o.v2n, WithinAbs(d.v2p, 1e-13 * scale));
    CHECK_THAT(o.v1t, WithinRel(t1, 1e-15));
    CHECK_THAT(o.v2t, WithinRel(t2, 1e-15));
  }
  // elastic, equal masses: velocities exchanged (Newton's cradle); wall limit m2 >> m1
  const auto eq = solve_direct_impact(1, 1, 3, -1, 1);
  CHECK_THAT(eq.v1p, WithinAbs(-1, 1e-15));
  CHECK_THAT(eq.v2p, WithinAbs(3, 1e-15));
  const auto wall = solve_direct_impact(1, 1e12, 2, 0, 1);
  CHECK_THAT(wall.v1p, WithinAbs(-2, 1e-11));
}
