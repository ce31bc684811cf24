// What a verdict that holds also requires of the sides' definedness (prove.hpp):
// require_defined_on_domain, require_antiderivative_defined, require_solution_without_singularities.
#include <string>

#include "derivations/decide/prove.hpp"
#include "derivations/kernel/sample.hpp"
#include "derivations/symbolic/inspect.hpp"
#include "derivations/symbolic/printer.hpp"

namespace dc {

using GiNaC::ex;

void require_defined_on_domain(Verdict& v) {
  if (!v.holds()) return;
  for (const SideCondition& sc : v.side_conditions) {
    if (sc.status != SideCondition::Status::Violated) continue;
    v.kind = VerdictKind::Refuted;
    v.method += " + side condition";
    v.points = 0;   // the agreeing points of the verdict it replaces are not evidence here
    v.point = sc.point;
    v.lhs_value.clear();
    v.rhs_value.clear();
    v.detail = "not defined on the whole declared domain: " + sc.what + " (" + sc.reason + ") " + sc.evidence +
               "; restrict the declarations or add an assumption";
    return;
  }
}

void require_antiderivative_defined(Verdict& v, const GiNaC::ex& integrand, const std::string& var,
                                    const SymbolTable& ctx) {
  if (!v.holds()) return;
  for (const SideCondition& sc : v.side_conditions) {
    if (sc.status == SideCondition::Status::Guaranteed) continue;
    if (sc.status == SideCondition::Status::Violated && !sc.point.empty()) {
      // the claimed antiderivative is undefined at this point of the domain: if the integrand
      // is defined there, the claim is false at that point
      GiNaC::exmap at;
      for (const auto& [name, value] : sc.point)
        if (const SymbolInfo* info = ctx.find(name)) at[info->sym] = GiNaC::numeric(value.c_str());
      DigitsGuard g(30);
      const GiNaC::ex f = integrand.subs(at).evalf();
      if (GiNaC::is_a<GiNaC::numeric>(f) && GiNaC::ex_to<GiNaC::numeric>(f).is_real()) {
        v.kind = VerdictKind::Refuted;
        v.method += " + side condition";
        v.points = 0;
        v.point = sc.point;
        v.lhs_value = detail::format_number(GiNaC::ex_to<GiNaC::numeric>(f));
        v.rhs_value = "undefined";
        v.detail = "the claimed antiderivative is not defined at a point of the declared domain where the integrand is: " +
                   sc.what + " (" + sc.reason + ") " + sc.evidence + "; restrict the declarations or use a form defined there";
        return;
      }
    }
    if (!names_symbol(sc.what, var)) continue;
    v.kind = VerdictKind::Undecided;
    v.reason = "the claimed antiderivative may be undefined or jump inside the domain of " + var + " (" + sc.what +
               ", " + sc.reason + ", " +
               (sc.status == SideCondition::Status::Violated
                    ? (sc.evidence.rfind("fails", 0) == 0 ? sc.evidence : "fails " + sc.evidence)
                    : "is not guaranteed by the declarations") +
               "): its derivative matching the integrand proves it only where it is defined and continuous; "
               "restrict the domain or add an assumption";
    v.detail = v.reason;
    return;
  }
}

void require_solution_without_singularities(Verdict& v, const std::string& var) {
  if (!v.holds()) return;
  for (const SideCondition& sc : v.side_conditions) {
    if (sc.status == SideCondition::Status::Guaranteed) continue;
    // A condition on a declared function's values (log(mr(t)/m0) with mr declared positive,
    // which the domains do not reach) is the author's: declared functions are taken to be
    // smooth, as in the continuity test of integrals.
    if (sc.evidence.find("abstract function") != std::string::npos) continue;
    if (!names_symbol(sc.what, var)) continue;
    v.kind = VerdictKind::Undecided;
    v.reason = "the claimed solution may be singular inside the domain (" + sc.what + ", " + sc.reason + ", " +
               (sc.status != SideCondition::Status::Violated ? std::string("is not guaranteed by the declarations")
                : sc.evidence.rfind("fails", 0) == 0         ? sc.evidence
                                                              : "fails " + sc.evidence) +
               "): the residual and the initial values prove it only up to the "
               "first singularity, and a closed form can jump there (atan(1/" + var + ") + atan(" + var +
               ") has derivative 0 but is not constant); restrict the domain or add an assumption";
    v.detail = v.reason;
    return;
  }
}

}  // namespace dc
