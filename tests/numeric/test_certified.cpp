// The certified evaluator (numeric/certified/certified.hpp) on a corpus of hard cases of our own
// (tests/data/numeric/hard.dc): cancellation, intermediate overflow and underflow, results near
// and outside double's range. For every case and method the certificate is checked against an
// independent reference (CLN at 60 digits, numeric/reference/reference.hpp, not the Arb enclosure the
// certificate comes from): `auto` must be within 0.5 ulp, every double method's error must be
// within its stated bound. The plain double error is computed too, to show the cases are hard.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "derivations/reader/derivation.hpp"
#include "numeric/certified/certified.hpp"
#include "numeric/reference/exact.hpp"
#include "numeric/reference/reference.hpp"

namespace {

using dc::num::DoubleMethod;

const dc::Derivation& hard() {
  static const dc::Derivation d =
      dc::load_derivation(std::string(DERIVCHECK_SOURCE_DIR) + "/tests/data/numeric/hard.dc");
  return d;
}

struct Case {
  const char* label;
  const char* at;
  int outside;   // 0: the value is a finite double; +1: overflows; -1: underflows to 0
};

const Case kCases[] = {
    {"log_ratio", "tau=1,t=1e-12", 0},          {"log_ratio", "tau=1,t=1e-5", 0},
    {"log_ratio", "tau=3,t=2.9999", 0},         {"log_ratio", "tau=1e-3,t=1e-18", 0},
    {"one_minus_cos", "theta=1e-8", 0},         {"one_minus_cos", "theta=1e-4", 0},
    {"one_minus_cos", "theta=1/2", 0},          {"one_minus_cos", "theta=3.1", 0},
    {"ellipse", "theta=1e-9,e=0.999999", 0},    {"ellipse", "theta=1.5707963267948966,e=0.3", 0},
    {"ellipse", "theta=1e-3,e=1/2", 0},         {"ellipse", "theta=3.14159,e=0.9999999", 0},
    {"momentum_norm", "m1=1e160,m2=1e160,v1=3,v2=4", 0},
    {"momentum_norm", "m1=1e-170,m2=1e-170,v1=3,v2=4", 0},
    {"momentum_norm", "m1=1,m2=2,v1=1e200,v2=1e200", 0},
    {"momentum_norm", "m1=2,m2=3,v1=0.5,v2=-0.25", 0},
    {"bounce", "y=3/4,k=2600,c=1000", 0},       {"bounce", "y=1/2,k=1074,c=1", 0},
    {"bounce", "y=0.9,k=7000,c=1e300", 0},      {"bounce", "y=3/4,k=2700,c=1", -1},
    {"rocket_mass", "mf=1,dv=1e3,u=1.5", 0},    {"rocket_mass", "mf=1e-300,dv=1500,u=2", 0},
    {"rocket_mass", "mf=1000,dv=9000,u=3000", 0}, {"rocket_mass", "mf=1,dv=-1e3,u=1.4", 0},
    {"rocket_mass", "mf=1e10,dv=2e3,u=2", +1},
    {"energy_difference", "m1=2,m2=3,v1=1.5,v2=1.4999999", 0},
    {"energy_difference", "m1=1e160,m2=2e160,v1=1,v2=2", 0},
    {"energy_difference", "m1=1,m2=1,v1=1e8,v2=100000001", 0},
    {"energy_difference", "m1=3,m2=1e-10,v1=2,v2=0", 0},
    {"restitution_loss", "e=0.9999999999", 0},  {"restitution_loss", "e=1/2", 0},
    {"restitution_loss", "e=0.99999999999999", 0},
    {"exp_big", "x=700", 0},                    {"exp_big", "x=709.7", 0},
    {"exp_big", "x=-745", 0},                   {"exp_big", "x=1e200", +1},
    {"exp_big", "x=-1e200", -1},                {"exp_big", "x=710", +1},
    {"expm1_small", "x=1e-10", 0},              {"expm1_small", "x=-1e-15", 0},
    {"expm1_small", "x=1e-300", 0},
    {"rocket_velocity", "mr=999.999,m0=1000,u=2500,g=9.81,t=0.001", 0},
    {"rocket_velocity", "mr=1,m0=1000,u=3000,g=9.81,t=100", 0},
    {"rocket_velocity", "mr=999.999999,m0=1000,u=2500,g=9.81,t=1e-9", 0},
    {"cancelled", "m=2,v=3", 0},                {"cancelled", "m=1e300,v=1e-300", 0},
    {"quadratic_root", "r=1e8,y=1", 0},         {"quadratic_root", "r=1e-8,y=1e-20", 0},
    {"quadratic_root", "r=-1e8,y=1", 0},
    {"log1p_small", "x=1e-12", 0},              {"log1p_small", "x=-1e-17", 0},
    {"log1p_small", "x=1e-300", 0},
};

// The exact point, or the point with every value rounded to the nearest double.
GiNaC::exmap point_of(const dc::Formula& f, const std::string& at, bool rounded) {
  auto values = dc::num::parse_assignments(at);
  if (rounded)
    for (auto& [n, v] : values) v = dc::num::exact_rational(dc::num::nearest_double(v));
  return dc::num::bind_point(hard(), f, values);
}

}  // namespace

