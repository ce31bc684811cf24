// The step context and the helpers every rule uses (context.hpp).
#include "derivations/steps/context.hpp"

#include <algorithm>

#include "derivations/symbolic/differential.hpp"
#include "derivations/symbolic/functions.hpp"
#include "derivations/symbolic/integral_atom.hpp"
#include "derivations/symbolic/printer.hpp"
#include "derivations/symbolic/vectors.hpp"
#include "derivations/symbolic/inspect.hpp"

namespace dc::rules {

InputError positioned(const Derivation& d, const SourcePos& p, const std::string& msg, int len) {
  return InputError(p, msg, len, d.source.line(p.line));
}

InputError with_line(const Derivation& d, const InputError& e) {
  if (!e.line_text().empty() || e.pos().line < 1) return e;
  return e.with_line_text(d.source.line(e.pos().line));
}

// --- verdicts -------------------------------------------------------------------------

int severity(VerdictKind k) {
  switch (k) {
    case VerdictKind::Proved: return 0;
    case VerdictKind::HoldsNumerically: return 1;
    case VerdictKind::Undecided: return 2;
    case VerdictKind::Refuted: return 3;
  }
  return 2;
}

namespace {
Verdict verdict(VerdictKind kind, const std::string& method) {
  Verdict v;
  v.kind = kind;
  v.method = method;
  return v;
}
}  // namespace

Verdict undecided(const std::string& method, const std::string& reason) {
  Verdict v = verdict(VerdictKind::Undecided, method);
  v.reason = reason;
  return v;
}

Verdict proved(const std::string& method, const std::string& detail) {
  Verdict v = verdict(VerdictKind::Proved, method);
  v.detail = detail;
  return v;
}

std::string prefix_method(const std::string& rule_method, const std::string& prove_method) {
  return prove_method.empty() ? rule_method : rule_method + " + " + prove_method;
}

void Combiner::add(Verdict v, const std::string& what, bool silent) {
  if (!(silent && v.holds()) && std::find(methods.begin(), methods.end(), v.method) == methods.end())
    methods.push_back(v.method);
  if (!what.empty() && v.kind != VerdictKind::Proved) v.detail = what + (v.detail.empty() ? "" : ": " + v.detail);
  if (!any || severity(v.kind) > severity(worst.kind)) worst = std::move(v);
  any = true;
}

Verdict Combiner::result() const {
  if (!any) return undecided("none", "nothing to check");
  Verdict v = worst;
  if (v.kind == VerdictKind::Proved && !methods.empty()) {
    std::string m;
    for (std::size_t i = 0; i < methods.size(); ++i) m += (i ? ", " : "") + methods[i];
    v.method = m;
  }
  return v;
}

// --- expressions ----------------------------------------------------------------------

ex Atomizer::operator()(const ex& e) {
  if (pool_function_index(e) >= 0 || is_integral_quantity(e)) {
    auto it = fwd.find(e);
    if (it != fwd.end()) return it->second;
    GiNaC::realsymbol s("dc_atom" + std::to_string(n++));
    fwd[e] = s;
    back[s] = e;
    return s;
  }
  return e.map(*this);
}

bool free_of_unknowns(const ex& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e) || pool_function_index(e) >= 0 || is_integral_quantity(e)) return false;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (!free_of_unknowns(e.op(i))) return false;
  return true;
}

bool has_any(const ex& e, const std::vector<ex>& syms) {
  for (const auto& s : syms)
    if (e.has(s)) return true;
  return false;
}

// --- the step -------------------------------------------------------------------------

void StepContext::fail(const SourcePos& p, const std::string& msg, int len) const {
  throw StepError{positioned(d, p, msg, len)};
}

std::string StepContext::text(const ex& e) const { return print_text(e, d.symbols); }

ex StepContext::conv(const Node& n) const {
  if (antiderivatives().empty()) return resolved_ginac(d, n);
  return resolved_ginac(d, instantiated(n));
}

namespace {
bool is_indefinite_integral(const Node& n) { return n.kind == NodeKind::Call && n.text == "integral" && n.args.size() == 2; }
}  // namespace

bool StepContext::is_antiderivative(const RuleArg& a) const {
  if (a.kind != RuleArg::Kind::Label) return false;
  for (const auto& ad : antiderivatives())
    if (ad.label == a.label) return true;
  return false;
}

