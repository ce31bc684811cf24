// Domains, the symbol table and constraints (parse_domain / to_ginac / dimension_of live in
// domain_parse.cpp and to_ginac.cpp).
#include "derivations/symbolic/symbols.hpp"

#include <cctype>
#include <sstream>

#include <cln/real.h>

#include "derivations/symbolic/verdict.hpp"
#include "derivations/syntax/source.hpp"

namespace dc {

namespace {

// Sign of (a - b) for exact constants a, b (rationals, or expressions in pi such as pi/2).
// Rational differences are decided exactly; others by evalf at 60 digits (a rational never
// equals a nonzero multiple of pi, so a tiny but nonzero float is still a strict sign).
// Returns -1, 0, +1, or 2 when the difference is not a real constant.
int compare_constants(const GiNaC::ex& a, const GiNaC::ex& b) {
  GiNaC::ex d = a - b;
  if (GiNaC::is_a<GiNaC::numeric>(d)) {
    const auto& n = GiNaC::ex_to<GiNaC::numeric>(d);
    if (!n.is_real()) return 2;
    return n.is_zero() ? 0 : (n.is_positive() ? 1 : -1);
  }
  GiNaC::ex v;
  {
    DigitsGuard g(60);
    v = d.evalf();
  }
  if (!GiNaC::is_a<GiNaC::numeric>(v)) return 2;
  const auto& n = GiNaC::ex_to<GiNaC::numeric>(v);
  if (!n.is_real()) return 2;
  if (n.is_zero()) return 0;
  return n.is_positive() ? 1 : -1;
}

// Deterministic text of an interval bound: rationals "1/2", "-3", multiples of pi "pi",
// "pi/2", "3*pi/4", "-pi".
std::string bound_text(const GiNaC::ex& b) {
  auto rational_text = [](const GiNaC::numeric& q) {
    std::ostringstream os;
    os << q;
    return os.str();
  };
  if (GiNaC::is_a<GiNaC::numeric>(b)) return rational_text(GiNaC::ex_to<GiNaC::numeric>(b));
  GiNaC::ex q = (b / GiNaC::Pi).normal();
  if (GiNaC::is_a<GiNaC::numeric>(q) && GiNaC::ex_to<GiNaC::numeric>(q).is_rational()) {
    const auto& r = GiNaC::ex_to<GiNaC::numeric>(q);
    GiNaC::numeric num = r.numer(), den = r.denom();
    std::string s;
    if (num.is_negative()) s = "-";
    GiNaC::numeric an = GiNaC::abs(num);
    if (an != 1) s += rational_text(an) + "*";
    s += "pi";
    if (den != 1) s += "/" + rational_text(den);
    return s;
  }
  // Bounds are documented to be rationals or pi multiples; anything else is printed by
  // CLN/GiNaC for a single node, which is order-free for these simple constants.
  std::ostringstream os;
  os << b;
  return os.str();
}

const char* const kGreek[] = {"alpha", "beta",  "gamma", "delta", "epsilon", "zeta",
                              "eta",   "theta", "iota",  "kappa", "lambda",  "mu",
                              "nu",    "xi",    "pi",    "rho",   "sigma",   "tau",
                              "phi",   "chi",   "psi",   "omega", "Gamma",   "Delta",
                              "Theta", "Lambda", "Xi",   "Pi",    "Sigma",   "Phi",
                              "Psi",   "Omega"};

bool is_word(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isalpha(static_cast<unsigned char>(c))) return false;
  return true;
}

std::string default_tex(const std::string& name) {
  for (const char* g : kGreek)
    if (name == g) return std::string("\\") + g;
  // head_sub: omega_n -> \omega_n, theta_max -> \theta_{\mathrm{max}}, v_e -> v_e,
  // k_G -> k_G, x_12 -> x_{12}, v_omega -> v_{\omega}; a word of two or more letters as a
  // subscript is a label, upright (\mathrm). Further underscores separate subscripts: a_b_c -> a_{b,c}.
  if (auto us = name.find('_'); us != std::string::npos && us > 0 && us + 1 < name.size()) {
    std::string head = default_tex(name.substr(0, us));
    std::string sub;
    std::size_t from = us + 1;
    while (from <= name.size()) {
      std::size_t to = name.find('_', from);
      if (to == std::string::npos) to = name.size();
      std::string part = name.substr(from, to - from);
      std::string p;
      bool greek = false;
      for (const char* g : kGreek) greek = greek || part == g;
      if (greek) p = "\\" + part;
      else if (part.size() > 1 && is_word(part)) p = "\\mathrm{" + part + "}";
      else p = part;
      sub += (sub.empty() ? "" : ",") + p;
      from = to + 1;
    }
    if (head.find('_') != std::string::npos) head = "{" + head + "}";   // m1_x -> {m_1}_x
    return head + "_" + (sub.size() == 1 ? sub : "{" + sub + "}");
  }
  // letters followed by digits: m1 -> m_1, m12 -> m_{12}
  std::size_t i = 0;
  while (i < name.size() && std::isalpha(static_cast<unsigned char>(name[i]))) ++i;
  if (i > 0 && i < name.size()) {
    bool digits = true;
    for (std::size_t j = i; j < name.size(); ++j)
      if (!std::isdigit(static_cast<unsigned char>(name[j]))) digits = false;
    if (digits) {
      std::string head = default_tex(name.substr(0, i));
      std::string tail = name.substr(i);
      return head + "_" + (tail.size() == 1 ? tail : "{" + tail + "}");
    }
  }
  return name;
}

constexpr int kMaxFunctions = 16;

}  // namespace

