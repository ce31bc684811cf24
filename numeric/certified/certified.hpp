// Double results with a certificate: `derivcheck eval --method ...` and the C++ API.
//
// Every result carries a rigorous bound on its error, measured against an Arb enclosure of the
// true value (derivations/kernel/ball.hpp, the layer the checker uses): the bound holds whatever
// libm, the tape or the compiler did, because it is computed a posteriori from the enclosure.
//
//   Auto         the double nearest the true value at the written (exact) point (bound 0.5
//                ulp): the tape in double-double, then in long double, each with a running
//                error bound (certified_batch.hpp, certified_fast.hpp), decides where both ends
//                of its interval round to the same double; elsewhere an Arb enclosure is
//                narrowed until they do (milliseconds).
//   Double       the formula's tape in double        } at the inputs rounded to the nearest
//   LongDouble   the formula's tape in long double   } double; the bound is against the true
//   Compensated  the tapes in double-double          } value at those rounded inputs
//   Stable       the file's stable form in its regime (the formula elsewhere), in double
//
// A true value beyond the largest double rounds to +-inf and one below half the smallest
// subnormal to 0: reported with the reason, never as a wrong finite number.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

#include "derivations/reader/derivation.hpp"

namespace dc::num {

enum class DoubleMethod { Auto, Double, LongDouble, Compensated, Stable };

// "auto", "double", "long-double", "compensated", "stable" (nullopt for anything else).
std::optional<DoubleMethod> parse_double_method(const std::string& name);
const char* to_string(DoubleMethod m);

struct CertifiedDouble {
  double value = 0;
  std::string method;        // how `value` was computed, e.g. "double (the formula's tape)"
  // Certified upper bound on |value - true value| in units of the double spacing at the true
  // value (0.5: correctly rounded); negative when there is none (value not finite).
  double error_ulps = -1;
  std::string note;          // why a value is inf/0, or what the bound is relative to
};

// The double nearest to x (ties to even), exactly: the candidate from a decimal conversion and
// its two neighbours are compared as exact rationals. Beyond the overflow threshold: +-inf.
double nearest_double(const GiNaC::numeric& x);

// Formula `label` of `d` at the point `at` (names -> exact values, as `--at` gives them). Names
// of declared symbols that do not occur in the formula (they cancelled) are accepted. Throws
// std::domain_error for a point outside the domain or where the formula has no real value, and
// std::range_error when the enclosure cannot be narrowed within the precision cap.
CertifiedDouble certified_eval(const Derivation& d, const std::string& label,
                               const std::vector<std::pair<std::string, GiNaC::numeric>>& at, DoubleMethod m);

// The first stage of Auto for many points at once (`eval --points`): for each point (exact
// values by name, as certified_eval takes them) the answer certified_eval(d, label, point, Auto)
// gives when its double-double stage decides, else nullopt -- also for a point that does not
// bind (outside the domain, a missing name): run certified_eval for those, which says why.
std::vector<std::optional<CertifiedDouble>> certified_auto_first_stage(
    const Derivation& d, const std::string& label,
    const std::vector<std::vector<std::pair<std::string, GiNaC::numeric>>>& points);

// The round-trip text of a double: the shortest decimal that reads back as the same double
// ("0.1", "1e+200", "-2.5e-300", "inf").
std::string shortest_text(double x);

}  // namespace dc::num