const std::vector<StepContext::Antiderivative>& StepContext::antiderivatives() const {
  if (antiderivatives_) return *antiderivatives_;
  antiderivatives_.emplace();
  for (const auto* group : {&s.rule.refs, &s.rule.into, &s.rule.with})
    for (const auto& a : *group) {
      if (a.kind != RuleArg::Kind::Label) continue;
      const Step* st = d.find(a.label);
      if (!st) continue;
      const Relation& r = claim_of(*st);
      if (r.sides.size() != 2 || !is_indefinite_integral(r.sides[0])) continue;
      const Node& f = r.sides[0].args[0];
      const Node& x = r.sides[0].args[1];
      if (x.kind != NodeKind::Symbol) continue;
      try {
        // F' = f on the whole line, x a fresh real variable: the cited step was checked on x's
        // declared domain only (with x in [0, 1], x^2/2 is an antiderivative of sqrt(x^2),
        // which would make the integral of sqrt(t^2) from -1 to 1 zero)
        const SymbolTable bound = d.symbols.with_bound_variable(x.text);
        const ex xs = bound.find(x.text)->sym;
        Antiderivative ad{a.label, r.sides[1], x, to_ginac(f, bound), xs, to_ginac(r.sides[1], bound)};
        if (!GiNaC::is_a<GiNaC::symbol>(xs) || !continuous_everywhere(ad.Fe, GiNaC::ex_to<GiNaC::symbol>(xs)))
          continue;
        if (!prove_equal(ad.Fe.diff(GiNaC::ex_to<GiNaC::symbol>(xs)), ad.f, bound, opt).holds()) continue;
        antiderivatives_->push_back(std::move(ad));
      } catch (const std::exception&) {
      }
    }
  return *antiderivatives_;
}

// n with each definite integral of a cited antiderivative's integrand replaced by the bar
// eval_between(F, x, a, b).
Node StepContext::instantiated(const Node& n) const {
  if (n.kind == NodeKind::Call && n.text == "integral" && n.args.size() == 4) {
    try {
      const Integrand in = integrand_of(n, d.symbols);
      for (const auto& ad : antiderivatives()) {
        const ex diff = ad.f.subs(GiNaC::exmap{{ad.xs, in.x}}, GiNaC::subs_options::no_pattern) - in.f;
        if (!diff.is_zero() && !diff.expand().is_zero()) continue;
        Node bar = n;
        bar.text = "eval_between";
        bar.args = {ad.F, ad.x, instantiated(n.args[2]), instantiated(n.args[3])};
        return bar;
      }
    } catch (const std::exception&) {
    }
  }
  Node out = n;
  for (auto& a : out.args) a = instantiated(a);
  return out;
}

std::vector<ex> StepContext::sides(const Relation& r) const {
  std::vector<ex> out;
  for (const auto& n : r.sides) out.push_back(conv(n));
  return out;
}

ex StepContext::symbol_of(const RuleArg& a) const {
  ex v = conv(a.value);
  if (!GiNaC::is_a<GiNaC::symbol>(v)) fail(a.pos, "expected a symbol", a.length);
  return v;
}

const Step& StepContext::ref_step(const RuleArg& a) const {
  const Step* st = d.find(a.label);
  if (!st) fail(a.pos, "unknown label '" + a.label + "'", a.length);
  return *st;
}

const Relation& claim_of(const Step& st) { return st.erratum ? st.erratum->corrected : st.claim; }