Domain Domain::interval(GiNaC::ex lo, bool lo_open, GiNaC::ex hi, bool hi_open) {
  Domain d;
  d.kind = Kind::Interval;
  d.lo = std::move(lo);
  d.hi = std::move(hi);
  d.lo_open = lo_open;
  d.hi_open = hi_open;
  return d;
}

bool Domain::contains(const GiNaC::numeric& x) const {
  if (!x.is_real()) return false;
  if (integer && !x.is_integer()) return false;
  switch (kind) {
    case Kind::Real: return true;
    case Kind::Positive: return x.is_positive();
    case Kind::Nonnegative: return !x.is_negative();
    case Kind::Negative: return x.is_negative();
    case Kind::Interval: {
      int c_lo = compare_constants(x, lo);
      int c_hi = compare_constants(x, hi);
      if (c_lo == 2 || c_hi == 2) return false;
      bool lo_ok = lo_open ? c_lo > 0 : c_lo >= 0;
      bool hi_ok = hi_open ? c_hi < 0 : c_hi <= 0;
      return lo_ok && hi_ok;
    }
  }
  return false;
}

bool Domain::strictly_positive() const {
  switch (kind) {
    case Kind::Positive: return true;
    case Kind::Interval: {
      int c = compare_constants(lo, 0);
      return c == 1 || (c == 0 && lo_open);
    }
    default: return false;
  }
}

bool Domain::nonnegative_values() const {
  switch (kind) {
    case Kind::Positive:
    case Kind::Nonnegative: return true;
    case Kind::Interval: {
      int c = compare_constants(lo, 0);
      return c == 1 || c == 0;
    }
    default: return false;
  }
}

bool Domain::empty() const {
  if (kind != Kind::Interval) return false;
  int c = compare_constants(lo, hi);
  if (c == 2) return true;  // not real constants: no point can satisfy it
  if (c > 0) return true;
  if (c == 0 && (lo_open || hi_open)) return true;
  if (!integer) return false;
  // an integer interval: is there an integer in it? The integers next to the lower end are
  // tried exactly; past them, an interval at least 2 long always holds one.
  DigitsGuard g(60);
  GiNaC::ex l = lo.evalf(), h = hi.evalf();
  if (!GiNaC::is_a<GiNaC::numeric>(l) || !GiNaC::is_a<GiNaC::numeric>(h)) return true;
  const GiNaC::numeric start =
      GiNaC::numeric(cln::floor1(cln::the<cln::cl_R>(GiNaC::ex_to<GiNaC::numeric>(l).to_cl_N()))) - 1;
  for (int k = 0; k < 4; ++k)
    if (contains(start + k)) return false;
  return GiNaC::ex_to<GiNaC::numeric>(h) - GiNaC::ex_to<GiNaC::numeric>(l) < 2;
}

std::string Domain::to_string() const {
  switch (kind) {
    case Kind::Real: return integer ? "integer" : "real";
    case Kind::Positive: return integer ? "positive integer" : "positive";
    case Kind::Nonnegative: return integer ? "nonnegative integer" : "nonnegative";
    case Kind::Negative: return integer ? "negative integer" : "negative";
    case Kind::Interval:
      return std::string(integer ? "integer in " : "in ") + (lo_open ? "(" : "[") + bound_text(lo) + ", " +
             bound_text(hi) + (hi_open ? ")" : "]");
  }
  return "real";
}

bool SymbolTable::narrow_domain(const std::string& name, const Domain& d) {
  auto it = by_name_.find(name);
  if (it == by_name_.end()) return false;
  symbols_[it->second].domain = d;
  return true;
}

