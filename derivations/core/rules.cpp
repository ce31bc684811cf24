// Rule checkers (docs/format.md, "Rules"). Each rule derives its own result with GiNaC and
// asks prove_equal / prove_zero whether the author's claim equals it; no rule decides
// equality with `ex == ex`.
//
// The shared tool is "the claim follows from equations": the references give equations
// E_k = 0; variables that an equation determines linearly are eliminated one equation at a
// time (Gaussian elimination over rational functions, with a preference for the unknowns the
// rule names and for symbols of the claim), and what remains of each side of the claim is
// handed to prove_equal. Eliminating x with E = c*x + r (c != 0 generically) parametrises the
// solution set of the equations, so a claim that holds on it reduces to an identity.
#include "derivations/core/rules.hpp"

#include <chrono>
#include <functional>
#include <map>
#include <set>

#include "derivations/core/functions.hpp"
#include "derivations/core/limit.hpp"
#include "derivations/core/printer.hpp"
#include "derivations/core/prove_detail.hpp"
#include "derivations/core/units.hpp"
#include "derivations/kernel/quadrature.hpp"

namespace dc {

namespace {

using GiNaC::ex;

// Thrown inside a rule when the step cannot be checked as written (reported as an error).
// input: the input itself is unusable (references that contradict each other): exit code 2.
struct StepError {
  InputError error;
  bool input = false;
};

InputError positioned(const Derivation& d, const SourcePos& p, const std::string& msg, int len = 1) {
  return InputError(p, msg, len, d.source.line(p.line));
}
InputError with_line(const Derivation& d, const InputError& e) {
  if (!e.line_text().empty() || e.pos().line < 1) return e;
  return e.with_line_text(d.source.line(e.pos().line));
}

int severity(VerdictKind k) {
  switch (k) {
    case VerdictKind::Proved: return 0;
    case VerdictKind::HoldsNumerically: return 1;
    case VerdictKind::Undecided: return 2;
    case VerdictKind::Refuted: return 3;
  }
  return 2;
}

Verdict undecided(const std::string& method, const std::string& reason) {
  Verdict v;
  v.kind = VerdictKind::Undecided;
  v.method = method;
  v.reason = reason;
  return v;
}

Verdict proved(const std::string& method, const std::string& detail = {}) {
  Verdict v;
  v.kind = VerdictKind::Proved;
  v.method = method;
  v.detail = detail;
  return v;
}

// The worst verdict decides; proved methods are listed once each, in order.
struct Combiner {
  Verdict worst;
  bool any = false;
  std::vector<std::string> methods;
  // silent: a consistency check whose method is not worth naming when it holds
  void add(Verdict v, const std::string& what, bool silent = false) {
    if (!(silent && v.holds()) && std::find(methods.begin(), methods.end(), v.method) == methods.end())
      methods.push_back(v.method);
    if (!what.empty() && v.kind != VerdictKind::Proved) v.detail = what + (v.detail.empty() ? "" : ": " + v.detail);
    if (!any || severity(v.kind) > severity(worst.kind)) worst = std::move(v);
    any = true;
  }
  Verdict result() const {
    if (!any) return undecided("none", "nothing to check");
    Verdict v = worst;
    if (v.kind == VerdictKind::Proved && !methods.empty()) {
      std::string m;
      for (std::size_t i = 0; i < methods.size(); ++i) m += (i ? ", " : "") + methods[i];
      v.method = m;
    }
    return v;
  }
};

std::string prefix_method(const std::string& rule_method, const std::string& prove_method) {
  return prove_method.empty() ? rule_method : rule_method + " + " + prove_method;
}

// --- atoms: abstract function applications become symbols while eliminating ----------
struct Atomizer : GiNaC::map_function {
  GiNaC::exmap fwd, back;
  int n = 0;
  ex operator()(const ex& e) override {
    if (pool_function_index(e) >= 0) {
      auto it = fwd.find(e);
      if (it != fwd.end()) return it->second;
      GiNaC::realsymbol s("dc_atom" + std::to_string(n++));
      fwd[e] = s;
      back[s] = e;
      return s;
    }
    return e.map(*this);
  }
  ex restore(const ex& e) const { return back.empty() ? e : e.subs(back, GiNaC::subs_options::no_pattern); }
};

void collect_symbols(const ex& e, std::vector<ex>& out) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    for (const auto& o : out)
      if (o.is_equal(e)) return;
    out.push_back(e);
    return;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) collect_symbols(e.op(i), out);
}

// No symbol and no abstract application: a constant (possibly irrational: pi - 3).
bool free_of_unknowns(const ex& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e) || pool_function_index(e) >= 0) return false;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (!free_of_unknowns(e.op(i))) return false;
  return true;
}

// A rational function of symbols with exact coefficients (pi allowed: it is transcendental).
// Such an expression is identically zero exactly when normal() makes it 0.
bool rational_function(const ex& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) return true;
  if (GiNaC::is_a<GiNaC::numeric>(e)) return GiNaC::ex_to<GiNaC::numeric>(e).is_crational();
  if (GiNaC::is_a<GiNaC::constant>(e)) return e.is_equal(GiNaC::Pi);
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!rational_function(e.op(i))) return false;
    return true;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) return e.op(1).info(GiNaC::info_flags::integer) && rational_function(e.op(0));
  return false;
}

bool has_any(const ex& e, const std::vector<ex>& syms) {
  for (const auto& s : syms)
    if (e.has(s)) return true;
  return false;
}

// An equation E = 0 with an optional hint: the symbol the author wrote alone on its left.
struct Eq {
  Eq(ex e_, ex hint_ = ex(), std::string from_ = {}, std::vector<std::string> also_ = {})
      : e(std::move(e_)), hint(std::move(hint_)), from(std::move(from_)), also(std::move(also_)) {}
  ex e;
  ex hint;
  std::string from;                // label, for messages
  std::vector<std::string> also;   // further references it rests on (substitutions applied to it)
};

class Checker {
 public:
  Checker(const Derivation& d, const Step& s, const ProveOptions& opt, StepResult& res)
      : d_(d), s_(s), opt_(opt), res_(res) {}

  Verdict run(const Relation& claim);

 private:
  const Derivation& d_;
  const Step& s_;
  const ProveOptions& opt_;
  StepResult& res_;
  Atomizer atoms_;

  const RuleSpec& rule() const { return s_.rule; }
  [[noreturn]] void fail(const SourcePos& p, const std::string& msg, int len = 1) const {
    throw StepError{positioned(d_, p, msg, len)};
  }

  std::string text(const ex& e) const { return print_text(e, d_.symbols); }

  ex conv(const Node& n) const { return resolved_ginac(d_, n); }

  std::vector<ex> sides(const Relation& r) const {
    std::vector<ex> out;
    for (const auto& n : r.sides) out.push_back(conv(n));
    return out;
  }

  const Step& ref_step(const RuleArg& a) const {
    const Step* st = d_.find(a.label);
    if (!st) fail(a.pos, "unknown label '" + a.label + "'", a.length);
    return *st;
  }
  static const Relation& claim_of(const Step& st) { return st.erratum ? st.erratum->corrected : st.claim; }

  // Equations of a referenced step (adjacent sides), or of an inline equation.
  std::vector<Eq> equations(const RuleArg& a) const {
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
    std::vector<ex> sd;
    try {
      sd = sides(*r);
    } catch (const InputError& e) {
      fail(a.pos, "'" + from + "' cannot be used here: " + e.message(), a.length);
    }
    for (std::size_t i = 0; i + 1 < sd.size(); ++i) {
      Eq q{sd[i] - sd[i + 1], ex(), from};
      if (i == 0 && r->sides[0].kind == NodeKind::Symbol) q.hint = sd[0];
      if (i == 0 && r->sides[0].kind == NodeKind::Call && pool_function_index(sd[0]) >= 0) q.hint = sd[0];
      out.push_back(std::move(q));
    }
    return out;
  }

  std::vector<Eq> all_equations(const std::vector<RuleArg>& args) const {
    std::vector<Eq> out;
    for (const auto& a : args) {
      auto e = equations(a);
      out.insert(out.end(), e.begin(), e.end());
    }
    return out;
  }

  // Substitutions `x = value` (inline or a label `x = expr`), applied in order.
  // labels (optional): the label of each substitution, for messages.
  std::vector<std::pair<ex, ex>> substitutions(const std::vector<RuleArg>& args, std::vector<Eq>* rest,
                                               std::vector<std::string>* labels = nullptr) const {
    std::vector<std::pair<ex, ex>> out;
    for (const auto& a : args) {
      std::size_t n = out.size();
      const Relation& r = a.kind == RuleArg::Kind::Label ? claim_of(ref_step(a)) : a.equation;
      if (r.sides.size() < 2) fail(a.pos, "'" + a.label + "' is not an equation", a.length);
      ex lhs = conv(r.sides.front()), rhs = conv(r.sides.back());
      // a symbol, an abstract function value v(0), or an application such as sin(theta)
      auto substitutable = [](const ex& e) {
        return GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::function>(e) || pool_function_index(e) >= 0;
      };
      if (substitutable(lhs) && !rhs.has(lhs)) out.push_back({lhs, rhs});
      else if (substitutable(rhs) && !lhs.has(rhs)) out.push_back({rhs, lhs});
      else if (rest) rest->push_back({lhs - rhs, ex(), a.label});
      else fail(a.pos, "expected 'x = value' with a symbol x on one side", a.length);
      if (labels && out.size() > n) labels->push_back(a.label);
    }
    return out;
  }

