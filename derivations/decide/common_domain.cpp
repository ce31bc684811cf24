// Sides undefined at the same points (common_domain.hpp).
#include "derivations/decide/common_domain.hpp"

#include <set>

#include "derivations/decide/prove.hpp"
#include "derivations/kernel/ball.hpp"
#include "derivations/kernel/sample.hpp"

namespace dc {

namespace {

using GiNaC::ex;

enum class Defined { Yes, No, Unknown };

// Is the side, as written, real at p? (defined_at_point, with the side's value when it is)
Defined defined_at(const WrittenSide& s, const GiNaC::exmap& p, std::string* value, const SymbolTable& ctx) {
  const int d = defined_at_point(s.parts, p, &ctx);
  if (d < 0) return Defined::No;
  if (d == 0) return Defined::Unknown;
  kernel::Ball b = kernel::enclose_sign_at(s.value, &p, 128, 1 << 12);
  if (b.status != kernel::BallStatus::Value) return Defined::Unknown;
  if (value) *value = b.text(20);
  return Defined::Yes;
}

GiNaC::exmap point_of(const std::vector<std::pair<std::string, std::string>>& pt, const SymbolTable& ctx) {
  GiNaC::exmap at;
  for (const auto& [name, value] : pt)
    if (const SymbolInfo* info = ctx.find(name)) at[info->sym] = GiNaC::numeric(value.c_str());
  return at;
}

// Refute v at p when one side is defined there and another is not; true when it did.
bool one_side_only(Verdict& v, const std::vector<WrittenSide>& sides, const GiNaC::exmap& p,
                   const std::vector<std::pair<std::string, std::string>>& described, const std::string& what,
                   bool* all_undefined, const SymbolTable& ctx) {
  int yes = -1, no = -1;
  std::string value;
  bool every_no = true;
  for (std::size_t i = 0; i < sides.size(); ++i) {
    std::string val;
    const Defined d = defined_at(sides[i], p, &val, ctx);
    every_no = every_no && d == Defined::No;
    if (d == Defined::Yes && yes < 0) yes = static_cast<int>(i), value = val;
    if (d == Defined::No && no < 0) no = static_cast<int>(i);
  }
  if (all_undefined) *all_undefined = every_no;
  if (yes < 0 || no < 0) return false;
  v.kind = VerdictKind::Refuted;
  v.method += " + side condition";
  v.points = 0;   // the agreeing points of the verdict it replaces are not evidence here
  v.point = described;
  const std::string undefined = "undefined (a side condition of it fails here)";
  // the first side against the one that differs from it in being defined
  const bool first_defined = yes == 0;
  v.lhs_value = first_defined ? value : undefined;
  v.rhs_value = first_defined ? undefined : value;
  if (yes != 0 && no != 0)
    v.lhs_value = "side " + std::to_string(no + 1) + " undefined", v.rhs_value = "side " + std::to_string(yes + 1) + " = " + value;
  v.detail = "only one side is defined at this point of the declared domain: " + what +
             "; restrict the declarations or add an assumption";
  return true;
}

}  // namespace

void require_defined_on_common_domain(Verdict& v, const std::vector<WrittenSide>& sides, const SymbolTable& ctx) {
  if (!v.holds()) return;
  if (sides.size() < 2) return require_defined_on_domain(v);
  std::vector<const SideCondition*> violated;
  for (const SideCondition& sc : v.side_conditions)
    if (sc.status == SideCondition::Status::Violated && !sc.point.empty()) violated.push_back(&sc);
  if (violated.empty()) return require_defined_on_domain(v);   // a violation without a point
  bool every_point_undefined = true;
  for (const SideCondition* sc : violated) {
    bool all_no = false;
    const std::string what = sc->what + " (" + sc->reason + ") " + sc->evidence;
    if (one_side_only(v, sides, point_of(sc->point, ctx), sc->point, what, &all_no, ctx)) return;
    every_point_undefined = every_point_undefined && all_no;
  }
  // The conditions each side needs and the declarations do not guarantee.
  std::vector<std::set<std::string>> needs(sides.size());
  for (std::size_t i = 0; i < sides.size(); ++i) {
    const auto keys = side_condition_keys(sides[i].parts, ctx);
    for (const SideCondition& c : sides[i].conditions)
      if (c.status != SideCondition::Status::Guaranteed) {
        const auto k = keys.find(c.what);
        needs[i].insert(k == keys.end() ? c.what : k->second);
      }
  }
  bool same = true;
  for (std::size_t i = 1; i < sides.size(); ++i) same = same && needs[i] == needs[0];
  // x^a (a not a number) is taken as undefined for x <= 0, yet it is real at special a
  // ((-1)^2): sides undefined by that convention may still be defined, and differ, on a null set
  // of parameter values, so such conditions do not make a common domain
  for (const WrittenSide& s : sides)
    for (const SideCondition& c : s.conditions)
      if (c.status != SideCondition::Status::Guaranteed && c.reason == "power base") same = false;
  // the violated conditions, one of each set of equivalent ones
  std::string conds;
  std::set<std::string> listed;
  for (const SideCondition* sc : violated) {
    std::string key = sc->what;
    for (const WrittenSide& s : sides) {
      const auto keys = side_condition_keys(s.parts, ctx);
      if (const auto k = keys.find(sc->what); k != keys.end()) key = k->second;
    }
    if (listed.insert(key).second) conds += (conds.empty() ? "" : ", ") + sc->what;
  }
  const std::string first_point = detail::join_point(violated.front()->point);
  GiNaC::lst all;
  for (const WrittenSide& s : sides)
    for (std::size_t i = 0; i < s.parts.nops(); ++i) all.append(s.parts.op(i));
  detail::PointSampler sampler({all}, ctx);
  if (same && every_point_undefined) {
    // the common domain must not be empty: a point where every side is defined
    bool inhabited = false;
    detail::Rng seek(20261127 ^ detail::hash_text(conds, 13));
    for (int attempt = 0; attempt < 48 && !inhabited; ++attempt) {
      bool adm = false;
      const GiNaC::exmap p = sampler.draw(seek, attempt % 3 == 2 ? 1 : 0, &adm);
      if (!adm) continue;
      inhabited = true;
      for (const WrittenSide& s : sides) inhabited = inhabited && defined_at(s, p, nullptr, ctx) == Defined::Yes;
    }
    if (!inhabited) {
      v.kind = VerdictKind::Undecided;
      v.reason = "both sides are undefined at " + first_point + " (" + conds +
                 " fails), and no point where they are defined was found: the claim may be about an empty set";
      v.detail = v.reason;
      return;
    }
    v.detail += (v.detail.empty() ? "" : "; ") +
                std::string("holds on the common domain of the sides: both are undefined where ") + conds +
                " fails (e.g. at " + first_point + "), and they need the same conditions";
    v.hint = "both sides are undefined where " + conds + " fails, so the claim holds on their common domain; assume " +
             conds + " to make it hold on the whole declared domain";
    return;
  }
  // Look for a point where exactly one side is defined.
  detail::Rng rng(20261127 ^ detail::hash_text(conds, 11));
  for (int attempt = 0; attempt < 48; ++attempt) {
    bool adm = false;
    const GiNaC::exmap p = sampler.draw(rng, attempt % 3 == 2 ? 1 : 0, &adm);
    if (!adm) continue;
    if (one_side_only(v, sides, p, sampler.describe(p), "the sides need different conditions (" + conds + ")", nullptr, ctx))
      return;
  }
  v.kind = VerdictKind::Undecided;
  v.reason = "the sides agree where both are defined, and both are undefined at " + first_point + " (" + conds +
             " fails), which is not evidence either way; they need different conditions and no point where only one "
             "of them is defined was found; assume " + conds + " to decide the claim on that set";
  v.detail = v.reason;
}

}  // namespace dc