const SymbolInfo& SymbolTable::declare(SymbolInfo info) {
  auto it = by_name_.find(info.name);
  if (it != by_name_.end()) {
    const SymbolInfo& prev = symbols_[it->second];
    throw InputError(info.pos, "symbol '" + info.name + "' is already declared at " +
                                   std::to_string(prev.pos.line) + ":" +
                                   std::to_string(prev.pos.col),
                     static_cast<int>(std::max<std::size_t>(1, info.name.size())));
  }
  if (info.domain.empty())
    throw InputError(info.pos, "the domain '" + info.domain.to_string() + "' of '" + info.name +
                                   "' is empty: no value can satisfy it",
                     static_cast<int>(std::max<std::size_t>(1, info.name.size())));
  if (info.is_function) {
    int count = 0;
    for (const auto& s : symbols_) count += s.is_function ? 1 : 0;
    if (count >= kMaxFunctions)
      throw InputError(info.pos, "too many functions: at most " + std::to_string(kMaxFunctions) +
                                     " functions may be declared ('" + info.name + "' is number " +
                                     std::to_string(count + 1) + ")");
  }
  if (info.tex.empty()) info.tex = default_tex(info.name);
  // The only place derivation symbols are created: possymbol when every value is > 0 (so
  // GiNaC simplifies sqrt(m^2) = m and log rules apply), realsymbol otherwise.
  if (info.domain.strictly_positive())
    info.sym = GiNaC::possymbol(info.name);
  else
    info.sym = GiNaC::realsymbol(info.name);
  std::size_t index = symbols_.size();
  by_name_[info.name] = index;
  symbols_.push_back(std::move(info));
  return symbols_.back();
}

bool SymbolTable::set_tex(const std::string& name, std::string tex) {
  auto it = by_name_.find(name);
  if (it == by_name_.end()) return false;
  symbols_[it->second].tex = std::move(tex);
  return true;
}

SymbolTable SymbolTable::with_bound_variable(const std::string& name) const {
  SymbolTable t = *this;
  auto it = by_name_.find(name);
  if (it == by_name_.end()) return t;
  SymbolInfo& info = t.symbols_[it->second];
  if (info.is_function) return t;
  const GiNaC::ex old = info.sym;
  info.sym = GiNaC::realsymbol(name);
  info.domain = Domain::real();   // (a real variable of integration even for an integer quantity)
  // relations assumed of the declared quantity say nothing about the dummy variable
  std::vector<Constraint> kept;
  for (const auto& c : t.constraints_)
    if (!c.lhs.has(old) && !c.rhs.has(old)) kept.push_back(c);
  t.constraints_ = std::move(kept);
  return t;
}

const SymbolInfo* SymbolTable::find(const std::string& name) const {
  auto it = by_name_.find(name);
  return it == by_name_.end() ? nullptr : &symbols_[it->second];
}

const SymbolInfo* SymbolTable::find(const GiNaC::symbol& s) const {
  // GiNaC symbols compare by serial; is_equal is that test.
  for (const auto& info : symbols_)
    if (GiNaC::is_a<GiNaC::symbol>(info.sym) && info.sym.is_equal(s)) return &info;
  return nullptr;
}

int SymbolTable::function_index(const std::string& name) const {
  int index = 0;
  for (const auto& s : symbols_) {
    if (!s.is_function) continue;
    if (s.name == name) return index;
    ++index;
  }
  return -1;
}


bool sign_satisfies(Constraint::Op op, int sign) {
  using Op = Constraint::Op;
  switch (op) {
    case Op::Lt: return sign < 0;
    case Op::Le: return sign <= 0;
    case Op::Gt: return sign > 0;
    case Op::Ge: return sign >= 0;
    case Op::Ne: return sign != 0;
  }
  return false;
}

Constraint::Op flipped(Constraint::Op op) {
  using Op = Constraint::Op;
  switch (op) {
    case Op::Lt: return Op::Gt;
    case Op::Le: return Op::Ge;
    case Op::Gt: return Op::Lt;
    case Op::Ge: return Op::Le;
    case Op::Ne: return Op::Ne;
  }
  return op;
}

const char* op_text(Constraint::Op op) {
  using Op = Constraint::Op;
  switch (op) {
    case Op::Lt: return "<";
    case Op::Le: return "<=";
    case Op::Gt: return ">";
    case Op::Ge: return ">=";
    case Op::Ne: return "!=";
  }
  return "?";
}

}  // namespace dc