  // Apply substitutions to an equation, recording the ones that changed it as references it
  // rests on.
  static void apply_to(Eq& q, const std::vector<std::pair<ex, ex>>& subs, const std::vector<std::string>& labels) {
    std::vector<bool> used;
    q.e = apply(q.e, subs, &used);
    for (std::size_t i = 0; i < used.size(); ++i)
      if (used[i]) q.also.push_back(labels[i]);
  }
  // Substitutions are applied repeatedly until nothing changes (so they may be given in any
  // order); a cycle x = y, y = x stops after a fixed number of rounds.
  // `used` (optional, one flag per substitution) records which substitutions changed something.
  static ex apply(ex e, const std::vector<std::pair<ex, ex>>& subs, std::vector<bool>* used = nullptr) {
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

  // --- elimination ------------------------------------------------------------------
  // Eliminating x with an equation c*x + r = 0 replaces x by -r/c everywhere. That division is
  // only allowed when c is not identically zero: u*log(a*b) = u*log(a) + u*log(b) holds for every
  // u (a, b positive), and dividing by its coefficient log(a*b) - log(a) - log(b) would "derive"
  // u = 0, from which false claims follow.
  struct Elimination {
    ex var;            // atomized: a symbol, an abstract application's stand-in, sin(theta), omega^2
    ex value;          // var = value in the quantities not eliminated (kept fully substituted)
    ex coef;           // the coefficient divided by, with later eliminations substituted as in value
    ex coef_checked;   // the coefficient when it was shown not to be identically zero
    bool function_atom = false;   // sin(theta), omega^2: a function of symbols that remain
    int equation = -1;            // index of the equation it was eliminated with
    std::string key;              // deterministic text of var
    std::vector<int> sources;     // every equation the value rests on (for messages)
  };
  struct Leftover {
    ex e;                         // atomized, reduced; nothing in it could be eliminated
    std::vector<int> sources;
    std::vector<ex> used;         // the eliminated atoms substituted into it
  };
  struct Reduction {
    std::vector<Elimination> eliminated;
    std::vector<Leftover> leftover;
    int vanished = 0;             // equations that reduced to 0 identically
    bool resource_limit = false;
    bool degenerate = false;      // no elimination order with nonzero coefficients was found
  };

  static void merge_sources(std::vector<int>& into, const std::vector<int>& from) {
    into.insert(into.end(), from.begin(), from.end());
    std::sort(into.begin(), into.end());
    into.erase(std::unique(into.begin(), into.end()), into.end());
  }

  int declaration_index(const ex& s) const {
    int i = 0;
    for (const auto& info : d_.symbols.all()) {
      if (info.sym.is_equal(s)) return i;
      ++i;
    }
    return -1;
  }
  bool real_domain(const ex& s) const {
    for (const auto& info : d_.symbols.all())
      if (info.sym.is_equal(s)) return info.domain.kind == Domain::Kind::Real;
    return true;  // atoms (abstract functions) are unrestricted
  }

  static void collect_functions(const ex& e, std::vector<ex>& out) {
    if (GiNaC::is_a<GiNaC::function>(e)) {
      for (const auto& o : out)
        if (o.is_equal(e)) return;
      out.push_back(e);
    }
    for (std::size_t i = 0; i < e.nops(); ++i) collect_functions(e.op(i), out);
  }

  static void collect_symbol_powers(const ex& e, std::vector<ex>& out) {
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::symbol>(e.op(0))) {
      for (const auto& o : out)
        if (o.is_equal(e)) return;
      out.push_back(e);
      return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i) collect_symbol_powers(e.op(i), out);
  }

  // Is `num` linear in `c` (a symbol or a function application)? Then value = -rest/coef.
  static bool linear_in(const ex& num, const ex& c, ex& coef, ex& value) {
    ex n = num, var = c;
    GiNaC::realsymbol tmp("dc_tmp");
    if (!GiNaC::is_a<GiNaC::symbol>(c)) {
      n = num.subs(c == tmp, GiNaC::subs_options::no_pattern);
      var = tmp;
      if (!n.has(tmp)) return false;
      // omega^2 counts only when omega occurs nowhere else
      if (GiNaC::is_a<GiNaC::power>(c) && n.has(c.op(0))) return false;
    }
    ex k = n.coeff(var, 1);
    if (k.is_zero() || k.has(var)) return false;
    ex rest = (n - k * var).expand();
    if (rest.has(var)) return false;
    if (!GiNaC::is_a<GiNaC::symbol>(c)) {
      // the application must not survive elsewhere (e.g. theta outside sin(theta) is fine,
      // but sin(theta) inside the coefficient is not)
      if (k.has(c) || rest.has(c)) return false;
    }
    coef = k;
    value = -rest / k;
    return true;
  }

  // Is the coefficient of an elimination not identically zero on the declared domain? Exact
  // tests first (a nonzero number, a sign the domains make evident, a rational function whose
  // normal form is not 0); otherwise the probe must find a point where it is nonzero (prove_zero
  // refutes it). Identically zero, "holds numerically" and undecided all forbid the division.
  bool nonzero_coefficient(const ex& coef) {
    if (GiNaC::is_a<GiNaC::numeric>(coef)) return !coef.is_zero();
    auto it = nonzero_cache_.find(coef);
    if (it != nonzero_cache_.end()) return it->second;
    bool nonzero;
    ex c = atoms_.restore(coef);
    if (detail::provably_nonzero(c, d_.symbols)) {
      nonzero = true;
    } else if (rational_function(coef)) {
      // Atoms stand for independent quantities; a nonzero rational function of independent
      // quantities is nonzero on any open set, so its normal form decides.
      try {
        nonzero = !GiNaC::normal(coef).is_zero();
      } catch (const std::exception&) {
        nonzero = false;
      }
    } else {
      nonzero = prove_zero(c, d_.symbols, opt_).kind == VerdictKind::Refuted;
    }
    nonzero_cache_.emplace(coef, nonzero);
    return nonzero;
  }
  std::map<ex, bool, GiNaC::ex_is_less> nonzero_cache_;

  // An atom that an equation determines linearly, and how much the rules prefer it.
  struct Candidate {
    long score = 0;
    std::string key;   // deterministic text: breaks ties (GiNaC's traversal order varies by process)
    ex var, value, coef;
    bool is_function = false;
  };