std::vector<Eq> StepContext::equations(const RuleArg& a) const {
  if (is_antiderivative(a)) return {};   // instantiated where its integrand is integrated (conv)
  const Relation* r;
  std::string from;
  if (a.kind == RuleArg::Kind::Label) {
    const Step& st = ref_step(a);
    r = &claim_of(st);
    from = st.label;
  } else if (a.kind == RuleArg::Kind::Equation) {
    r = &a.equation;
    from = a.label;
  } else {
    fail(a.pos, "expected a label or an equation 'x = value'", a.length);
  }
  if (r->sides.size() < 2)
    fail(a.pos, "'" + from + "' is an expression, not an equation; a rule can only use equations", a.length);
  std::vector<Eq> out;
  if (const int k = vector_shape(*r, d.symbols)) {   // a vector equation: one equation per component
    for (int i = 1; i <= k; ++i) {
      RuleArg component = a;
      component.kind = RuleArg::Kind::Equation;
      component.equation = vector_component(*r, d.symbols, i);
      component.label = from;
      for (auto& q : equations(component)) out.push_back(std::move(q));
    }
    return out;
  }
  // The sides with a value: a side whose limit or integral has none (the limit of an abstract
  // function in `v_T = limit(v(t), t, oo) = m*g/b`) is left out, and the others, equal to it
  // and so to each other, still give equations.
  std::vector<ex> sd;
  std::vector<std::size_t> at;
  std::string undecided_why;
  for (std::size_t i = 0; i < r->sides.size(); ++i) {
    try {
      sd.push_back(conv(r->sides[i]));
      at.push_back(i);
    } catch (const InputError& e) {
      fail(a.pos, "'" + from + "' cannot be used here: " + e.message(), a.length);
    } catch (const UndecidedLimit& e) {
      undecided_why = e.what();
    }
  }
  if (sd.size() < 2 && !undecided_why.empty()) throw UndecidedLimit(undecided_why);
  for (std::size_t i = 0; i + 1 < sd.size(); ++i) {
    Eq q{sd[i] - sd[i + 1], ex(), from};
    if (i == 0 && at[0] == 0 && r->sides[0].kind == NodeKind::Symbol) q.hint = sd[0];
    if (i == 0 && at[0] == 0 && r->sides[0].kind == NodeKind::Call && pool_function_index(sd[0]) >= 0) q.hint = sd[0];
    out.push_back(std::move(q));
  }
  return out;
}

std::vector<Eq> StepContext::all_equations(const std::vector<RuleArg>& args) const {
  std::vector<Eq> out;
  for (const auto& a : args) {
    auto e = equations(a);
    out.insert(out.end(), e.begin(), e.end());
  }
  return out;
}

Substitutions StepContext::substitutions(const std::vector<RuleArg>& args, std::vector<Eq>* rest,
                                         std::vector<std::string>* labels) const {
  Substitutions out;
  for (const auto& a : args) {
    if (is_antiderivative(a)) continue;   // instantiated where its integrand is integrated (conv)
    std::size_t n = out.size();
    const Relation& r0 = a.kind == RuleArg::Kind::Label ? claim_of(ref_step(a)) : a.equation;
    if (r0.sides.size() < 2) fail(a.pos, "'" + a.label + "' is not an equation", a.length);
    const int vk = vector_shape(r0, d.symbols);   // a vector: one substitution per component
    for (int component = vk ? 1 : 0; component <= vk; ++component) {
      const Relation r = vk ? vector_component(r0, d.symbols, component) : r0;
      ex lhs = conv(r.sides.front()), rhs = conv(r.sides.back());
      // a symbol, an abstract function value v(0), or an application such as sin(theta)
      auto substitutable = [](const ex& e) {
        return GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::function>(e) || pool_function_index(e) >= 0;
      };
      const bool forward = substitutable(lhs) && !rhs.has(lhs);
      if (forward || (substitutable(rhs) && !lhs.has(rhs))) {
        if (!forward) std::swap(lhs, rhs);
        // `with f(t) = x` where the file uses d(x): f'(t) is d(x)/d(t) (differential.hpp)
        const ex dx = differential_of(rhs, d.symbols);
        if (!dx.is_zero() && pool_function_index(lhs) >= 0 && pool_derivative_order(lhs) == 0 && lhs.nops() == 1) {
          const ex dt = differential_of(lhs.op(0), d.symbols);
          if (!dt.is_zero()) out.push_back({lhs.diff(GiNaC::ex_to<GiNaC::symbol>(lhs.op(0))), dx / dt});
        }
        out.push_back({lhs, rhs});
      } else if (rest) {
        rest->push_back({lhs - rhs, ex(), a.label});
      } else {
        fail(a.pos, "expected 'x = value' with a symbol x on one side", a.length);
      }
    }
    for (std::size_t k = n; labels && k < out.size(); ++k) labels->push_back(a.label);
  }
  return out;
}

std::vector<ex> StepContext::symbols_in(const std::vector<ex>& es) const {
  GiNaC::lst all;
  for (const auto& e : es) all.append(e);
  return detail::ordered_symbols(all, d.symbols);
}

int StepContext::declaration_index(const ex& s) const {
  int i = 0;
  for (const auto& info : d.symbols.all()) {
    if (info.sym.is_equal(s)) return i;
    ++i;
  }
  return -1;
}

bool StepContext::real_domain(const ex& s) const {
  for (const auto& info : d.symbols.all())
    if (info.sym.is_equal(s)) return info.domain.unrestricted();
  return true;  // atoms (abstract functions) are unrestricted
}

