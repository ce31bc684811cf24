// Bad physical input: std::domain_error naming the parameter, its value and the bound.
#include <cmath>
#include <limits>
#include <string>

#include <catch2/catch.hpp>

#include "numeric/scenes/scenes.hpp"

using namespace dc::scenes;
using Catch::Matchers::Contains;

namespace {

std::string error_of(const std::string& scene, const std::vector<std::string>& sets) {
  try {
    const SceneSpec& spec = find_scene(scene);
    run_scene(spec, resolve(spec, sets), RunOptions{});
  } catch (const std::domain_error& e) {
    return e.what();
  }
  return "no error";
}

std::string run_error(const std::string& scene, double h, double tol = 1e-10) {
  try {
    const SceneSpec& spec = find_scene(scene);
    RunOptions o;
    o.h = h;
    o.tol = tol;
    o.method = Method::dopri5;
    run_scene(spec, defaults(spec), o);
  } catch (const std::domain_error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_CASE("bad physical input names the parameter, its value and the bound", "[scenes][errors]") {
  CHECK_THAT(error_of("spring", {"m1=0"}), Contains("m1 = 0 kg") && Contains("need m1 > 0"));
  CHECK_THAT(error_of("spring", {"m2=-2"}), Contains("m2 = -2 kg") && Contains("m2 > 0"));
  CHECK_THAT(error_of("impact", {"e=1.5"}), Contains("e = 1.5") && Contains("0 <= e <= 1"));
  CHECK_THAT(error_of("bounce", {"e12=-0.1"}), Contains("e12 = -0.1") && Contains("0 <= e12 <= 1"));
  CHECK_THAT(error_of("bounce", {"s=-0.001"}), Contains("s = -0.001 m") && Contains("s >= 0"));
  CHECK_THAT(error_of("chain", {"x=1.5"}), Contains("x = 1.5 m") && Contains("0 <= x <= L = 1 m"));
  CHECK_THAT(error_of("chain", {"x=-0.1"}), Contains("x = -0.1 m"));
  CHECK_THAT(error_of("rocket", {"m_r=1200"}), Contains("m_r = 1200 kg") && Contains("0 < m_r <= m0 = 1000 kg"));
  CHECK_THAT(error_of("rocket", {"m_r=0"}), Contains("m_r = 0 kg"));
  CHECK_THAT(error_of("pendulum", {"v0=1000"}),
             Contains("v0 = 1000 m/s") && Contains("v0 <= (M+m)/m sqrt(2 g L)") && Contains("slack"));
  CHECK_THAT(error_of("pendulum", {"v0=5000"}), Contains("over the top"));
  CHECK_THAT(error_of("ladder", {"theta0=90"}), Contains("theta0 = 90 deg") && Contains("0 < theta0 < 90"));
  CHECK_THAT(error_of("cradle", {"n=2.5"}), Contains("n = 2.5") && Contains("integer"));
  CHECK_THAT(error_of("impact", {"v1=-2"}), Contains("v1 = -2 m/s") && Contains("v1 > v2 = -1"));
  CHECK_THAT(error_of("spring", {"k=nan"}), Contains("k = nan") && Contains("finite"));
  CHECK_THAT(error_of("spring", {"v0=inf"}), Contains("v0 = inf") && Contains("finite"));
  CHECK_THAT(error_of("bounce", {"y2=0.1"}), Contains("y2 = 0.1 m") && Contains("y2 > r2 = 0.12 m"));
  CHECK(error_of("spring", {"m1=3/2"}) == "no error");
}

TEST_CASE("non-positive or non-finite step and tolerance are errors", "[scenes][errors]") {
  CHECK_THAT(run_error("spring", -0.01), Contains("step h = -0.01 s") && Contains("h > 0"));
  CHECK_THAT(run_error("rocket", std::numeric_limits<double>::infinity()), Contains("step h = inf"));
  CHECK_THAT(run_error("spring", 0.01, 0), Contains("tolerance tol = 0") && Contains("tol > 0"));
  CHECK_THAT(run_error("spring", 0.01, -1e-6), Contains("tol > 0"));
  CHECK_THAT(run_error("spring", 0.01, NAN), Contains("tol"));
}

TEST_CASE("the Eigen impact solvers check their input too", "[scenes][errors]") {
  CHECK_THROWS_AS(solve_direct_impact(0, 1, 1, 0, 0.5), std::domain_error);
  CHECK_THROWS_AS(solve_direct_impact(1, 1, 1, 0, 1.01), std::domain_error);
  CHECK_THROWS_AS(solve_oblique_impact(1, -1, 1, 0, 0, 0, 0.5), std::domain_error);
  CHECK_THROWS_AS(solve_oblique_impact(1, 1, NAN, 0, 0, 0, 0.5), std::domain_error);
}

TEST_CASE("unknown scenes, parameters, malformed values and unsuitable methods are rejected", "[scenes][errors]") {
  CHECK_THROWS_AS(find_scene("springs"), std::invalid_argument);
  const SceneSpec& spec = find_scene("spring");
  CHECK_THROWS_WITH(resolve(spec, {"mass=2"}), Contains("unknown parameter 'mass'") && Contains("m1, m2"));
  CHECK_THROWS_WITH(resolve(spec, {"m1=two"}), Contains("cannot read m1"));
  CHECK_THROWS_WITH(resolve(spec, {"m1"}), Contains("NAME=VALUE"));
  RunOptions o;
  o.method = Method::verlet;
  CHECK_THROWS_AS(run_scene(find_scene("ladder"), defaults(find_scene("ladder")), o), std::invalid_argument);
}

TEST_CASE("every scene's defaults are within its own bounds and documented", "[scenes]") {
  for (const auto& spec : scene_specs()) {
    CAPTURE(spec.name);
    CHECK_NOTHROW(validate(spec, defaults(spec)));
    CHECK_FALSE(spec.assumptions.empty());
    CHECK_FALSE(spec.dofs.empty());
    const std::string d = describe(spec);
    for (const auto& ps : spec.params) CHECK_THAT(d, Contains(ps.name) && Contains(ps.unit));
  }
}