  // Every atom of `num` that it determines linearly, best first: the rule's unknowns, symbols
  // before applications such as sin(theta), atoms of the claim, the symbol written alone on the
  // reference's left, real-domain symbols, numeric coefficients, then declaration order and text.
  std::vector<Candidate> candidates(const ex& num, const ex& hint, const ex& target, const std::vector<ex>& preferred,
                                    bool only_preferred) {
    std::vector<Candidate> out;
    auto consider = [&](const ex& c, bool is_function) {
      bool pref = false;
      for (const auto& p : preferred)
        if (p.is_equal(c) || atoms_(p).is_equal(c)) pref = true;
      if (only_preferred && !pref) return;
      Candidate k;
      if (!linear_in(num, c, k.coef, k.value)) return;
      long score = 0;
      if (pref) score += 1000;
      if (!is_function) score += 500;
      if (target.has(c)) score += 100;
      if (hint.is_equal(c)) score += 50;
      if (is_function || real_domain(c)) score += 20;
      if (GiNaC::is_a<GiNaC::numeric>(k.coef)) score += 10;
      k.score = score * 100 + std::max(0, declaration_index(c)) % 100;
      k.key = text(atoms_.restore(c));
      k.var = c;
      k.is_function = is_function;
      out.push_back(std::move(k));
    };
    std::vector<ex> syms;
    collect_symbols(num, syms);
    for (const auto& c : syms) consider(c, false);
    std::vector<ex> fns;
    collect_functions(num, fns);
    collect_symbol_powers(num, fns);
    for (const auto& f : fns)
      if (pool_function_index(f) < 0) consider(f, true);
    std::stable_sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
      return a.score != b.score ? a.score > b.score : a.key < b.key;
    });
    return out;
  }

  // Gaussian elimination, one atom per equation. An elimination whose coefficient turns out to
  // vanish identically once later equations are used (c*u = 0, then c = 0) was not allowed: the
  // reduction is redone without that choice.
  using Bans = std::set<std::pair<int, std::string>>;   // (equation, atom) choices that may not be used
  Reduction reduce(const std::vector<Eq>& eqs, const ex& target, const std::vector<ex>& preferred,
                   bool only_preferred, Bans banned = {}) {
    Reduction red;
    for (int attempt = 0; attempt < 8; ++attempt) {
      red = reduce_once(eqs, target, preferred, only_preferred, banned);
      const Elimination* bad = vanishing_elimination(red);
      if (!bad) return red;
      banned.insert({bad->equation, bad->key});
    }
    red.degenerate = true;
    return red;
  }

  // The first elimination whose coefficient, with the later eliminations substituted, is
  // identically zero (nullptr if none).
  const Elimination* vanishing_elimination(const Reduction& red) {
    for (const auto& el : red.eliminated)
      if (!el.coef.is_equal(el.coef_checked) && !nonzero_coefficient(el.coef)) return &el;
    return nullptr;
  }

  Reduction reduce_once(const std::vector<Eq>& eqs, const ex& target, const std::vector<ex>& preferred,
                        bool only_preferred, const Bans& banned) {
    Reduction red;
    ex t = atoms_(target);
    // Work list: an equation with nothing to eliminate is retried after later eliminations
    // (v1 eliminated by a later reference makes dh = v1^2/(2 g) usable).
    std::vector<int> pending(eqs.size());
    for (std::size_t i = 0; i < eqs.size(); ++i) pending[i] = static_cast<int>(i);
    for (int pass = 0; pass < 8 && !pending.empty(); ++pass) {
      std::size_t before = red.eliminated.size();
      std::vector<int> retry;
      red.leftover.clear();
      for (int idx : pending) {
        std::vector<int> sources{idx};
        std::vector<ex> used;
        ex e = atoms_(eqs[idx].e);
        for (const auto& el : red.eliminated) {
          if (!e.has(el.var)) continue;
          e = e.subs(el.var == el.value, GiNaC::subs_options::no_pattern);
          merge_sources(sources, el.sources);
          used.push_back(el.var);
        }
        if (estimate_expanded_terms(e) > static_cast<double>(opt_.max_terms)) {
          red.resource_limit = true;
          continue;
        }
        ex num;
        try {
          num = GiNaC::numer(GiNaC::normal(e)).expand();
        } catch (const std::exception&) {
          red.resource_limit = true;
          continue;
        }
        if (num.is_zero()) {
          ++red.vanished;
          continue;
        }
        const Candidate* pick = nullptr;
        std::vector<Candidate> cands = candidates(num, atoms_(eqs[idx].hint), t, preferred, only_preferred);
        for (const auto& c : cands) {
          if (banned.count({idx, c.key}) || !nonzero_coefficient(c.coef)) continue;
          pick = &c;
          break;
        }
        if (!pick) {
          red.leftover.push_back({num, sources, used});
          retry.push_back(idx);
          continue;
        }
        for (auto& el : red.eliminated) {
          if (!el.value.has(pick->var) && !el.coef.has(pick->var)) continue;
          el.value = el.value.subs(pick->var == pick->value, GiNaC::subs_options::no_pattern);
          el.coef = el.coef.subs(pick->var == pick->value, GiNaC::subs_options::no_pattern);
          merge_sources(el.sources, sources);
        }
        red.eliminated.push_back({pick->var, pick->value, pick->coef, pick->coef, pick->is_function, idx, pick->key,
                                  sources});
        t = t.subs(pick->var == pick->value, GiNaC::subs_options::no_pattern);
      }
      pending = std::move(retry);
      if (red.eliminated.size() == before) break;
    }
    return red;
  }

  ex reduced(const ex& e, const Reduction& red) {
    ex r = atoms_(e);
    for (const auto& el : red.eliminated) r = r.subs(el.var == el.value, GiNaC::subs_options::no_pattern);
    return atoms_.restore(r);
  }

  std::string eliminated_text(const Reduction& red) const {
    std::string out;
    for (const auto& el : red.eliminated) out += (out.empty() ? "" : ", ") + text(atoms_.restore(el.var));
    return out;
  }

  // "reference 'a1'" / "references 'a1' and 'a2'" / "references 'e1', 'e2' and 'e3'", in the
  // order the rule lists them.
  static std::vector<std::string> source_labels(const std::vector<int>& sources, const std::vector<Eq>& eqs) {
    std::vector<int> idx = sources;
    std::sort(idx.begin(), idx.end());
    std::vector<std::string> out;
    auto add = [&](const std::string& l) {
      if (std::find(out.begin(), out.end(), l) == out.end()) out.push_back(l);
    };
    for (int i : idx) {
      add(eqs[i].from);
      for (const auto& l : eqs[i].also) add(l);
    }
    return out;
  }
  static std::string quoted_list(const std::vector<std::string>& labels) {
    std::string out;
    for (std::size_t i = 0; i < labels.size(); ++i)
      out += (i == 0 ? "" : i + 1 == labels.size() ? " and " : ", ") + ("'" + labels[i] + "'");
    return out;
  }
  static std::string reference_names(const std::vector<int>& sources, const std::vector<Eq>& eqs) {
    std::vector<std::string> labels = source_labels(sources, eqs);
    return (labels.size() == 1 ? "reference " : "references ") + quoted_list(labels);
  }

  // The rule argument that names a label (for error positions); the rule itself otherwise.
  std::pair<SourcePos, int> argument_position(const std::string& label) const {
    for (const auto* group : {&rule().refs, &rule().into, &rule().with})
      for (const auto& a : *group)
        if (a.label == label) return {a.pos, a.length};
    return {rule().pos, 2};
  }

  // References whose equations reduce to a nonzero constant (a = 1 and a = 2 leave -1 = 0) have
  // no common solution, and anything would follow from them: an input error naming them, never
  // a premise of a proof. (Only for equations of references, never for a claim substituted
  // back, which is simply refuted.)
  void reject_contradictions(const Reduction& red, const std::vector<Eq>& eqs) {
    for (const auto& l : red.leftover) {
      ex e = atoms_.restore(l.e);
      if (!free_of_unknowns(e)) continue;
      bool contradiction = GiNaC::is_a<GiNaC::numeric>(e)
                               ? !e.is_zero()
                               : prove_zero(e, d_.symbols, opt_).kind == VerdictKind::Refuted;
      if (!contradiction) continue;
      std::vector<std::string> labels = source_labels(l.sources, eqs);
      std::string msg = labels.size() == 1
                            ? "the reference '" + labels[0] + "' contradicts itself: it leaves " + text(e) + " = 0"
                            : "the references " + quoted_list(labels) + " contradict each other: together they leave " +
                                  text(e) + " = 0";
      if (!l.used.empty()) {
        std::string names;
        for (const auto& u : l.used) names += (names.empty() ? "" : ", ") + text(atoms_.restore(u));
        msg += " (after eliminating " + names + ")";
      }
      auto [pos, len] = argument_position(labels.back());
      throw StepError{positioned(d_, pos, msg, len), true};
    }
  }

  // The counterexample of a Verdict as exact values of the declared symbols (false when a name
  // or value cannot be read back).
  bool point_values(const Verdict& v, GiNaC::exmap& out) const {
    for (const auto& [name, value] : v.point) {
      const SymbolInfo* info = d_.symbols.find(name);
      if (!info || info->is_function) return false;
      try {
        GiNaC::parser reader;
        ex x = reader(value);
        if (!free_of_unknowns(x)) return false;
        out[info->sym] = x;
      } catch (const std::exception&) {
        return false;
      }
    }
    return true;
  }

  // Is `value` (the symbol's value at the counterexample) inside the declared domain of the
  // symbol `s`? "" when it is, otherwise why not (`formula`: the value before the point was
  // substituted, for the message).
  std::string domain_gap(const ex& s, const ex& value, const ex& formula) const {
    const SymbolInfo* info = d_.symbols.find(GiNaC::ex_to<GiNaC::symbol>(s));
    if (!info) return "";
    const Domain& dom = info->domain;
    if (!free_of_unknowns(value)) {
      if (dom.kind == Domain::Kind::Real) return "";   // any real value of what remains will do
      return "need not keep " + info->name + " " + dom.to_string() + " (" + info->name + " = " + text(formula) + ")";
    }
    detail::RealValue rv = detail::eval_real(value, 60);
    if (!rv.ok) return "gives " + info->name + " = " + text(value) + ", which is " + rv.why;
    bool inside = dom.contains(rv.value);
    if (!rv.exact) {
      // an approximation: inside only when it is clearly away from the bounds
      GiNaC::numeric tiny = GiNaC::numeric(1, 10).power(40);
      inside = inside && dom.contains(rv.value * (1 + tiny)) && dom.contains(rv.value * (1 - tiny));
    }
    if (inside) return "";
    return "gives " + info->name + " = " + text(value) + ", outside its domain (" + dom.to_string() + ")";
  }

  // Why a point is not (shown to be) a counterexample; `elimination` is the elimination at fault
  // when another choice of eliminated atom may avoid the problem.
  struct Gap {
    std::string why;                     // "" when the point satisfies the references
    const Elimination* elimination = nullptr;
  };

  // A refutation found on the reduced sides is a counterexample to the step only when the point,
  // extended by the eliminated quantities computed from it, satisfies the references: every
  // leftover equation holds there (or is an identity), no coefficient that was divided by
  // vanishes there, an eliminated application such as sin(theta) equals the value the references
  // give it, and eliminated symbols stay inside their declared domains and the assumptions.
  // Quantities that neither the point nor the eliminations fix (m1 in m2 = m1 when the claim
  // only involves v1, v2) do not affect the claim: any admissible value will do, so a few are
  // drawn from their domains until one satisfies everything.
  // Returns an empty gap when a full point is found, otherwise the first gap.
  Gap counterexample_gap(const Reduction& red, const std::vector<Eq>& eqs, const Verdict& v) {
    GiNaC::exmap P;
    if (!point_values(v, P)) return {"the counterexample cannot be checked against the references"};
    std::vector<const Leftover*> constraining;   // leftovers that are not identities
    std::vector<ex> involved;                    // what the checks evaluate
    for (const auto& l : red.leftover) {
      ex L = atoms_.restore(l.e);
      if (prove_zero(L, d_.symbols, opt_).holds()) continue;   // an identity constrains nothing
      constraining.push_back(&l);
      involved.push_back(L);
    }
    for (const auto& el : red.eliminated) {
      involved.push_back(atoms_.restore(el.value));
      involved.push_back(atoms_.restore(el.coef));
      if (el.function_atom) involved.push_back(atoms_.restore(el.var));
    }
    std::vector<ex> free;   // symbols left open by the point and the eliminations
    for (const auto& e : involved) collect_symbols(e, free);
    free.erase(std::remove_if(free.begin(), free.end(),
                              [&](const ex& s) {
                                if (P.count(s)) return true;
                                for (const auto& el : red.eliminated)
                                  if (atoms_.restore(el.var).is_equal(s)) return true;
                                return false;
                              }),
               free.end());
    std::sort(free.begin(), free.end(), [&](const ex& x, const ex& y) { return text(x) < text(y); });
    Gap first;
    const int draws = free.empty() ? 1 : 8;
    for (int k = 0; k < draws; ++k) {
      GiNaC::exmap Q = P;
      detail::Rng rng(opt_.seed + 0x51ED270B7u * static_cast<std::uint64_t>(k + 1));
      for (const auto& s : free) Q[s] = detail::sample_value(detail::domain_of(s, d_.symbols), rng, false);
      Gap g = gap_at(red, eqs, constraining, Q, free);
      if (g.why.empty()) return g;
      if (k == 0) first = g;
    }
    return first;
  }

  // The checks of counterexample_gap at one full point Q (the counterexample plus values for the
  // free quantities `completed`).
  Gap gap_at(const Reduction& red, const std::vector<Eq>& eqs, const std::vector<const Leftover*>& constraining,
             GiNaC::exmap Q, const std::vector<ex>& completed) {
    try {
      for (const Leftover* l : constraining) {
        ex L = atoms_.restore(l->e);
        ex at = L.subs(Q, GiNaC::subs_options::no_pattern);
        if (!free_of_unknowns(at))
          return {"the counterexample need not satisfy " + reference_names(l->sources, eqs) + " (" + text(L) +
                  " = 0, which determines nothing linearly, is not fixed by the point)"};
        if (!prove_zero(at, d_.symbols, opt_).holds())
          return {"the counterexample does not satisfy " + reference_names(l->sources, eqs) + " (" + text(L) + " = 0)"};
      }
      const GiNaC::exmap open = Q;   // the values the eliminated quantities are computed from
      std::vector<ex> assigned = completed;
      for (const auto& el : red.eliminated) {
        ex var = atoms_.restore(el.var);
        ex value = atoms_.restore(el.value).subs(open, GiNaC::subs_options::no_pattern);
        ex coef = atoms_.restore(el.coef).subs(open, GiNaC::subs_options::no_pattern);
        bool coef_ok = free_of_unknowns(coef) ? (GiNaC::is_a<GiNaC::numeric>(coef)
                                                     ? !coef.is_zero()
                                                     : prove_zero(coef, d_.symbols, opt_).kind == VerdictKind::Refuted)
                                              : nonzero_coefficient(atoms_(coef));
        if (!coef_ok)
          return {"the counterexample need not satisfy " + reference_names(el.sources, eqs) + " (" + text(var) +
                      " was obtained by dividing by " + text(atoms_.restore(el.coef)) + ", which vanishes there)",
                  &el};
        if (GiNaC::is_a<GiNaC::symbol>(var) && d_.symbols.find(GiNaC::ex_to<GiNaC::symbol>(var))) {
          std::string gap = domain_gap(var, value, atoms_.restore(el.value));
          if (!gap.empty()) return {"the counterexample " + gap + " by " + reference_names(el.sources, eqs), &el};
          Q[var] = value;
          assigned.push_back(var);
        } else if (el.function_atom) {
          ex at = var.subs(open, GiNaC::subs_options::no_pattern);
          if (!free_of_unknowns(at) || !free_of_unknowns(value) || !prove_equal(at, value, d_.symbols, opt_).holds())
            return {"the counterexample need not satisfy " + reference_names(el.sources, eqs) + " (it gives " +
                        text(var) + " = " + text(atoms_.restore(el.value)) + ")",
                    &el};
        }
      }
      for (const auto& c : d_.symbols.constraints()) {
        bool touched = false;
        for (const auto& s : assigned) touched = touched || c.lhs.has(s) || c.rhs.has(s);
        if (touched && !c.holds_at(Q))
          return {"the counterexample need not satisfy the assumption " + c.text +
                  " once the quantities the references determine are computed from it"};
      }
    } catch (const std::exception&) {
      return {"the references are undefined at the counterexample"};
    }
    return {};
  }

  // Does e contain an application y(s) (or a derivative of one) of a declared function at s? An
  // equation with one holds for every value of s (y(t) = F0*t), so it may be used at other
  // values of s. An equation between plain symbols (y = F0*t with y a symbol) is one value:
  // instantiating it at two points would give y = F0*t1 and y = 0, from which anything follows.
  static bool has_application_at(const ex& e, const ex& s) {
    if (pool_function_index(e) >= 0 && e.nops() >= 1 && e.op(0).is_equal(s)) return true;
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (has_application_at(e.op(i), s)) return true;
    return false;
  }

  static void application_args(const ex& e, std::vector<ex>& out) {
    if (pool_function_index(e) >= 0 && e.nops() >= 1) {
      for (const auto& o : out)
        if (o.is_equal(e.op(0))) return;
      out.push_back(e.op(0));
      return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i) application_args(e.op(i), out);
  }

  // An equation between function applications of one parameter s (p(t) = m*v(t)) holds for
  // every value of s: add its instances at the other arguments the claim uses (t1, t2). An
  // equation without applications is between plain symbols, each one value: it is used as is.
  std::vector<Eq> instantiate(const std::vector<Eq>& eqs, const ex& claim) const {
    std::vector<ex> want;
    application_args(claim, want);
    std::sort(want.begin(), want.end(), [&](const ex& x, const ex& y) { return text(x) < text(y); });
    std::vector<Eq> out = eqs;
    if (want.empty()) return out;
    bool claim_has_derivative = false;
    {
      std::function<void(const ex&)> walk = [&](const ex& e) {
        if (GiNaC::is_a<GiNaC::fderivative>(e)) claim_has_derivative = true;
        for (std::size_t i = 0; i < e.nops(); ++i) walk(e.op(i));
      };
      walk(claim);
    }
    for (const auto& q : eqs) {
      std::vector<ex> args;
      application_args(q.e, args);
      if (args.size() != 1 || !GiNaC::is_a<GiNaC::symbol>(args[0])) continue;
      const GiNaC::symbol& s = GiNaC::ex_to<GiNaC::symbol>(args[0]);
      // it holds for every s, so its derivative in s holds too (p(t) = m v(t) gives p' = m v')
      std::vector<ex> forms{q.e};
      if (claim_has_derivative) {
        ex d = q.e.diff(s);
        if (!d.is_zero()) forms.push_back(d);
      }
      for (std::size_t k = 0; k < forms.size(); ++k) {
        if (k > 0) out.push_back({forms[k], ex(), q.from});
        for (const auto& w : want)
          if (!w.is_equal(args[0]))
            out.push_back({forms[k].subs(args[0] == w, GiNaC::subs_options::no_pattern), ex(), q.from});
      }
    }
    return out;
  }

  // Does a = b follow from the equations? The equations are reduced (contradictory ones are an
  // input error), both sides are reduced with the eliminations, and prove_equal decides; a
  // refutation stands only when its point satisfies the references (counterexample_gap). When
  // the point fails because of one elimination (it puts F0 = y/t outside F0's domain, or gives
  // sin(theta) a value theta does not have), the reduction is redone without that choice: any
  // valid reduction proves, and any certified point refutes.
  Verdict follows(const ex& a, const ex& b, const std::vector<Eq>& eqs0, const std::vector<ex>& preferred = {}) {
    if (eqs0.empty()) return prove_equal(a, b, d_.symbols, opt_);
    std::vector<Eq> eqs = instantiate(eqs0, a - b);
    Bans bans;
    Reduction red;
    Verdict v;
    for (int attempt = 0;; ++attempt) {
      red = reduce(eqs, a - b, preferred, false, bans);
      reject_contradictions(red, eqs);
      ex ra = reduced(a, red), rb = reduced(b, red);
      v = prove_equal(ra, rb, d_.symbols, opt_);
      if (v.kind != VerdictKind::Refuted) break;
      Gap gap = counterexample_gap(red, eqs, v);
      if (gap.why.empty()) break;
      if (gap.elimination && attempt < 3 && bans.insert({gap.elimination->equation, gap.elimination->key}).second)
        continue;
      std::string after = red.eliminated.empty() ? "" : " after eliminating " + eliminated_text(red);
      Verdict u = undecided(v.method, "the difference does not vanish" + after + ", but " + gap.why);
      u.residual = text(ra - rb);
      v = u;
      break;
    }
    if (red.degenerate && v.holds())
      v = undecided(v.method, "every order of elimination divides by a coefficient that vanishes identically");
    if (red.resource_limit && !v.holds()) {
      v = undecided(v.method, "resource limit: an equation would expand beyond " + std::to_string(opt_.max_terms) + " terms");
    }
    if (!red.eliminated.empty()) {
      std::string el = "eliminating " + eliminated_text(red) + " with the references";
      v.detail = v.detail.empty() ? el : v.detail + "; " + el;
    }
    return v;
  }

  // --- the rules ----------------------------------------------------------------------
  Verdict rewrite(const Relation& claim);
  Verdict substitute(const Relation& claim);
  Verdict solve(const Relation& claim);
  Verdict limit_or_series(const Relation& claim, bool is_limit);
  Verdict first_order_rule(const Relation& claim);
  Verdict differentiate(const Relation& claim);
  Verdict integrate(const Relation& claim);
  Verdict solves_ode(const Relation& claim);

  Verdict links_follow(const std::vector<ex>& sd, const std::vector<Eq>& eqs, const std::string& rule_method,
                       const std::vector<ex>& preferred = {}) {
    Combiner c;
    for (std::size_t i = 0; i + 1 < sd.size(); ++i) {
      Verdict v = follows(sd[i], sd[i + 1], eqs, preferred);
      v.method = prefix_method(rule_method, v.method);
      c.add(v, sd.size() > 2 ? "link " + std::to_string(i + 1) + " (" + text(sd[i]) + " = " + text(sd[i + 1]) + ")" : "");
    }
    return c.result();
  }

  // Does the linear system `nums` (linear in the unknowns) determine them? Only when some
  // square choice of its equations has a coefficient determinant that is not identically zero:
  // lsolve divides by pivots without knowing that log(a*b) - log(a) - log(b) is zero.
  bool determines(const std::vector<ex>& nums, const std::vector<ex>& unknowns) {
    const std::size_t n = unknowns.size(), m = nums.size();
    if (n == 0 || m < n) return false;
    std::vector<bool> pick(m, false);   // the chosen equations; combinations in lexicographic order
    std::fill(pick.begin(), pick.begin() + static_cast<long>(n), true);
    int tries = 0;
    do {
      GiNaC::matrix A(static_cast<unsigned>(n), static_cast<unsigned>(n));
      unsigned r = 0;
      for (std::size_t i = 0; i < m; ++i) {
        if (!pick[i]) continue;
        for (std::size_t j = 0; j < n; ++j) A(r, static_cast<unsigned>(j)) = nums[i].coeff(unknowns[j], 1);
        ++r;
      }
      try {
        if (nonzero_coefficient(A.determinant())) return true;
      } catch (const std::exception&) {
        // an unusable determinant: try the next choice
      }
    } while (++tries < 64 && std::prev_permutation(pick.begin(), pick.end()));
    return false;
  }

  ex symbol_of(const RuleArg& a) const {
    ex v = conv(a.value);
    if (!GiNaC::is_a<GiNaC::symbol>(v)) fail(a.pos, "expected a symbol", a.length);
    return v;
  }
};

