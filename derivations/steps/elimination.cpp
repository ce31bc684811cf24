// Elimination with the references' equations (elimination.hpp).
#include "derivations/steps/elimination.hpp"

#include <algorithm>
#include <map>

#include "derivations/symbolic/functions.hpp"
#include "derivations/symbolic/inspect.hpp"
#include "derivations/kernel/range.hpp"

namespace dc::rules {

namespace {

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

void merge_sources(std::vector<int>& into, const std::vector<int>& from) {
  into.insert(into.end(), from.begin(), from.end());
  std::sort(into.begin(), into.end());
  into.erase(std::unique(into.begin(), into.end()), into.end());
}

void collect_functions(const ex& e, std::vector<ex>& out) {
  if (GiNaC::is_a<GiNaC::function>(e)) {
    for (const auto& o : out)
      if (o.is_equal(e)) return;
    out.push_back(e);
  }
  for (std::size_t i = 0; i < e.nops(); ++i) collect_functions(e.op(i), out);
}

void collect_symbol_powers(const ex& e, std::vector<ex>& out) {
  if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::symbol>(e.op(0))) {
    for (const auto& o : out)
      if (o.is_equal(e)) return;
    out.push_back(e);
    return;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) collect_symbol_powers(e.op(i), out);
}

// Is `num` linear in `c` (a symbol or a function application)? Then value = -rest/coef.
bool linear_in(const ex& num, const ex& c, ex& coef, ex& value) {
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

// An atom that an equation determines linearly, and how much the rules prefer it.
struct Candidate {
  long score = 0;
  std::string key;   // deterministic text: breaks ties (GiNaC's traversal order varies by process)
  ex var, value, coef;
  bool is_function = false;
  bool factor_of_zero = false;
};

// Does e divide by anything (a negative power)?
bool has_denominator(const ex& e) {
  if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
      GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_negative())
    return true;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_denominator(e.op(i))) return true;
  return false;
}

// num with the product of quantities common to all its terms divided out (u_e*m' + u_e*m_r'
// becomes m' + m_r'): the cancellation an author makes, read before any elimination could
// read the equation as u_e = 0 (a division by u_e, as eliminating with coefficient u_e would be).
// A single term (m*a = 0) is left whole: which factor is zero is the question.
ex without_common_factor(const ex& num) {
  if (!GiNaC::is_a<GiNaC::add>(num)) return num;
  // the factors of one term with their integer exponents (a number contributes none)
  auto factors_of = [](const ex& term) {
    std::map<ex, long, GiNaC::ex_is_less> f;
    auto add = [&](const ex& x) {
      if (GiNaC::is_a<GiNaC::numeric>(x)) return;
      if (GiNaC::is_a<GiNaC::power>(x) && GiNaC::is_a<GiNaC::numeric>(x.op(1)) &&
          GiNaC::ex_to<GiNaC::numeric>(x.op(1)).is_pos_integer())
        f[x.op(0)] += GiNaC::ex_to<GiNaC::numeric>(x.op(1)).to_long();
      else
        f[x] += 1;
    };
    if (GiNaC::is_a<GiNaC::mul>(term))
      for (std::size_t i = 0; i < term.nops(); ++i) add(term.op(i));
    else
      add(term);
    return f;
  };
  // the product of the quantities common to every term, each to its least power
  auto common = factors_of(num.op(0));
  for (std::size_t i = 1; i < num.nops() && !common.empty(); ++i) {
    const auto f = factors_of(num.op(i));
    for (auto it = common.begin(); it != common.end();) {
      auto jt = f.find(it->first);
      if (jt == f.end()) {
        it = common.erase(it);
      } else {
        it->second = std::min(it->second, jt->second);
        ++it;
      }
    }
  }
  if (common.empty()) return num;
  ex g = 1;
  for (const auto& [x, k] : common) g *= GiNaC::pow(x, k);
  try {
    return GiNaC::expand(num / g);
  } catch (const std::exception&) {
    return num;
  }
}

// Does solving num = c*x + r = 0 for x read a product as one of its factors? With r = 0 and c
// not a number it sets x = 0 (u*(a - b) = 0 read as u = 0, m_r*g = 0 as m_r = 0). (A factor
// common to c and r is cancelled before: without_common_factor.)
bool reads_one_factor(const ex& coef, const ex& value) {
  return value.is_zero() && !GiNaC::is_a<GiNaC::numeric>(coef);
}