TEST_CASE("certified double results are within their stated bounds on the hard corpus", "[numeric][certified]") {
  int hard_for_double = 0, cases = 0;
  for (const Case& c : kCases) {
    CAPTURE(c.label, c.at);
    ++cases;
    const dc::Formula f = dc::formula(hard(), c.label);
    const auto at = dc::num::parse_assignments(c.at);
    const dc::num::CertifiedDouble a = dc::num::certified_eval(hard(), c.label, at, DoubleMethod::Auto);
    CAPTURE(a.value, a.method, a.error_ulps, a.note);
    if (c.outside > 0) {
      // not representable: infinity with the reason, never a wrong finite number
      CHECK(std::isinf(a.value));
      CHECK(a.error_ulps < 0);
      CHECK(a.note.find("overflows double") != std::string::npos);
      continue;
    }
    if (c.outside < 0) {
      CHECK(a.value == 0);
      CHECK(a.note.find("0") != std::string::npos);
      continue;
    }
    // auto: correctly rounded, against CLN at 60 digits
    const GiNaC::numeric ref = dc::num::reference_value(f.expr, point_of(f, c.at, false), 60);
    CAPTURE(dc::num::format_significant(ref, 20));
    REQUIRE(std::isfinite(a.value));
    CHECK(a.error_ulps == 0.5);
    CHECK(dc::num::error_in_ulps(a.value, ref) <= 0.5 + 1e-12);
    // every double method: its error at the rounded inputs is within its certificate
    const GiNaC::numeric ref_rounded = dc::num::reference_value(f.expr, point_of(f, c.at, true), 60);
    for (DoubleMethod m : {DoubleMethod::Double, DoubleMethod::LongDouble, DoubleMethod::Compensated,
                           DoubleMethod::Stable}) {
      const dc::num::CertifiedDouble r = dc::num::certified_eval(hard(), c.label, at, m);
      CAPTURE(dc::num::to_string(m), r.value, r.error_ulps, r.note);
      if (!std::isfinite(r.value)) {
        CHECK(r.error_ulps < 0);   // no bound claimed for a value that is not finite
        CHECK(r.note.find("the true value") != std::string::npos);
        if (m == DoubleMethod::Double) ++hard_for_double;
        continue;
      }
      const double actual = dc::num::error_in_ulps(r.value, ref_rounded);
      CHECK(actual <= r.error_ulps * (1 + 1e-9) + 1e-300);
      if (m == DoubleMethod::Double && actual > 4) ++hard_for_double;
    }
  }
  INFO(hard_for_double << " of " << cases << " cases lose more than 4 ulps (or overflow) in plain double");
  CHECK(cases >= 50);
  CHECK(hard_for_double >= 20);
}

TEST_CASE("nearest_double rounds exactly, ties to even, and overflows only past the threshold", "[numeric][certified]") {
  using dc::num::exact_rational;
  using dc::num::nearest_double;
  const double one_ulp = std::nextafter(1.0, 2.0) - 1.0;
  const GiNaC::numeric half_ulp = exact_rational(one_ulp) / 2;
  CHECK(nearest_double(1 + half_ulp) == 1.0);                        // tie: even
  CHECK(nearest_double(1 + 3 * half_ulp) == 1 + 2 * one_ulp);       // tie: even (up)
  CHECK(nearest_double(1 + half_ulp + GiNaC::numeric(1, 10).power(30)) == 1 + one_ulp);
  const double big = std::numeric_limits<double>::max();
  const GiNaC::numeric max_ulp = exact_rational(big) - exact_rational(std::nextafter(big, 0.0));
  CHECK(nearest_double(exact_rational(big) + max_ulp / 2 - 1) == big);
  CHECK(std::isinf(nearest_double(exact_rational(big) + max_ulp / 2)));
  CHECK(nearest_double(exact_rational(4.9406564584124654e-324) / 2) == 0.0);   // tie with 0: even
  CHECK(nearest_double(GiNaC::numeric(1, 10)) == 0.1);
  CHECK(dc::num::shortest_text(0.1) == "0.1");
  CHECK(dc::num::shortest_text(1e200) == "1e+200");
  CHECK(dc::num::shortest_text(-std::numeric_limits<double>::infinity()) == "-inf");
}
