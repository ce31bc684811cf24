// side_conditions and check_satisfiable.
#include <catch2/catch.hpp>

#include "derivations/decide/prove.hpp"
#include "support.hpp"

using namespace dc;
using GiNaC::ex;

namespace {

const SideCondition* find_condition(const std::vector<SideCondition>& v, const std::string& what) {
  for (const auto& c : v)
    if (c.what == what) return &c;
  return nullptr;
}

std::string all_text(const std::vector<SideCondition>& v) {
  std::string s;
  for (const auto& c : v) s += c.what + " [" + c.reason + "] " + std::to_string(static_cast<int>(c.status)) + " " + c.evidence + "\n";
  return s;
}

}  // namespace

TEST_CASE("side conditions: divisors, logs, roots, acos", "[side]") {
  test::Table T;
  T.add("m1", Domain::positive())
      .add("m2", Domain::positive())
      .add("x", Domain::real())
      .add("z", test::unit_interval())
      .add("a", Domain::real())
      .add("b", Domain::real());
  ex m1 = T["m1"], m2 = T["m2"], x = T["x"], z = T["z"], a = T["a"], b = T["b"];
  T.assume(a, Constraint::Op::Gt, b, "a > b");
  ex e = (m1 - m2) / (m1 + m2) + GiNaC::log(a - b) + GiNaC::sqrt(x) + GiNaC::acos(1 - 2 * z * z) +
         GiNaC::asin(2 * z) + 1 / (m1 - m2);
  auto conds = side_conditions(e, T.t);
  CAPTURE(all_text(conds));
  using S = SideCondition::Status;
  const SideCondition* sum = find_condition(conds, "m1 + m2 != 0");
  REQUIRE(sum);
  REQUIRE(sum->status == S::Guaranteed);
  REQUIRE(sum->reason == "divisor");
  REQUIRE(sum->evidence.find("m1 positive") != std::string::npos);
  const SideCondition* logc = find_condition(conds, "a - b > 0");
  REQUIRE(logc);
  REQUIRE(logc->status == S::Guaranteed);
  REQUIRE(logc->evidence == "assumed: a > b");
  const SideCondition* root = find_condition(conds, "x >= 0");
  REQUIRE(root);
  REQUIRE(root->status == S::Violated);
  REQUIRE(root->evidence.rfind("fails at x = -", 0) == 0);
  const SideCondition* ac = find_condition(conds, "-1 <= 1 - 2*z^2 <= 1");
  REQUIRE(ac);
  REQUIRE(ac->status == S::Guaranteed);
  const SideCondition* as = find_condition(conds, "-1 <= 2*z <= 1");
  REQUIRE(as);
  REQUIRE(as->status == S::Violated);
  // m1 - m2 can vanish for positive masses but no random point hits it: unknown, not violated
  bool found_diff = false;
  for (const auto& c : conds)
    if (c.reason == "divisor" && c.what.find("m2") != std::string::npos && c.what.find('-') != std::string::npos) {
      found_diff = true;
      REQUIRE(c.status == S::Unknown);
    }
  REQUIRE(found_diff);
  // deterministic, sorted, no duplicates
  auto again = side_conditions(e, T.t);
  REQUIRE(all_text(again) == all_text(conds));
  for (std::size_t i = 1; i < conds.size(); ++i) REQUIRE(conds[i - 1].what < conds[i].what);
}

TEST_CASE("side conditions of a constant-free rational expression with positive symbols", "[side]") {
  test::Table T;
  T.add("m", Domain::positive()).add("M", Domain::positive()).add("L", Domain::positive()).add("g", Domain::positive());
  ex m = T["m"], M = T["M"], L = T["L"], g = T["g"];
  auto conds = side_conditions(m / (M + m) / (2 * L * g), T.t);
  CAPTURE(all_text(conds));
  REQUIRE(!conds.empty());
  for (const auto& c : conds) REQUIRE(c.status == SideCondition::Status::Guaranteed);
}