// Every atom of `num` that it determines linearly, best first (a factor of a product that is
// zero last): the rule's unknowns, symbols
// before applications such as sin(theta), atoms of the claim, the symbol written alone on the
// reference's left, real-domain symbols, numeric coefficients, then declaration order and text.
std::vector<Candidate> candidates(StepContext& c, const ex& num, const ex& hint, const ex& target,
                                  const std::vector<ex>& preferred, bool only_preferred) {
  std::vector<Candidate> out;
  auto consider = [&](const ex& a, bool is_function) {
    bool pref = false;
    for (const auto& p : preferred)
      if (p.is_equal(a) || c.atoms(p).is_equal(a)) pref = true;
    if (only_preferred && !pref) return;
    Candidate k;
    if (!linear_in(num, a, k.coef, k.value)) return;
    long score = 0;
    // a product read as one of its factors comes last: u*(a - b) = 0 is a = b far more often
    // than u = 0, and a factor another row needs nonzero (m_r*g = 0) is a pin from which
    // anything about it follows
    k.factor_of_zero = reads_one_factor(k.coef, k.value);
    if (k.factor_of_zero) score -= 10000;
    if (pref) score += 1000;
    if (!is_function) score += 500;
    if (target.has(a)) score += 100;
    if (hint.is_equal(a)) score += 50;
    if (is_function || c.real_domain(a)) score += 20;
    if (GiNaC::is_a<GiNaC::numeric>(k.coef)) score += 10;
    k.score = score * 100 + std::max(0, c.declaration_index(a)) % 100;
    k.key = c.text(c.atoms.restore(a));
    k.var = a;
    k.is_function = is_function;
    out.push_back(std::move(k));
  };
  for (const auto& s : c.symbols_in({num})) consider(s, false);
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

// The first elimination whose coefficient, with the later eliminations substituted, is
// identically zero (nullptr if none).
const Elimination* vanishing_elimination(StepContext& c, const Reduction& red) {
  for (const auto& el : red.eliminated)
    if (!el.coef.is_equal(el.coef_checked) && !nonzero_coefficient(c, el.coef)) return &el;
  return nullptr;
}

Reduction reduce_once(StepContext& c, const std::vector<Eq>& eqs, const ex& target, const std::vector<ex>& preferred,
                      bool only_preferred, const Bans& banned) {
  Reduction red;
  ex t = c.atoms(target);
  // Work list: an equation with nothing to eliminate is retried after later eliminations
  // (v1 eliminated by a later reference makes dh = v1^2/(2 g) usable).
  std::vector<int> pending(eqs.size());
  for (std::size_t i = 0; i < eqs.size(); ++i) pending[i] = static_cast<int>(i);
  // each equation atomized, with the author's own cancellation made once, before an earlier
  // elimination hides it (u_e*m' = -u_e*m_r' after u_e = m_r*(a + g)/mu is a product of three
  // factors)
  std::vector<ex> own(eqs.size());
  for (std::size_t i = 0; i < eqs.size(); ++i) {
    own[i] = c.atoms(eqs[i].e);
    if (estimate_expanded_terms(own[i]) <= static_cast<double>(c.opt.max_terms)) try {
        // (normal() only where a term has a denominator: it is the costly part)
        const ex e = (has_denominator(own[i]) ? GiNaC::numer(GiNaC::normal(own[i])) : own[i]).expand();
        const ex stripped = without_common_factor(e);
        if (!stripped.is_equal(e)) own[i] = stripped;
      } catch (const std::exception&) {
      }
  }
  // a value as written first (c = 0 beside c*u = 0: c is eliminated with it, not read as the
  // zero factor of c*u)
  std::stable_partition(pending.begin(), pending.end(), [&](int i) {
    const ex e = own[static_cast<std::size_t>(i)].expand();
    const auto atoms = c.symbols_in({e});
    if (atoms.size() != 1) return false;
    const ex k = e.coeff(atoms.front(), 1), r = (e - k * atoms.front()).expand();
    return GiNaC::is_a<GiNaC::numeric>(k) && !k.is_zero() && GiNaC::is_a<GiNaC::numeric>(r);
  });
  for (int pass = 0; pass < 8 && !pending.empty(); ++pass) {
    std::size_t before = red.eliminated.size();
    std::vector<int> retry;
    red.leftover.clear();
    for (int idx : pending) {
      std::vector<int> sources{idx};
      std::vector<ex> used;
      ex e = own[static_cast<std::size_t>(idx)];
      for (const auto& el : red.eliminated) {
        if (!e.has(el.var)) continue;
        e = e.subs(el.var == el.value, GiNaC::subs_options::no_pattern);
        merge_sources(sources, el.sources);
        used.push_back(el.var);
      }
      if (estimate_expanded_terms(e) > static_cast<double>(c.opt.max_terms)) {
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
      num = without_common_factor(num);
      const Candidate* pick = nullptr;
      std::vector<Candidate> cands = candidates(c, num, c.atoms(eqs[idx].hint), t, preferred, only_preferred);
      // The earlier eliminations and the target with the pick put in. A pick that makes one of
      // their denominators vanish identically (x' = .../(m x'' + k x), then m x'' + k x = 0
      // from Newton's law) is skipped for the next candidate, not a failed derivation.
      std::vector<Elimination> updated;
      ex t_updated;
      for (const auto& k : cands) {
        if (banned.count({idx, k.key}) || !nonzero_coefficient(c, k.coef)) continue;
        try {
          updated = red.eliminated;
          for (auto& el : updated) {
            if (!el.value.has(k.var) && !el.coef.has(k.var)) continue;
            el.value = el.value.subs(k.var == k.value, GiNaC::subs_options::no_pattern);
            el.coef = el.coef.subs(k.var == k.value, GiNaC::subs_options::no_pattern);
            merge_sources(el.sources, sources);
          }
          t_updated = t.subs(k.var == k.value, GiNaC::subs_options::no_pattern);
        } catch (const std::exception&) {
          continue;
        }
        pick = &k;
        break;
      }
      if (!pick) {
        red.leftover.push_back({num, sources, used});
        retry.push_back(idx);
        continue;
      }
      red.eliminated = std::move(updated);
      red.eliminated.push_back({pick->var, pick->value, pick->coef, pick->coef, pick->is_function, idx, pick->key,
                                sources, pick->factor_of_zero, pick->coef * (pick->var - pick->value), pick->value});
      t = t_updated;
    }
    pending = std::move(retry);
    if (red.eliminated.size() == before) break;
  }
  return red;
}

}  // namespace

bool nonzero_coefficient(StepContext& c, const ex& coef) {
  if (GiNaC::is_a<GiNaC::numeric>(coef)) return !coef.is_zero();
  auto it = c.nonzero_cache.find(coef);
  if (it != c.nonzero_cache.end()) return it->second;
  bool nonzero;
  ex restored = c.atoms.restore(coef);
  if (detail::provably_nonzero(restored, c.d.symbols)) {
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
    nonzero = prove_zero(restored, c.d.symbols, c.opt).kind == VerdictKind::Refuted;
  }
  c.nonzero_cache.emplace(coef, nonzero);
  return nonzero;
}

Reduction reduce(StepContext& c, const std::vector<Eq>& eqs, const ex& target, const std::vector<ex>& preferred,
                 bool only_preferred, Bans banned) {
  Reduction red;
  for (int attempt = 0; attempt < 8; ++attempt) {
    red = reduce_once(c, eqs, target, preferred, only_preferred, banned);
    const Elimination* bad = vanishing_elimination(c, red);
    if (!bad) return red;
    banned.insert({bad->equation, bad->key});
  }
  red.degenerate = true;
  return red;
}

ex reduced(StepContext& c, const ex& e, const Reduction& red) {
  ex r = c.atoms(e);
  for (const auto& el : red.eliminated) r = r.subs(el.var == el.value, GiNaC::subs_options::no_pattern);
  r = c.atoms.restore(r);
  // gamma^2 eliminated, gamma positive: gamma itself is (gamma^2)^(1/2) wherever it is left
  for (const auto& el : red.eliminated) {
    const ex var = c.atoms.restore(el.var);
    if (!el.function_atom || !GiNaC::is_a<GiNaC::power>(var) || !GiNaC::is_a<GiNaC::symbol>(var.op(0)) ||
        !GiNaC::is_a<GiNaC::numeric>(var.op(1)) || !GiNaC::ex_to<GiNaC::numeric>(var.op(1)).is_pos_integer() ||
        !r.has(var.op(0)))
      continue;
    const SymbolInfo* s = c.d.symbols.find(GiNaC::ex_to<GiNaC::symbol>(var.op(0)));
    const ex value = c.atoms.restore(el.value);
    if (s && s->domain.strictly_positive() && !value.has(var.op(0)))
      r = r.subs(var.op(0) == GiNaC::pow(value, 1 / var.op(1)), GiNaC::subs_options::no_pattern);
  }
  return r;
}

std::string eliminated_text(const StepContext& c, const Reduction& red) {
  std::string out;
  for (const auto& el : red.eliminated) out += (out.empty() ? "" : ", ") + c.text(c.atoms.restore(el.var));
  return out;
}

}  // namespace dc::rules