Verdict Checker::rewrite(const Relation& claim) {
  std::vector<ex> sd = sides(claim);
  std::vector<std::string> labels;
  auto subs = substitutions(rule().with, nullptr, &labels);
  for (auto& e : sd) e = apply(e, subs);
  if (sd.size() < 2) {
    // An expression step: nothing to compare; its side conditions are still checked.
    return proved("expression", "an expression (no equation to check)");
  }
  std::vector<Eq> eqs = all_equations(rule().refs);
  for (auto& q : eqs) apply_to(q, subs, labels);
  return links_follow(sd, eqs, rule().refs.empty() ? "identity" : "rewrite");
}

// `substitute S... into C`: the claim must follow from C with the substitutions applied and
// from the substitutions themselves taken as equations. (The claim may still mention a
// substituted name, T = 2*pi/omega, or a defined name whose definition brings one in; a
// counterexample must then respect omega = sqrt(k/m) too.)
Verdict Checker::substitute(const Relation& claim) {
  std::vector<Eq> extra;   // references that are not `x = value`: equations only (added below)
  std::vector<std::string> labels;
  auto subs = substitutions(rule().refs, &extra, &labels);
  auto w = substitutions(rule().with, nullptr, &labels);
  subs.insert(subs.end(), w.begin(), w.end());
  const Step& c = ref_step(rule().into[0]);
  const Relation& cr = claim_of(c);
  std::vector<ex> cs = sides(cr);
  std::vector<std::string> applied;   // the substitutions C' rests on
  for (auto& e : cs) {
    std::vector<bool> used;
    e = apply(e, subs, &used);
    for (std::size_t i = 0; i < used.size(); ++i)
      if (used[i] && std::find(applied.begin(), applied.end(), labels[i]) == applied.end()) applied.push_back(labels[i]);
  }
  std::vector<Eq> eqs;
  for (std::size_t i = 0; i + 1 < cs.size(); ++i) {
    Eq q{cs[i] - cs[i + 1], ex(), c.label, applied};
    if (i == 0 && (GiNaC::is_a<GiNaC::symbol>(cs[0]) || pool_function_index(cs[0]) >= 0)) q.hint = cs[0];
    eqs.push_back(q);
  }
  for (const auto* group : {&rule().refs, &rule().with})
    for (const auto& a : *group) {
      auto e = equations(a);
      eqs.insert(eqs.end(), e.begin(), e.end());
    }
  if (cs.size() >= 2) res_.derived = text(cs.front()) + " = " + text(cs.back());
  else if (!cs.empty()) res_.derived = text(cs.front());
  std::vector<ex> sd = sides(claim);
  if (cs.size() < 2) {
    // substituting into an expression: the claim must be that expression
    if (sd.size() != 1) fail(rule().into[0].pos, "'" + c.label + "' is an expression; the claim must be one too");
    Verdict v = follows(sd[0], cs[0], eqs);
    v.method = prefix_method("substitute", v.method);
    return v;
  }
  if (sd.size() < 2) fail(s_.claim_pos, "expected an equation as the claim of 'by substitute'");
  return links_follow(sd, eqs, "substitute");
}