TEST_CASE("check_satisfiable", "[side][satisfiable]") {
  test::Table T;
  T.add("m1", Domain::positive()).add("m2", Domain::positive()).add("x", Domain::positive());
  ex m1 = T["m1"], m2 = T["m2"], x = T["x"];
  REQUIRE(check_satisfiable(T.t) == "");
  T.assume(m1, Constraint::Op::Gt, m2, "m1 > m2");
  REQUIRE(check_satisfiable(T.t) == "");
  T.assume(m2, Constraint::Op::Gt, m1, "m2 > m1");
  std::string why = check_satisfiable(T.t);
  CAPTURE(why);
  REQUIRE(!why.empty());
  REQUIRE(why.find("'m1 > m2'") != std::string::npos);
  REQUIRE(why.find("'m2 > m1'") != std::string::npos);

  test::Table U;
  U.add("x", Domain::positive());
  U.assume(U["x"], Constraint::Op::Lt, 0, "x < 0");
  std::string never = check_satisfiable(U.t);
  CAPTURE(never);
  REQUIRE(never.find("never hold") != std::string::npos);

  // a thin but nonempty set is found (wide sampling reaches 1e-6)
  test::Table W;
  W.add("x", Domain::positive());
  W.assume(W["x"], Constraint::Op::Lt, GiNaC::numeric(1, 1000), "x < 1/1000");
  REQUIRE(check_satisfiable(W.t) == "");
}

TEST_CASE("side conditions: sin on (0, pi) is positive, a constraint times a positive factor fixes a sign",
          "[prove][side]") {
  test::Table T;
  T.add("g", Domain::positive()).add("l", Domain::positive());
  T.add("theta0", Domain::interval(0, true, GiNaC::Pi / 2, true));
  T.add("y2", Domain::positive()).add("r2", Domain::positive());
  T.add("phi", Domain::real());
  T.assume(T["y2"], Constraint::Op::Gt, T["r2"], "y2 > r2");
  auto status_of = [&](const GiNaC::ex& e) {
    auto conds = side_conditions(e, T.t);
    REQUIRE(conds.size() == 1);
    return conds[0].status;
  };
  // ladder: sqrt(g*l*sin(theta0)) with theta0 in (0, pi/2)
  CHECK(status_of(GiNaC::sqrt(T["g"] * T["l"] * GiNaC::sin(T["theta0"]))) == SideCondition::Status::Guaranteed);
  // cos on (0, pi/2) is positive too; sin of a real angle is not
  CHECK(status_of(GiNaC::log(GiNaC::cos(T["theta0"]))) == SideCondition::Status::Guaranteed);
  CHECK(status_of(GiNaC::log(GiNaC::sin(T["phi"]))) != SideCondition::Status::Guaranteed);
  // two-ball bounce: sqrt(2 g (y2 - r2)), written as GiNaC normalises it, with y2 > r2 assumed
  CHECK(status_of(GiNaC::sqrt(-2 * T["g"] * (T["r2"] - T["y2"]))) == SideCondition::Status::Guaranteed);
  // the constraint gives no sign to a factor of unknown sign
  CHECK(status_of(GiNaC::sqrt(T["phi"] * (T["y2"] - T["r2"]))) != SideCondition::Status::Guaranteed);
}

TEST_CASE("require_solution_without_singularities names a failing condition once", "[side][ode]") {
  dc::Verdict v;
  v.kind = dc::VerdictKind::Proved;
  dc::SideCondition sc;
  sc.what = "t != 0";
  sc.reason = "divisor";
  sc.status = dc::SideCondition::Status::Violated;
  sc.evidence = "fails at t = 0 (value 0)";
  v.side_conditions.push_back(sc);
  dc::require_solution_without_singularities(v, "t");
  CHECK(v.kind == dc::VerdictKind::Undecided);
  CHECK(v.reason.find("(t != 0, divisor, fails at t = 0 (value 0))") != std::string::npos);
  CHECK(v.reason.find("fails fails") == std::string::npos);
}