ex apply_subs(ex e, const Substitutions& subs, std::vector<bool>* used) {
  if (used) used->resize(subs.size(), false);
  for (int round = 0; round < 16; ++round) {
    ex before = e;
    for (std::size_t i = 0; i < subs.size(); ++i) {
      ex next = e.subs(subs[i].first == subs[i].second, GiNaC::subs_options::no_pattern);
      if (used && !next.is_equal(e)) (*used)[i] = true;
      e = next;
    }
    if (e.is_equal(before)) break;   // structural: only to detect a fixed point
  }
  return e;
}

void apply_to(Eq& q, const Substitutions& subs, const std::vector<std::string>& labels) {
  std::vector<bool> used;
  q.e = apply_subs(q.e, subs, &used);
  for (std::size_t i = 0; i < used.size(); ++i)
    if (used[i]) q.also.push_back(labels[i]);
}

void add_path_differentials(const StepContext& c, const std::vector<ex>& claim, std::vector<Eq>& eqs) {
  bool differential = false;
  for (const auto& e : claim) differential = differential || !differentials_in(e, c.d.symbols).empty();
  if (!differential) return;
  // the changes this step speaks of: the differentials in the claim and the cited equations;
  // any other quantity's change is an unknown of its own (never a drawn value: a counterexample
  // that needs it is no counterexample to what the author wrote)
  GiNaC::lst spoken;
  for (const auto& e : claim) spoken.append(e);
  for (const auto& q : eqs) spoken.append(q.e);
  std::map<ex, ex, GiNaC::ex_is_less> unknown_change;
  std::vector<Eq> more;
  for (const auto& q : eqs) {
    if (!differentials_in(q.e, c.d.symbols).empty()) continue;
    ex total = 0;
    for (const auto& z : c.symbols_in({q.e})) {
      if (!GiNaC::is_a<GiNaC::symbol>(z)) continue;
      ex dz = differential_of(z, c.d.symbols);
      if (dz.is_zero() || !ex(spoken).has(dz)) {
        auto [it, fresh] = unknown_change.emplace(z, ex());
        // (named apart from d(z): a counterexample that needs it cannot be read back as a point)
        if (fresh) it->second = GiNaC::realsymbol(std::string(kUnknownChange) + c.text(z));
        dz = it->second;
      }
      total += q.e.diff(GiNaC::ex_to<GiNaC::symbol>(z)) * dz;
    }
    if (!total.is_zero()) more.push_back({total, ex(), q.from, q.also});
  }
  eqs.insert(eqs.end(), more.begin(), more.end());
}

// --- names that are functions of t ---------------------------------------------------

ThroughT names_through(const StepContext& c, const ex& t) {
  ThroughT out;
  auto note = [&](const std::string& name, const char* how, const std::string& label) {
    out.evidence += std::string(out.evidence.empty() ? "" : "; ") + name + " is a function of " + c.text(t) + " by its " +
                    how + " " + label;
  };
  for (const auto& a : c.rule().refs) {
    if (a.kind != RuleArg::Kind::Label) continue;
    const Step& r = c.ref_step(a);
    const Relation& rel = claim_of(r);
    if (rel.sides.size() != 2) continue;
    if (r.rule.name == "definition" && introduces_name(r)) {
      if (c.conv(rel.sides[1]).has(t)) note(to_text(rel.sides[0]), "definition", r.label);
      continue;
    }
    if (r.rule.name != "given" || rel.sides[0].kind != NodeKind::Symbol) continue;
    const std::string& name = rel.sides[0].text;
    const SymbolInfo* info = c.d.symbols.find(name);
    if (!info || info->is_function || out.given_values.count(name)) continue;
    const ex value = c.conv(rel.sides[1]);
    if (!value.has(t) || value.has(info->sym) || info->sym.is_equal(t)) continue;
    out.given_values.emplace(name, resolve_definitions(c.d, rel.sides[1]));
    note(name, "given", r.label);
  }
  return out;
}

Node ThroughT::resolve(const Node& n) const {
  if (given_values.empty()) return n;
  std::map<std::string, const Node*> values;
  for (const auto& [name, value] : given_values) values[name] = &value;
  return substitute_names(n, values);
}

std::vector<ex> ThroughT::sides(const StepContext& c, const Relation& claim) const {
  std::vector<ex> out;
  for (const auto& n : claim.sides) out.push_back(c.conv(resolve(resolve_definitions(c.d, n))));
  return out;
}

}  // namespace dc::rules