Verdict Checker::solve(const Relation& claim) {
  std::vector<Eq> eqs = all_equations(rule().refs);
  std::vector<ex> sd = sides(claim);
  if (sd.size() < 2) fail(s_.claim_pos, "the claim of 'by solve' must be an equation 'x = expression'");
  // Unknowns: symbols, or expressions (sin(theta)) replaced by stand-in symbols.
  std::vector<ex> unknowns;
  GiNaC::exmap standin, standback;
  int k = 0;
  for (const auto& u : rule().unknowns) {
    ex e = atoms_(conv(u.value));
    if (!GiNaC::is_a<GiNaC::symbol>(e)) {
      GiNaC::realsymbol s("dc_unknown" + std::to_string(k++));
      standin[e] = s;
      standback[s] = e;
      e = s;
    }
    unknowns.push_back(e);
  }
  auto in = [&](const ex& e) { return atoms_(e).subs(standin, GiNaC::subs_options::no_pattern); };
  auto out = [&](const ex& e) { return atoms_.restore(e.subs(standback, GiNaC::subs_options::no_pattern)); };
  std::vector<ex> E;
  for (auto& q : eqs) E.push_back(in(q.e));
  for (std::size_t i = 0; i < unknowns.size(); ++i) {
    bool appears = false;
    for (const auto& e : E) appears = appears || e.has(unknowns[i]);
    if (!appears)
      fail(rule().unknowns[i].pos, "the unknown '" + rule().unknowns[i].label + "' does not appear in the equations",
           rule().unknowns[i].length);
  }
  // Linear in the unknowns?
  bool linear = E.size() >= unknowns.size();
  std::vector<ex> nums;
  for (const auto& e : E) {
    ex num;
    try {
      num = GiNaC::numer(GiNaC::normal(e)).expand();
    } catch (const std::exception&) {
      linear = false;
      break;
    }
    nums.push_back(num);
    for (const auto& u : unknowns) {
      ex c = num.coeff(u, 1);
      ex rest = (num - c * u).expand();
      if (rest.has(u) || has_any(c, unknowns)) linear = false;
    }
  }
  if (linear && !determines(nums, unknowns)) {
    std::string names;
    for (const auto& u : unknowns) names += (names.empty() ? "" : ", ") + text(out(u));
    return undecided("lsolve", "the equations do not determine " + names +
                                   ": the determinant of their coefficients vanishes identically");
  }
  if (linear) {
    GiNaC::lst eqlist, varlist;
    for (const auto& n : nums) eqlist.append(n == 0);
    for (const auto& u : unknowns) varlist.append(u);
    ex sol;
    bool ok = true;
    try {
      sol = GiNaC::lsolve(eqlist, varlist);
    } catch (const std::exception&) {
      ok = false;
    }
    if (ok && GiNaC::is_a<GiNaC::lst>(sol) && sol.nops() == unknowns.size()) {
      GiNaC::exmap solmap;
      std::string derived;
      bool determined = true;
      for (std::size_t i = 0; i < sol.nops(); ++i) {
        ex var = sol.op(i).lhs(), val = sol.op(i).rhs();
        if (has_any(val, unknowns)) determined = false;
        solmap[var] = val;
      }
      if (determined) {
        for (std::size_t i = 0; i < unknowns.size(); ++i) {
          ex val = out(solmap[unknowns[i]]);
          derived += (derived.empty() ? "" : "; ") + text(out(unknowns[i])) + " = " + text(val);
          for (auto& sc : side_conditions(val, d_.symbols)) res_.verdict.side_conditions.push_back(sc);
        }
        res_.derived = derived;
        Combiner c;
        for (std::size_t i = 0; i + 1 < sd.size(); ++i) {
          ex a = out(in(sd[i]).subs(solmap)), b = out(in(sd[i + 1]).subs(solmap));
          Verdict v = prove_equal(a, b, d_.symbols, opt_);
          v.method = prefix_method("lsolve", v.method);
          c.add(v, sd.size() > 2 ? "link " + std::to_string(i + 1) : "");
        }
        return c.result();
      }
    }
  }
  // Nonlinear (or not uniquely solvable): substitute the claim back. The claim must be
  // `u = G` for an unknown u; each equation, with u = G and the other unknowns eliminated,
  // must reduce to an identity.
  ex lhs = in(sd[0]);
  int which = -1;
  for (std::size_t i = 0; i < unknowns.size(); ++i)
    if (lhs.is_equal(unknowns[i])) which = static_cast<int>(i);
  if (which < 0) {
    Verdict v = links_follow(sd, eqs, "solve (elimination)", [&] {
      std::vector<ex> p;
      for (auto& u : unknowns) p.push_back(out(u));
      return p;
    }());
    return v;
  }
  Combiner c;
  std::vector<ex> others;
  for (std::size_t i = 0; i < unknowns.size(); ++i)
    if (static_cast<int>(i) != which) others.push_back(unknowns[i]);
  for (std::size_t k2 = 1; k2 < sd.size(); ++k2) {
    ex G = in(sd[k2]);
    if (G.has(unknowns[which])) fail(s_.claim_pos, "the claimed solution for '" + text(out(lhs)) + "' contains it");
    std::vector<Eq> back;
    for (const auto& e : E) back.push_back({e.subs(unknowns[which] == G), ex(), ""});
    // Quantities of the equations that the claim does not mention (v1, dh in the ballistic
    // pendulum) are intermediate: they are eliminated together with the other unknowns.
    // A quantity counts as intermediate when it links at least two of the equations (a
    // parameter such as g in a single equation is not eliminated: that would use the equation
    // up instead of checking it).
    std::vector<ex> elim = others, in_eqs;
    for (const auto& q : back) collect_symbols(q.e, in_eqs);
    for (const auto& sym : in_eqs) {
      int count = 0;
      for (const auto& q : back) count += q.e.has(sym) ? 1 : 0;
      if (count >= 2 && !G.has(sym) && !has_any(sym, elim)) elim.push_back(sym);
    }
    Reduction red = reduce(back, ex(0), elim, true);
    int checked = 0;
    for (const auto& left : red.leftover) {
      Verdict v = prove_zero(atoms_.restore(out(left.e)), d_.symbols, opt_);
      v.method = prefix_method("claim substituted back", v.method);
      c.add(v, "equation with " + text(out(lhs)) + " = " + text(out(G)));
      ++checked;
    }
    if (red.resource_limit) c.add(undecided("claim substituted back", "resource limit"), "");
    if (red.degenerate)
      c.add(undecided("claim substituted back",
                      "every order of elimination divides by a coefficient that vanishes identically"),
            "");
    if (checked == 0 && !red.resource_limit) {
      // Every equation was used to eliminate another unknown, or reduced to 0: the claim
      // satisfies all of them identically.
      if (red.vanished == 0)
        c.add(undecided("claim substituted back", "the equations do not determine " + text(out(lhs)) +
                                                      " (they are used up by the other unknowns)"),
              "");
      else
        c.add(proved("claim substituted back (normal)"), "");
    }
    // The declared domain of the unknown picks the root: v0 : negative for v0 = -sqrt(...).
    std::string root_note = " (other roots are not excluded)";
    if (GiNaC::is_a<GiNaC::symbol>(out(lhs))) {
      const SymbolInfo* info = d_.symbols.find(GiNaC::ex_to<GiNaC::symbol>(out(lhs)));
      if (info && info->domain.kind != Domain::Kind::Real && info->domain.kind != Domain::Kind::Interval) {
        bool neg = info->domain.kind == Domain::Kind::Negative;
        ex g = out(G);
        Verdict v = prove_equal(GiNaC::sqrt(GiNaC::pow(g, 2)), neg ? -g : g, d_.symbols, opt_);
        v.method = prefix_method("root in the declared domain", v.method);
        c.add(v, "the claimed root must be " + info->domain.to_string() + " like " + info->name, true);
        root_note = " (the root is the one in the declared domain: " + info->name + " " + info->domain.to_string() + ")";
      }
    }
    res_.derived = "nonlinear in the unknowns: the claim " + text(out(lhs)) + " = " + text(out(G)) +
                   " was substituted into the equations" + root_note;
  }
  return c.result();
}

