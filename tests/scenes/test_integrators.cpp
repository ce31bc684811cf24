// Integrators on the two-mass spring (Example 9.3), whose exact solution is known: convergence
// at each method's order, conservation laws, and the stiff spring's stability limits.
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "numeric/scenes/scenes.hpp"

using namespace dc::scenes;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

SceneResult spring(Method m, double h, Params over = {}, double tol = 1e-10) {
  const SceneSpec& spec = find_scene("spring");
  Params p = defaults(spec);
  for (auto& [k, v] : over) p[k] = v;
  RunOptions o;
  o.method = m;
  o.h = h;
  o.tol = tol;
  return run_scene(spec, p, o);
}

double error_at_end(Method m, double h) {
  // global error of x2(t_end) against the exact solution
  return spring(m, h).get("x2(t_end)").rel_error();
}

}  // namespace

TEST_CASE("spring: the centre of mass moves at 4/3 m/s and momentum is conserved by every method", "[scenes][spring]") {
  for (Method m : {Method::euler, Method::rk4, Method::dopri5, Method::verlet, Method::rosenbrock}) {
    CAPTURE(method_name(m));
    const auto r = spring(m, 0.01);
    // every method here preserves linear invariants exactly (up to rounding)
    CHECK(r.metric("max_momentum_drift") < 1e-13);
    CHECK_THAT(r.get("v_G").simulated, WithinRel(4.0 / 3.0, 1e-12));
    CHECK_THAT(r.get("v_G").closed_form, WithinRel(4.0 / 3.0, 1e-15));
  }
}

TEST_CASE("spring: global error converges at each integrator's order", "[scenes][spring][convergence]") {
  struct Case {
    Method m;
    double h;
    double order;
  };
  // h chosen so the error is well above rounding and in the asymptotic regime
  for (Case c : {Case{Method::euler, 1e-4, 1}, Case{Method::verlet, 4e-3, 2}, Case{Method::rk4, 2e-2, 4},
                 Case{Method::rosenbrock, 2e-2, 4}}) {
    CAPTURE(method_name(c.m), c.h);
    const double e1 = error_at_end(c.m, c.h), e2 = error_at_end(c.m, c.h / 2);
    const double ratio = e1 / e2;
    CAPTURE(e1, e2, ratio);
    const double expected = std::pow(2.0, c.order);
    CHECK(ratio > 0.8 * expected);
    CHECK(ratio < 1.25 * expected);
  }
}

TEST_CASE("spring: dopri5's error follows its tolerance", "[scenes][spring][convergence]") {
  double prev = 1;
  for (double tol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    const double err = spring(Method::dopri5, 0.1, {}, tol).get("x2(t_end)").rel_error();
    CAPTURE(tol, err);
    CHECK(err < 100 * tol);
    CHECK(err < prev);
    prev = err;
  }
}

TEST_CASE("spring: energy drift per integrator (symplectic Verlet stays bounded, Euler grows)", "[scenes][spring]") {
  const double h = 0.01;
  const double drift_euler = spring(Method::euler, h).metric("max_energy_drift");
  const double drift_verlet = spring(Method::verlet, h).metric("max_energy_drift");
  const double drift_rk4 = spring(Method::rk4, h).metric("max_energy_drift");
  const double drift_verlet_long = spring(Method::verlet, h, {{"t_end", 1000}}).metric("max_energy_drift");
  CAPTURE(drift_euler, drift_verlet, drift_rk4, drift_verlet_long);
  CHECK(drift_euler > 0.1);              // explicit Euler gains energy every step
  CHECK(drift_verlet < 1e-3);            // O((omega h)^2) oscillation, no drift
  CHECK(drift_verlet_long < 2 * drift_verlet);  // 100x longer: still bounded
  CHECK(drift_rk4 < 1e-8);
}

TEST_CASE("stiff spring: explicit steppers blow up past their stability limits, rosenbrock stays bounded",
          "[scenes][spring][stiff]") {
  // k = 1e6 N/m: omega = sqrt(k (m1+m2)/(m1 m2)) = 1224.7 rad/s, 2/omega = 1.633 ms
  const Params stiff = {{"k", 1e6}, {"t_end", 1.0}};
  const double omega = std::sqrt(1e6 * 3.0 / 2.0);
  const double below = 1.8 / omega, above = 2.2 / omega;
  SECTION("omega h = 1.8 (below 2)") {
    const double euler = spring(Method::euler, below, stiff).metric("max_energy_drift");
    const double verlet = spring(Method::verlet, below, stiff).metric("max_energy_drift");
    const double rosen = spring(Method::rosenbrock, below, stiff).metric("max_energy_drift");
    CAPTURE(euler, verlet, rosen);
    CHECK(euler > 1e100);  // |1 + i omega h| = 2.06 per step: blows up
    CHECK(verlet < 10);    // symplectic: bounded (modified energy), large but finite
    CHECK(rosen <= 1.0);   // L-stable: energy can only decay
  }
  SECTION("omega h = 2.2 (above 2)") {
    const double verlet = spring(Method::verlet, above, stiff).metric("max_energy_drift");
    const double rosen = spring(Method::rosenbrock, above, stiff).metric("max_energy_drift");
    CAPTURE(verlet, rosen);
    CHECK(verlet > 1e100);  // Verlet's limit omega h < 2 crossed
    CHECK(rosen <= 1.0);
  }
}

TEST_CASE("integrate: an event is located to the integrator's accuracy", "[scenes][integrators]") {
  // x'' = -x from x = 0, x' = 1: x' = cos t crosses 0 at t = pi/2
  OdeSystem sys;
  sys.dim = 2;
  sys.rhs = [](const State& x, State& d, double) {
    d[0] = x[1];
    d[1] = -x[0];
  };
  Integrator ig(Method::rk4, sys);
  State x = {0, 1};
  auto ev = integrate(ig, x, 0, 10, 0.01, [](const State& s, double) { return s[1]; });
  REQUIRE(ev.event);
  CHECK_THAT(ev.t, WithinAbs(M_PI / 2, 1e-9));
  CHECK_THAT(x[0], WithinAbs(1.0, 1e-9));
}

TEST_CASE("integrators: bad step, tolerance and unsuitable method are errors", "[scenes][integrators][errors]") {
  OdeSystem sys;
  sys.dim = 1;
  sys.rhs = [](const State&, State& d, double) { d[0] = 1; };
  Integrator ig(Method::rk4, sys);
  State x = {0};
  CHECK_THROWS_AS(integrate(ig, x, 0, 1, 0.0), std::domain_error);
  CHECK_THROWS_AS(integrate(ig, x, 0, 1, -1e-3), std::domain_error);
  CHECK_THROWS_AS(integrate(ig, x, 0, 1, NAN), std::domain_error);
  CHECK_THROWS_AS(Integrator(Method::dopri5, sys, 0.0), std::domain_error);
  CHECK_THROWS_AS(Integrator(Method::verlet, sys), std::invalid_argument);
  CHECK_THROWS_AS(parse_method("rk45"), std::invalid_argument);
  CHECK(parse_method("rosenbrock") == Method::rosenbrock);
}
