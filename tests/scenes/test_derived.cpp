// The closed forms evaluated from the derivation files (by label) agree with the hand-typed
// built-in copies, and every labelled closed form resolves at the scenes' defaults.
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "numeric/scenes/derived.hpp"
#include "numeric/scenes/scenes.hpp"

using namespace dc::scenes;
using Catch::Matchers::StartsWith;

static const std::string kDir = std::string(DERIVCHECK_SOURCE_DIR) + "/derivations/handout9";

TEST_CASE("closed forms from derivations/handout9 agree with the built-in copies", "[scenes][derived]") {
  int derived = 0;
  for (const auto& spec : scene_specs()) {
    RunOptions o;
    o.method = spec.default_method;
    o.derivations = kDir;
    const auto r = run_scene(spec, defaults(spec), o);
    for (const auto& c : r.comparisons) {
      CAPTURE(spec.name, c.quantity, c.source, c.closed_form, c.builtin);
      // a labelled closed form that failed to load says "built-in (reason)"
      CHECK_THAT(c.source, !StartsWith("built-in ("));
      if (c.source != "built-in") {
        ++derived;
        const double scale = std::max(std::abs(c.builtin), 1e-300);
        CHECK(std::abs(c.closed_form - c.builtin) <= 4e-16 * scale);
      }
    }
  }
  CHECK(derived >= 18);
}

TEST_CASE("derived_value reports why a closed form is unavailable", "[scenes][derived]") {
  std::string why;
  CHECK_FALSE(derived_value("", "06_ballistic_pendulum.dc", "deflection", {}, &why));
  CHECK_FALSE(derived_value(kDir, "no_such_file.dc", "x", {}, &why));
  CHECK_THAT(why, Catch::Matchers::Contains("no_such_file.dc"));
  CHECK_FALSE(derived_value(kDir, "06_ballistic_pendulum.dc", "no_such_label", {}, &why));
  CHECK_FALSE(derived_value(kDir, "06_ballistic_pendulum.dc", "deflection", {{"m", 1}}, &why));
  CHECK_THAT(why, Catch::Matchers::Contains("needs"));
  const auto v = derived_value(kDir, "06_ballistic_pendulum.dc", "deflection",
                               {{"m", 0.01}, {"M", 2}, {"v0", 300}, {"L", 1}, {"g", 9.81}}, &why);
  REQUIRE(v);
  CHECK_THAT(*v, Catch::Matchers::WithinRel(0.481158522735854, 1e-14));
}