namespace {
bool is_infinity(const Node& n, int& sign) {
  if (n.kind == NodeKind::Symbol && n.text == "oo") { sign = 1; return true; }
  if (n.kind == NodeKind::Neg && n.args[0].kind == NodeKind::Symbol && n.args[0].text == "oo") { sign = -1; return true; }
  if (n.kind == NodeKind::Sub || n.kind == NodeKind::Add) return false;
  return false;
}
}  // namespace

Verdict Checker::limit_or_series(const Relation& claim, bool is_limit) {
  const std::string rname = is_limit ? "limit" : "series";
  const Step& A = ref_step(rule().into[0]);
  const Relation& ar = claim_of(A);
  auto subs = substitutions(rule().with, nullptr);
  std::vector<ex> as = sides(ar);
  for (auto& e : as) e = apply(e, subs);
  ex f = as.back();
  bool has_lhs = as.size() >= 2;
  ex x = symbol_of(*rule().var);
  int inf = 0;
  ex point;
  if (!is_infinity(rule().point->value, inf)) point = conv(rule().point->value);
  if (!is_limit && inf != 0) fail(rule().point->pos, "a first-order series needs a finite point", rule().point->length);
  ex value;
  std::string how;
  int value_inf = 0;
  if (is_limit) {
    LimitResult L = compute_limit(f, GiNaC::ex_to<GiNaC::symbol>(x), inf ? ex(0) : point, inf, d_.symbols);
    if (!L.ok) return undecided("limit", L.reason.empty() ? "the limit helper could not decide" : L.reason);
    value = L.value;
    value_inf = L.infinite;
    how = "limit (" + L.method + (L.confirmed_numerically ? ", confirmed numerically" : "") + ")";
    res_.derived = value_inf ? (value_inf > 0 ? "oo" : "-oo") : text(value);
  } else {
    std::string why;
    auto s = series_first_order(f, GiNaC::ex_to<GiNaC::symbol>(x), point, &why, &d_.symbols);
    if (!s) return undecided("series", why.empty() ? "series expansion failed" : why);
    value = *s;
    how = "series (first order)";
    res_.derived = text(value);
  }
  Combiner c;
  for (std::size_t i = 0; i < claim.sides.size(); ++i) {
    Node n = resolve_definitions(d_, claim.sides[i]);
    std::string what = claim.sides.size() > 1 ? "side " + std::to_string(i + 1) : "";
    if (is_limit && n.kind == NodeKind::Call && n.text == "limit" && n.args.size() == 3) {
      // limit(g, x, p) written in the claim: g must be the referenced f, x and p the rule's.
      ex gx = to_ginac(n.args[1], d_.symbols);
      int ginf = 0;
      bool same_point;
      if (is_infinity(n.args[2], ginf) || inf) same_point = ginf == inf;
      else same_point = prove_equal(to_ginac(n.args[2], d_.symbols), point, d_.symbols, opt_).holds();
      if (!gx.is_equal(x) || !same_point)
        fail(n.pos, "this limit is not the one of the rule ('" + rule().text + "')", n.length);
      ex g = apply(to_ginac(n.args[0], d_.symbols), subs);
      Verdict v = prove_equal(g, f, d_.symbols, opt_);
      v.method = prefix_method("limit argument", v.method);
      c.add(v, what, true);
      continue;
    }
    if (i == 0 && has_lhs) {
      Verdict v = prove_equal(conv(claim.sides[0]), as[0], d_.symbols, opt_);
      v.method = prefix_method(rname + " (left-hand side)", v.method);
      c.add(v, what, true);
      continue;
    }
    int sinf = 0;
    if (is_infinity(n, sinf) || value_inf) {
      if (sinf == value_inf) c.add(proved(how), what);
      else {
        Verdict v;
        v.kind = VerdictKind::Refuted;
        v.method = how;
        v.detail = "the limit is " + (value_inf ? std::string(value_inf > 0 ? "oo" : "-oo") : text(value)) +
                   ", the claim says " + to_text(claim.sides[i]);
        v.lhs_value = to_text(claim.sides[i]);
        v.rhs_value = value_inf ? (value_inf > 0 ? "oo" : "-oo") : text(value);
        c.add(v, what);
      }
      continue;
    }
    Verdict v;
    try {
      v = prove_equal(to_ginac(n, d_.symbols), value, d_.symbols, opt_);
    } catch (const UndecidedLimit& e) {
      v = undecided("limit", e.what());
    }
    v.method = prefix_method(how, v.method);
    c.add(v, what);
  }
  return c.result();
}

Verdict Checker::first_order_rule(const Relation& claim) {
  std::vector<GiNaC::symbol> smalls;
  for (const auto& a : rule().smalls) smalls.push_back(GiNaC::ex_to<GiNaC::symbol>(symbol_of(a)));
  const Step& A = ref_step(rule().into[0]);
  std::vector<Eq> eqs;
  std::string derived;
  for (auto& q : equations(rule().into[0])) {
    ex e = first_order(q.e.expand(), smalls);
    derived += (derived.empty() ? "" : "; ") + text(e) + " = 0";
    eqs.push_back({e, ex(), A.label});
  }
  res_.derived = derived;
  std::vector<ex> sd = sides(claim);
  if (sd.size() < 2) fail(s_.claim_pos, "the claim of 'by first_order' must be an equation");
  return links_follow(sd, eqs, "first order");
}

// Only equations that contain a function of t (x(t) = a*t^2/2) hold for every t and may be
// differentiated; an equation between plain symbols (y = F0*t, y a symbol) is one value, and
// differentiating it would "derive" 0 = F0. Such equations are used as they are.
Verdict Checker::differentiate(const Relation& claim) {
  ex t = symbol_of(*rule().var);
  std::vector<Eq> eqs, originals;
  std::string derived;
  for (const auto& a : rule().refs)
    for (auto& q : equations(a)) {
      originals.push_back(q);
      if (has_application_at(q.e, t)) eqs.push_back({q.e.diff(GiNaC::ex_to<GiNaC::symbol>(t)), ex(), q.from});
    }
  if (eqs.empty()) {
    const RuleArg& a = rule().refs[0];
    fail(a.pos, "'" + a.label + "' contains no function of " + text(t) +
                    ": a plain symbol is one value and cannot be differentiated (declare the quantities that vary "
                    "with " + text(t) + " as functions of " + text(t) + ")",
         a.length);
  }
  // the derivative of the first equation, as derived
  {
    const Relation& r = claim_of(ref_step(rule().refs[0]));
    std::vector<ex> as = sides(r);
    if (as.size() >= 2)
      derived = text(as[0].diff(GiNaC::ex_to<GiNaC::symbol>(t))) + " = " +
                text(as[1].diff(GiNaC::ex_to<GiNaC::symbol>(t)));
  }
  res_.derived = derived;
  eqs.insert(eqs.end(), originals.begin(), originals.end());
  std::vector<ex> sd = sides(claim);
  if (sd.size() < 2) fail(s_.claim_pos, "the claim of 'by differentiate' must be an equation");
  return links_follow(sd, eqs, "differentiate");
}

Verdict Checker::integrate(const Relation& claim) {
  ex t = symbol_of(*rule().var);
  const GiNaC::symbol& ts = GiNaC::ex_to<GiNaC::symbol>(t);
  ex T0 = conv(rule().point->value);
  // The references at the bounds: only equations between function applications of t hold for
  // every t (see has_application_at); the others are used as they are.
  auto inst = [&](const std::vector<Eq>& eqs, const std::vector<ex>& at) {
    std::vector<Eq> out = eqs;
    for (const auto& p : at)
      for (const auto& q : eqs)
        if (has_application_at(q.e, t)) out.push_back({q.e.subs(t == p), ex(), q.from});
    return out;
  };
  std::vector<Eq> ref_eqs = all_equations(rule().refs);
  Node side0 = resolve_definitions(d_, claim.sides[0]);
  if (side0.kind == NodeKind::Call && side0.text == "integral") {
    // integral(f, x, a, b) = G: dG/db = f(b) and G = 0 at b = a.
    if (side0.args.size() != 4) fail(side0.pos, "expected integral(f, x, a, b)", side0.length);
    ex f = to_ginac(side0.args[0], d_.symbols);
    ex x = to_ginac(side0.args[1], d_.symbols);
    ex a = to_ginac(side0.args[2], d_.symbols);
    ex b = to_ginac(side0.args[3], d_.symbols);
    if (!GiNaC::is_a<GiNaC::symbol>(b))
      fail(side0.args[3].pos, "the upper limit of the integral must be a symbol (it is differentiated)",
           side0.args[3].length);
    if (!x.is_equal(t)) fail(side0.args[1].pos, "the integration variable must be the rule's 'wrt' variable", side0.args[1].length);
    if (claim.sides.size() < 2) fail(s_.claim_pos, "expected 'integral(f, x, a, b) = G'");
    std::vector<Eq> eqs = inst(ref_eqs, {b, a});
    const GiNaC::symbol& bs = GiNaC::ex_to<GiNaC::symbol>(b);
    Combiner c;
    if (f.has(b)) {
      // The upper limit also appears in the integrand: d/db of the integral is not f(b), so
      // the closed form is checked against a rigorous quadrature at sampled parameter values.
      // A refutation stands only when every reference can be satisfied independently of the
      // point (it constrains a function that neither the integrand nor the claim uses).
      bool refs_independent = true;
      for (const auto& q : ref_eqs)
        refs_independent = refs_independent && detail::has_abstract_application(q.e) &&
                           !detail::has_abstract_application(f);
      for (std::size_t i = 1; i < claim.sides.size(); ++i) {
        ex G = conv(claim.sides[i]);
        refs_independent = refs_independent && !detail::has_abstract_application(G);
        Verdict v = kernel::probe_definite_integral(f, ts, a, b, G, d_.symbols, opt_);
        if (v.kind == VerdictKind::Refuted && !refs_independent)
          v = undecided("rigorous quadrature", "the quadrature differs from the closed form at a point that need not "
                                               "satisfy the references");
        c.add(v, claim.sides.size() > 2 ? "side " + std::to_string(i + 1) : "");
      }
      res_.derived = "the integrand depends on the upper limit " + text(b) + ": checked by rigorous quadrature";
      return c.result();
    }
    for (std::size_t i = 1; i < claim.sides.size(); ++i) {
      ex G = conv(claim.sides[i]);
      Verdict v1 = follows(G.diff(bs), f.subs(x == b), eqs);
      v1.method = prefix_method("d/d" + text(b) + " of the closed form", v1.method);
      c.add(v1, "side " + std::to_string(i + 1) + ", derivative");
      Verdict v2 = follows(G.subs(b == a), 0, eqs);
      v2.method = prefix_method("value at the lower limit", v2.method);
      c.add(v2, "side " + std::to_string(i + 1) + ", at " + text(b) + " = " + text(a));
      if (i == 1) res_.derived = "d/d" + text(b) + " (" + text(G) + ") = " + text(G.diff(bs));
    }
    return c.result();
  }
  // The ODE form: A is diff(Y, t) = f; the claim is Y = G.
  const Relation& ar = claim_of(ref_step(rule().refs[0]));
  Node alhs = resolve_definitions(d_, ar.sides[0]);
  if (ar.sides.size() < 2 || alhs.kind != NodeKind::Call || alhs.text != "diff" || alhs.args.size() < 2 ||
      (alhs.args.size() == 3 && to_text(alhs.args[2]) != "1"))
    fail(rule().refs[0].pos, "'" + rule().refs[0].label + "' must be an ODE 'diff(y(t), t) = f' for 'by integrate'",
         rule().refs[0].length);
  ex Y = to_ginac(alhs.args[0], d_.symbols);
  ex f = conv(ar.sides.back());
  if (claim.sides.size() < 2) fail(s_.claim_pos, "expected the claim 'y(t) = G'");
  ex cl = conv(claim.sides[0]);
  if (!cl.is_equal(Y)) {
    Verdict v = prove_equal(cl, Y, d_.symbols, opt_);
    if (!v.holds())
      fail(claim.sides[0].pos, "the claim must start with '" + to_text(alhs.args[0]) + " = ...' (the function of the ODE)",
           claim.sides[0].length);
  }
  // initial value
  ex y0 = Y.subs(t == T0), y0_value = y0;
  std::vector<std::pair<ex, ex>> at_T0;   // other values at T0, e.g. m_r(0) = m0
  for (const auto& w : rule().with) {
    ex l = conv(w.equation.sides[0]), r = conv(w.equation.sides[1]);
    if (l.is_equal(y0)) y0_value = r;
    else if (GiNaC::is_a<GiNaC::symbol>(l) || GiNaC::is_a<GiNaC::function>(l)) at_T0.push_back({l, r});
    else fail(w.pos, "expected 'y(T0) = value' after 'with' (the initial value of " + text(y0) + " or of another function)",
              w.length);
  }
  std::vector<Eq> extra;
  for (std::size_t i = 1; i < rule().refs.size(); ++i) {
    auto e = equations(rule().refs[i]);
    extra.insert(extra.end(), e.begin(), e.end());
  }
  extra = inst(extra, {T0});
  Combiner c;
  for (std::size_t i = 1; i < claim.sides.size(); ++i) {
    ex G = conv(claim.sides[i]);
    ex fG = f.subs(Y == G);
    Verdict v1 = follows(G.diff(ts), fG, extra);
    v1.method = prefix_method("d/d" + text(t) + " of the closed form", v1.method);
    c.add(v1, "side " + std::to_string(i + 1) + ", derivative");
    Verdict v2 = follows(apply(G.subs(t == T0), at_T0), apply(y0_value, at_T0), extra);
    v2.method = prefix_method("initial value", v2.method);
    c.add(v2, "side " + std::to_string(i + 1) + ", at " + text(t) + " = " + text(T0));
    if (i == 1) res_.derived = "d/d" + text(t) + " (" + text(G) + ") = " + text(G.diff(ts));
  }
  return c.result();
}

Verdict Checker::solves_ode(const Relation& claim) {
  ex t = symbol_of(*rule().var);
  const GiNaC::symbol& ts = GiNaC::ex_to<GiNaC::symbol>(t);
  if (claim.sides.size() < 2) fail(s_.claim_pos, "expected the claim 'y(t) = G'");
  ex Y = conv(claim.sides[0]);
  if (pool_function_index(Y) < 0 || pool_derivative_order(Y) != 0)
    fail(claim.sides[0].pos, "the claim must be 'y(t) = G' with y a declared function", claim.sides[0].length);
  ex G = conv(claim.sides.back());
  GiNaC::exmap m;
  ex dY = Y, dG = G;
  for (int n = 1; n <= 4; ++n) {
    dY = dY.diff(ts);
    dG = dG.diff(ts);
    m[dY] = dG;
  }
  m[Y] = G;
  Combiner c;
  const Relation& ar = claim_of(ref_step(rule().refs[0]));
  std::vector<ex> as = sides(ar);
  if (as.size() < 2) fail(rule().refs[0].pos, "'" + rule().refs[0].label + "' must be an ODE (an equation)", rule().refs[0].length);
  for (std::size_t i = 0; i + 1 < as.size(); ++i) {
    ex a = as[i].subs(m, GiNaC::subs_options::no_pattern), b = as[i + 1].subs(m, GiNaC::subs_options::no_pattern);
    Verdict v = prove_equal(a, b, d_.symbols, opt_);
    v.method = prefix_method("ODE residual", v.method);
    c.add(v, "the ODE");
  }
  for (const auto& w : rule().with) {
    const Node& l = w.equation.sides[0];
    if (l.kind != NodeKind::Call || l.args.size() != 1)
      fail(w.pos, "expected an initial condition 'y(T0) = value' after 'with'", w.length);
    ex at = conv(l.args[0]);
    ex lhs = conv(l);
    if (!lhs.is_equal(Y.subs(t == at)))
      fail(w.pos, "the initial condition must be for the claimed function, e.g. '" + text(Y.subs(t == at)) + " = value'",
           w.length);
    Verdict v = prove_equal(G.subs(t == at), conv(w.equation.sides[1]), d_.symbols, opt_);
    v.method = prefix_method("initial condition", v.method);
    c.add(v, "initial condition " + w.label);
  }
  for (std::size_t i = 1; i + 1 < claim.sides.size(); ++i) {
    Verdict v = prove_equal(conv(claim.sides[i]), G, d_.symbols, opt_);
    c.add(v, "side " + std::to_string(i + 1));
  }
  res_.derived = "residual of the ODE with " + text(Y) + " = " + text(G);
  return c.result();
}

Verdict Checker::run(const Relation& claim) {
  const std::string& r = rule().name;
  if (r == "given") return proved("given", "premise taken from the source");
  if (r == "definition") return proved("definition", "introduces " + to_text(claim.sides[0]));
  if (r == "rewrite") return rewrite(claim);
  if (r == "substitute") return substitute(claim);
  if (r == "solve") return solve(claim);
  if (r == "limit") return limit_or_series(claim, true);
  if (r == "series") return limit_or_series(claim, false);
  if (r == "first_order") return first_order_rule(claim);
  if (r == "differentiate") return differentiate(claim);
  if (r == "integrate") return integrate(claim);
  if (r == "solves_ode") return solves_ode(claim);
  fail(rule().pos, "unknown rule '" + r + "'");
}

// Dimension of every side; a mismatch is an error at the claim with both dimensions.
void check_dimensions(const Derivation& d, const Relation& claim, StepResult& res) {
  std::vector<Dimension> dims;
  std::vector<const Node*> nodes;
  for (const auto& side : claim.sides) {
    // A literal 0 has every dimension (`m_p*v_p - m_c*v_c = 0`).
    const Node* z = &side;
    while (z->kind == NodeKind::Neg) z = &z->args[0];
    if (z->kind == NodeKind::Number && z->text.find_first_not_of("0.") == std::string::npos) continue;
    nodes.push_back(&side);
    try {
      dims.push_back(dimension_of(side, d.symbols));
    } catch (const InputError& e) {
      res.errors.push_back(with_line(d, e));
      return;
    }
  }
  if (dims.empty()) return;
  for (std::size_t i = 1; i < dims.size(); ++i) {
    if (dims[i] != dims[0]) {
      const Node& n = *nodes[i];
      res.errors.push_back(positioned(
          d, n.pos,
          "dimension mismatch: '" + to_text(*nodes[0]) + "' has dimension " + dims[0].to_string() + " but '" +
              to_text(n) + "' has dimension " + dims[i].to_string(),
          n.length));
      return;
    }
  }
  res.dimension = dims[0].to_string();
}

Verdict run_rule(const Derivation& d, const Step& s, const Relation& claim, const ProveOptions& opt,
                 StepResult& res) {
  try {
    Checker c(d, s, opt, res);
    return c.run(claim);
  } catch (const StepError& e) {
    res.errors.push_back(e.error);
    if (e.input) res.input_error = true;
    return undecided(s.rule.name, "the step could not be checked: " + e.error.message());
  } catch (const InputError& e) {
    res.errors.push_back(with_line(d, e));
    return undecided(s.rule.name, "the step could not be checked: " + e.message());
  } catch (const UndecidedLimit& e) {
    return undecided("limit", e.what());
  } catch (const std::exception& e) {
    // GiNaC arithmetic errors (division by zero in a substitution, pole in a series, ...):
    // the rule could not carry out its derivation; never shown with GiNaC internals.
    std::string what = e.what();
    if (what.find("division by zero") != std::string::npos) what = "division by zero while deriving";
    else what = "the symbolic computation failed";
    return undecided(s.rule.name, what);
  }
}

}  // namespace

StepResult check_step(const Derivation& d, const Step& s, const ProveOptions& opt) {
  auto t0 = std::chrono::steady_clock::now();
  StepResult res;
  res.step = &s;
  const Relation& claim = s.erratum ? s.erratum->corrected : s.claim;
  if (s.erratum) {
    // The printed claim: an undefined symbol is reported at its position; a well-formed but
    // wrong printed claim is reported with its refutation.
    if (auto err = erratum_error(d, s)) {
      res.errors.push_back(*err);
      res.erratum_reported = true;
    } else {
      StepResult printed;
      printed.step = &s;
      Verdict pv = run_rule(d, s, s.claim, opt, printed);
      if (pv.kind == VerdictKind::Refuted || !printed.errors.empty()) {
        std::string why = !printed.errors.empty() ? printed.errors[0].message()
                                                  : "refuted" + (pv.detail.empty() ? std::string() : " (" + pv.detail + ")");
        res.errors.push_back(positioned(d, s.claim_pos, "the printed claim is wrong: " + why + "; erratum: " + s.erratum->why,
                                        static_cast<int>(std::max<std::size_t>(1, s.claim_text.size()))));
        res.erratum_reported = true;
      } else {
        res.errors.push_back(positioned(d, s.erratum->pos,
                                        "an erratum is declared but the printed claim is not refuted (" +
                                            std::string(to_string(pv.kind)) + "); remove the erratum or fix the claim",
                                        7));
      }
    }
  }
  check_dimensions(d, claim, res);
  res.verdict = run_rule(d, s, claim, opt, res);
  // Side conditions of the claim's sides.
  try {
    for (const auto& side : claim.sides) {
      Node n = resolve_definitions(d, side);
      std::function<void(const Node&)> walk = [&](const Node& m) {
        if (m.kind == NodeKind::Call && m.text == "integral") {
          for (const auto& a : m.args) walk(a);
          return;
        }
        for (auto& sc : side_conditions_of_tree(m, d.symbols)) {
          bool dup = false;
          for (const auto& o : res.verdict.side_conditions) dup = dup || o.what == sc.what;
          if (!dup) res.verdict.side_conditions.push_back(sc);
        }
      };
      bool has_integral = false;
      std::function<void(const Node&)> find = [&](const Node& m) {
        if (m.kind == NodeKind::Call && m.text == "integral") has_integral = true;
        for (const auto& a : m.args) find(a);
      };
      find(n);
      if (has_integral) {
        for (const auto& a : n.args) walk(a);
        if (n.kind == NodeKind::Call && n.text == "integral") continue;
      } else {
        walk(n);
      }
    }
  } catch (const std::exception&) {
    // conversion problems were reported by the rule already
  }
  // A claim must hold on the whole declared domain (premises only warn).
  if (s.rule.name != "given" && s.rule.name != "definition") require_defined_on_domain(res.verdict);
  // A stable form must equal the form it replaces.
  if (s.stable_of) {
    const Step* other = d.find(*s.stable_of);
    try {
      auto a = claim_sides(d, s);
      auto b = claim_sides(d, *other);
      Verdict v = prove_equal(a.back(), b.back(), d.symbols, opt);
      if (!v.holds())
        res.errors.push_back(positioned(d, s.pos,
                                        "the stable form is not equal to '" + *s.stable_of + "' (" +
                                            std::string(to_string(v.kind)) + (v.detail.empty() ? "" : ": " + v.detail) + ")",
                                        static_cast<int>(s.label.size())));
    } catch (const std::exception& e) {
      res.errors.push_back(positioned(d, s.pos, "the stable form cannot be compared with '" + *s.stable_of + "'",
                                      static_cast<int>(s.label.size())));
    }
  }
  res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

int CheckSummary::exit_code(bool strict) const {
  if (input_errors > 0) return 2;
  if (refuted > 0 || errors > 0) return 1;
  if (undecided > 0) return 3;
  if (strict && errata > 0) return 1;
  return 0;
}

void CheckSummary::add(StepResult r) {
  const Step& s = *r.step;
  std::size_t own_errors = r.errors.size() - (r.erratum_reported ? 1 : 0);
  if (r.erratum_reported) ++errata;
  r.premise = s.rule.name == "given" || s.rule.name == "definition";
  if (r.input_error) ++input_errors;
  if (own_errors > 0) ++errors;
  else if (r.premise && r.verdict.holds()) ++premises;
  else switch (r.verdict.kind) {
      case VerdictKind::Proved: ++proved; break;
      case VerdictKind::HoldsNumerically: ++holds_numerically; break;
      case VerdictKind::Refuted: ++refuted; break;
      case VerdictKind::Undecided: ++undecided; break;
    }
  results.push_back(std::move(r));
}

CheckSummary check_derivation(const Derivation& d, const ProveOptions& opt) {
  CheckSummary sum;
  for (const auto& s : d.steps) sum.add(check_step(d, s, opt));
  return sum;
}

}  // namespace dc
