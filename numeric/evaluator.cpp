// Compiler from GiNaC expressions to register programs (see evaluator.hpp).
#include "numeric/evaluator.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "derivations/decide/prove.hpp"
#include "numeric/reference/exact.hpp"

namespace dc::num {

const char* op_name(Op op) {
  switch (op) {
    case Op::Add: return "add";
    case Op::Sub: return "sub";
    case Op::Mul: return "mul";
    case Op::Div: return "div";
    case Op::Neg: return "neg";
    case Op::Sqrt: return "sqrt";
    case Op::Exp: return "exp";
    case Op::Expm1: return "expm1";
    case Op::Log: return "log";
    case Op::Log1p: return "log1p";
    case Op::Sin: return "sin";
    case Op::Cos: return "cos";
    case Op::Tan: return "tan";
    case Op::Asin: return "asin";
    case Op::Acos: return "acos";
    case Op::Atan: return "atan";
    case Op::Abs: return "abs";
    case Op::Pow: return "pow";
    case Op::Hypot: return "hypot";
  }
  return "?";
}

int op_arity(Op op) {
  switch (op) {
    case Op::Add: case Op::Sub: case Op::Mul: case Op::Div: case Op::Pow: case Op::Hypot:
      return 2;
    default:
      return 1;
  }
}

std::size_t Program::count(Op op) const {
  return static_cast<std::size_t>(
      std::count_if(code.begin(), code.end(), [op](const Instr& i) { return i.op == op; }));
}

std::string Program::listing() const {
  std::ostringstream os;
  for (std::size_t i = 0; i < inputs.size(); ++i) os << "r" << i << " = input " << inputs[i] << "\n";
  for (std::size_t c = 0; c < const_text.size(); ++c)
    os << "r" << inputs.size() + c << " = const " << const_text[c] << "\n";
  for (const Instr& in : code) {
    os << "r" << in.dst << " = " << op_name(in.op) << " r" << in.a;
    if (op_arity(in.op) == 2) os << " r" << in.b;
    os << "\n";
  }
  os << "result r" << result << "\n";
  return os.str();
}

namespace {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;

bool is_constant_expr(const ex& e) {
  if (is_a<GiNaC::symbol>(e)) return false;
  if (is_a<GiNaC::function>(e)) {
    // abstract functions (v(t)) are not constants even without arguments
    const auto& f = ex_to<GiNaC::function>(e);
    static const std::set<std::string> known = {"exp", "log", "sin", "cos", "tan", "asin",
                                                "acos", "atan", "abs", "sqrt"};
    if (!known.count(f.get_name())) return false;
  }
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (!is_constant_expr(e.op(i))) return false;
  return true;
}

// Virtual registers during compilation: inputs [0, n); then constants and temporaries in
// creation order (kind recorded), renumbered at the end.
class Compiler {
 public:
  Compiler(const std::vector<GiNaC::symbol>& inputs, const CompileOptions& opt)
      : inputs_(inputs), opt_(opt) {
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      // by name: a possymbol held in a GiNaC::symbol value is sliced to a plain symbol, which
      // no longer compares equal to the possymbol in the expression
      if (!input_index_.emplace(inputs[i].get_name(), static_cast<std::uint32_t>(i)).second)
        throw std::invalid_argument("evaluator: input '" + inputs[i].get_name() + "' given twice");
      kind_.push_back(Kind::Input);
    }
  }

  Program finish(const ex& e) {
    const std::uint32_t res = compile(e);
    return allocate(res);
  }

 private:
  enum class Kind { Input, Const, Temp };

  // ---- canonical keys: a deterministic total order on subexpressions -------------------
  const std::string& key(const ex& e) {
    auto it = keys_.find(e);
    if (it != keys_.end()) return it->second;
    std::string k;
    if (is_a<GiNaC::numeric>(e)) {
      std::ostringstream os;
      os << ex_to<GiNaC::numeric>(e);
      k = "#" + os.str();
    } else if (is_a<GiNaC::symbol>(e)) {
      k = "s:" + ex_to<GiNaC::symbol>(e).get_name();
      auto in = input_index_.find(ex_to<GiNaC::symbol>(e).get_name());
      if (in != input_index_.end()) k += ":" + std::to_string(in->second);
    } else if (is_a<GiNaC::constant>(e)) {
      std::ostringstream os;
      os << e;
      k = "c:" + os.str();
    } else if (is_a<GiNaC::add>(e)) {
      std::vector<std::string> parts;
      for (std::size_t i = 0; i < e.nops(); ++i) parts.push_back(product_key(product_of(e.op(i))));
      std::sort(parts.begin(), parts.end());
      k = "+(";
      for (const auto& p : parts) k += p + ",";
      k += ")";
    } else if (is_a<GiNaC::mul>(e)) {
      k = product_key(product_of(e));
    } else if (is_a<GiNaC::power>(e)) {
      if (is_int_power_of_sum(e)) {
        bool flip = false;  // the sign is the enclosing product's business (product_of)
        k = "^(" + key(orient_add(e.op(0), flip)) + "," + key(e.op(1)) + ")";
      } else {
        k = "^(" + key(e.op(0)) + "," + key(e.op(1)) + ")";
      }
    } else if (is_a<GiNaC::function>(e)) {
      k = ex_to<GiNaC::function>(e).get_name() + "(";
      for (std::size_t i = 0; i < e.nops(); ++i) k += key(e.op(i)) + ",";
      k += ")";
    } else {
      std::ostringstream os;
      os << e;
      throw std::invalid_argument("evaluator: cannot compile '" + os.str() + "'");
    }
    return keys_.emplace(e, std::move(k)).first->second;
  }

  // ---- canonical orientation of sub-sums ----------------------------------------------
  // GiNaC may store -e*m1*(v2 - v1) as e*m1*(v1 - v2), and which one it picks follows hash
  // order, i.e. changes between processes (and rebuilding the product may flip it again). The
  // value is the same, but the order in which the program adds terms, and so the rounding,
  // would not be. So a product is never taken as GiNaC stores it: it is read as a coefficient
  // times factors, each sum factor (and each sum raised to an integer power) turned to the
  // orientation with the smaller canonical key, the flips folded into the coefficient's sign.
  // Keys of products are computed from this form, so they do not depend on GiNaC's choice.
  struct Product {
    GiNaC::numeric coeff{1};
    std::vector<ex> factors;  // sorted by key
  };

  static bool is_int_power_of_sum(const ex& f) {
    return is_a<GiNaC::power>(f) && is_a<GiNaC::add>(f.op(0)) && is_a<GiNaC::numeric>(f.op(1)) &&
           ex_to<GiNaC::numeric>(f.op(1)).is_integer();
  }

  // a or -a, whichever has the smaller key (-a is built by distributing -1 over the terms, which
  // GiNaC does without touching the terms' factors)
  // Preference: fewer negative terms (m1 + m2, not -m1 - m2, which would cost a negation),
  // then the smaller key.
  int negative_terms(const ex& a) {
    int n = 0;
    for (std::size_t i = 0; i < a.nops(); ++i) {
      const ex t = a.op(i);
      const ex c = is_a<GiNaC::mul>(t) ? t.op(t.nops() - 1) : t;
      if (is_a<GiNaC::numeric>(c) && ex_to<GiNaC::numeric>(c).is_negative()) ++n;
    }
    return n;
  }

  ex orient_add(const ex& a, bool& negate) {
    const ex neg = -a;
    const int na = negative_terms(a), nn = negative_terms(neg);
    if (nn < na || (nn == na && key(neg) < key(a))) {
      negate = !negate;
      return neg;
    }
    return a;
  }

  Product product_of(const ex& e) {
    Product p;
    bool negate = false;
    auto take = [&](const ex& f) {
      if (is_a<GiNaC::numeric>(f) && ex_to<GiNaC::numeric>(f).is_rational())
        p.coeff *= ex_to<GiNaC::numeric>(f);
      else if (is_a<GiNaC::add>(f))
        p.factors.push_back(orient_add(f, negate));
      else if (is_int_power_of_sum(f)) {
        // kept as written; compiled with the oriented base (compile_base_power), and an odd
        // power's sign goes to the coefficient
        bool flip = false;
        orient_add(f.op(0), flip);
        if (flip && ex_to<GiNaC::numeric>(f.op(1)).is_odd()) negate = !negate;
        p.factors.push_back(f);
      } else
        p.factors.push_back(f);
    };
    if (is_a<GiNaC::mul>(e))
      for (std::size_t i = 0; i < e.nops(); ++i) take(e.op(i));
    else
      take(e);
    if (negate) p.coeff = -p.coeff;
    std::stable_sort(p.factors.begin(), p.factors.end(),
                     [&](const ex& a, const ex& b) { return key(a) < key(b); });
    return p;
  }

  std::string product_key(const Product& p) {
    std::ostringstream os;
    os << p.coeff;
    std::string k = "*(#" + os.str();
    for (const ex& f : p.factors) k += "," + key(f);
    return k + ")";
  }

  std::vector<ex> sorted_ops(const ex& e) {
    std::vector<ex> v;
    for (std::size_t i = 0; i < e.nops(); ++i) v.push_back(e.op(i));
    std::stable_sort(v.begin(), v.end(), [&](const ex& a, const ex& b) { return key(a) < key(b); });
    return v;
  }

  // ---- registers and instructions ------------------------------------------------------
  std::uint32_t new_reg(Kind k) {
    kind_.push_back(k);
    return static_cast<std::uint32_t>(kind_.size() - 1);
  }

  std::uint32_t constant(const GiNaC::numeric& value) {
    const GiNaC::numeric exact = to_exact(value);
    std::ostringstream os;
    os << exact;
    const std::string text = os.str();
    auto it = consts_.find(text);
    if (it != consts_.end()) return it->second;
    const std::uint32_t r = new_reg(Kind::Const);
    const_values_[r] = exact;
    consts_[text] = r;
    return r;
  }

  std::uint32_t emit(Op op, std::uint32_t a, std::uint32_t b) {
    if (op_arity(op) == 1) b = a;
    if ((op == Op::Add || op == Op::Mul || op == Op::Hypot) && b < a) std::swap(a, b);
    const auto k = std::make_tuple(op, a, b);
    auto it = cse_.find(k);
    if (it != cse_.end()) return it->second;
    const std::uint32_t d = new_reg(Kind::Temp);
    code_.push_back({op, d, a, b});
    cse_[k] = d;
    return d;
  }

  std::uint32_t emit(Op op, std::uint32_t a) { return emit(op, a, a); }

  std::uint32_t one() { return constant(GiNaC::numeric(1)); }

  // ---- compilation ---------------------------------------------------------------------
  std::uint32_t compile(const ex& e) {
    // an integer power of a sum is compiled as a product, whose key carries the sign that
    // orienting the sum may move out of the power; a constant one ((1 + 7 atan(3))^-1) is a
    // constant (compile_product hands constant factors back here: no other way ends)
    if (is_int_power_of_sum(e) && !is_constant_expr(e)) return compile_product(product_of(e));
    const std::string& k = key(e);
    auto it = memo_.find(k);
    if (it != memo_.end()) return it->second;
    const std::uint32_t r = compile_uncached(e);
    memo_[key(e)] = r;
    return r;
  }

  std::uint32_t compile_uncached(const ex& e) {
    if (is_a<GiNaC::symbol>(e)) {
      auto in = input_index_.find(ex_to<GiNaC::symbol>(e).get_name());
      if (in == input_index_.end())
        throw std::invalid_argument("evaluator: symbol '" + ex_to<GiNaC::symbol>(e).get_name() +
                                    "' is not an input of the formula");
      return in->second;
    }
    if (is_a<GiNaC::numeric>(e)) {
      const auto& n = ex_to<GiNaC::numeric>(e);
      if (!n.is_real()) throw std::invalid_argument("evaluator: complex constant in formula");
      return constant(n);
    }
    if (is_constant_expr(e)) {
      DigitsGuard guard(45);
      ex v = GiNaC::evalf(e);
      if (!is_a<GiNaC::numeric>(v) || !ex_to<GiNaC::numeric>(v).is_real()) {
        std::ostringstream os;
        os << e;
        throw std::invalid_argument("evaluator: constant '" + os.str() + "' is not a real number");
      }
      return constant(ex_to<GiNaC::numeric>(v));
    }
    if (is_a<GiNaC::add>(e)) return compile_add(e);
    if (is_a<GiNaC::mul>(e)) return compile_product(product_of(e));
    if (is_a<GiNaC::power>(e)) return compile_power(e);
    if (is_a<GiNaC::function>(e)) return compile_function(e);
    std::ostringstream os;
    os << e;
    throw std::invalid_argument("evaluator: cannot compile '" + os.str() + "'");
  }

  // |c| * (product of factors) with c = p/q rational, applied as (product * p) / q so that
  // x/3 is a correctly rounded division, not a multiplication by a rounded 1/3.
  std::uint32_t scaled(const GiNaC::numeric& absc, const std::vector<ex>& factors) {
    if (factors.empty()) return constant(absc);
    Product unit;
    unit.factors = factors;
    std::uint32_t r = compile_product(unit);
    const GiNaC::numeric p = absc.numer(), q = absc.denom();
    if (!p.is_equal(GiNaC::numeric(1))) r = emit(Op::Mul, constant(p), r);
    if (!q.is_equal(GiNaC::numeric(1))) r = emit(Op::Div, r, constant(q));
    return r;
  }

  std::uint32_t compile_add(const ex& e) {
    std::vector<ex> terms = sorted_ops(e);
    // exp(x) - 1 -> expm1(x)
    std::vector<std::uint32_t> fused_pos;
    if (opt_.fuse_expm1) {
      auto minus_one = std::find_if(terms.begin(), terms.end(), [](const ex& t) {
        return is_a<GiNaC::numeric>(t) && ex_to<GiNaC::numeric>(t).is_equal(GiNaC::numeric(-1));
      });
      if (minus_one != terms.end()) {
        auto ex_term = std::find_if(terms.begin(), terms.end(), [](const ex& t) {
          return is_a<GiNaC::function>(t) && ex_to<GiNaC::function>(t).get_name() == "exp";
        });
        if (ex_term != terms.end()) {
          fused_pos.push_back(emit(Op::Expm1, compile(ex_term->op(0))));
          const ex exp_term = *ex_term;
          terms.erase(std::remove_if(terms.begin(), terms.end(),
                                     [&](const ex& t) {
                                       return t.is_equal(exp_term) ||
                                              (is_a<GiNaC::numeric>(t) &&
                                               ex_to<GiNaC::numeric>(t).is_equal(GiNaC::numeric(-1)));
                                     }),
                      terms.end());
        }
      }
    }
    std::vector<std::uint32_t> pos = fused_pos, neg;
    // terms in key order of their oriented product form (independent of GiNaC's choices)
    std::vector<std::pair<std::string, Product>> prods;
    for (const ex& t : terms) {
      Product pr = product_of(t);
      if (pr.coeff.is_zero()) continue;
      Product unit;
      unit.factors = pr.factors;
      prods.emplace_back(product_key(unit) + "|" + product_key(pr), std::move(pr));
    }
    std::stable_sort(prods.begin(), prods.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [k, pr] : prods) {
      const std::uint32_t r = scaled(GiNaC::abs(pr.coeff), pr.factors);
      (pr.coeff.is_negative() ? neg : pos).push_back(r);
    }
    std::uint32_t acc;
    std::size_t ni = 0;
    if (!pos.empty()) {
      acc = pos[0];
      for (std::size_t i = 1; i < pos.size(); ++i) acc = emit(Op::Add, acc, pos[i]);
    } else if (!neg.empty()) {
      acc = emit(Op::Neg, neg[0]);
      ni = 1;
    } else {
      return constant(GiNaC::numeric(0));
    }
    for (; ni < neg.size(); ++ni) acc = emit(Op::Sub, acc, neg[ni]);
    return acc;
  }

  // symbols occurring in e (by key), for the ratio-first heuristic
  void symbols_of(const ex& e, std::set<std::string>& out) {
    if (is_a<GiNaC::symbol>(e)) {
      out.insert(key(e));
      return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i) symbols_of(e.op(i), out);
  }

  std::uint32_t product(const std::vector<std::uint32_t>& f) {
    std::uint32_t acc = f[0];
    for (std::size_t i = 1; i < f.size(); ++i) acc = emit(Op::Mul, acc, f[i]);
    return acc;
  }

  std::uint32_t compile_product(const Product& pr) {
    const std::string pk = product_key(pr);
    auto memo = memo_.find(pk);
    if (memo != memo_.end()) return memo->second;
    const GiNaC::numeric coeff = pr.coeff;
    // factor = base^exp; den holds 1/den factors with their exponent made positive
    std::vector<std::pair<ex, GiNaC::numeric>> num, den;
    for (const ex& f : pr.factors) {
      if (is_a<GiNaC::power>(f) && is_a<GiNaC::numeric>(f.op(1)) &&
          ex_to<GiNaC::numeric>(f.op(1)).is_rational() && !is_constant_expr(f)) {
        const GiNaC::numeric n = ex_to<GiNaC::numeric>(f.op(1));
        (n.is_negative() ? den : num).emplace_back(f.op(0), GiNaC::abs(n));
      } else {
        num.emplace_back(f, GiNaC::numeric(1));
      }
    }
    std::vector<std::uint32_t> nr, dr;
    const GiNaC::numeric p = GiNaC::abs(coeff.numer()), q = coeff.denom();
    for (const auto& [b, n] : num) nr.push_back(compile_base_power(b, n));
    if (!p.is_equal(GiNaC::numeric(1))) nr.push_back(constant(p));
    for (const auto& [b, n] : den) dr.push_back(compile_base_power(b, n));
    if (!q.is_equal(GiNaC::numeric(1))) dr.push_back(constant(q));
    std::uint32_t r;
    if (dr.empty()) {
      r = nr.empty() ? one() : product(nr);
    } else {
      const std::uint32_t d = product(dr);
      if (nr.empty()) {
        r = emit(Op::Div, one(), d);
      } else {
        std::size_t first = 0;
        if (opt_.ratio_first && nr.size() > 1) {
          std::set<std::string> dsyms;
          for (const auto& f : den) symbols_of(f.first, dsyms);
          for (std::size_t i = 0; i < num.size(); ++i) {
            std::set<std::string> s;
            symbols_of(num[i].first, s);
            if (std::any_of(s.begin(), s.end(), [&](const std::string& x) { return dsyms.count(x); })) {
              first = i;
              break;
            }
          }
          std::uint32_t acc = emit(Op::Div, nr[first], d);
          for (std::size_t i = 0; i < nr.size(); ++i)
            if (i != first) acc = emit(Op::Mul, acc, nr[i]);
          r = acc;
        } else {
          r = emit(Op::Div, product(nr), d);
        }
      }
    }
    if (coeff.is_negative()) r = emit(Op::Neg, r);
    memo_[pk] = r;
    return r;
  }

  std::uint32_t int_power(std::uint32_t base, unsigned long n) {
    // binary powering by multiplication: x^5 = (x^2)^2 * x
    std::uint32_t result = 0;
    bool have = false;
    std::uint32_t sq = base;
    while (n > 0) {
      if (n & 1UL) {
        result = have ? emit(Op::Mul, result, sq) : sq;
        have = true;
      }
      n >>= 1;
      if (n > 0) sq = emit(Op::Mul, sq, sq);
    }
    return have ? result : one();
  }

  // base^n for a positive rational n; a sum raised to an integer power is compiled with its
  // oriented base (the caller's product coefficient carries the sign)
  std::uint32_t compile_base_power(const ex& b, const GiNaC::numeric& an) {
    if (an > GiNaC::numeric(1000000)) throw std::invalid_argument("evaluator: exponent too large");
    if (an.is_integer()) {
      bool flip = false;
      const ex base = is_a<GiNaC::add>(b) ? orient_add(b, flip) : b;
      return int_power(compile(base), an.to_long());
    }
    if (an.denom().is_equal(GiNaC::numeric(2))) {
      std::uint32_t s;
      if (opt_.fuse_hypot && an.numer().is_equal(GiNaC::numeric(1)) && hypot_args(b)) {
        s = emit(Op::Hypot, compile(hypot_a_), compile(hypot_b_));
      } else {
        s = emit(Op::Sqrt, compile(b));
      }
      return int_power(s, an.numer().to_long());
    }
    return emit(Op::Pow, compile(b), constant(an));
  }

  std::uint32_t compile_power(const ex& e) {
    const ex b = e.op(0), x = e.op(1);
    if (is_a<GiNaC::numeric>(x) && ex_to<GiNaC::numeric>(x).is_rational()) {
      const GiNaC::numeric n = ex_to<GiNaC::numeric>(x);
      if (GiNaC::abs(n) > GiNaC::numeric(1000000))
        throw std::invalid_argument("evaluator: exponent too large");
      const std::uint32_t r = compile_base_power(b, GiNaC::abs(n));
      return n.is_negative() ? emit(Op::Div, one(), r) : r;
    }
    return emit(Op::Pow, compile(b), compile(x));
  }

  // b == x^2 + y^2 (two terms, coefficient 1, both even powers)?
  bool hypot_args(const ex& b) {
    if (!is_a<GiNaC::add>(b) || b.nops() != 2) return false;
    ex half[2];
    for (int i = 0; i < 2; ++i) {
      const ex t = b.op(static_cast<std::size_t>(i));
      if (!is_a<GiNaC::power>(t) || !t.op(1).is_equal(ex(2))) return false;
      half[i] = t.op(0);
    }
    if (key(half[1]) < key(half[0])) std::swap(half[0], half[1]);
    hypot_a_ = half[0];
    hypot_b_ = half[1];
    return true;
  }

  std::uint32_t compile_function(const ex& e) {
    const std::string name = ex_to<GiNaC::function>(e).get_name();
    if (e.nops() != 1)
      throw std::invalid_argument("evaluator: unsupported function '" + name + "'");
    const ex a = e.op(0);
    if (name == "log") {
      // log(1 + x) -> log1p(x): the sum 1 + x would round x away when |x| << 1
      if (opt_.fuse_log1p && is_a<GiNaC::add>(a)) {
        for (std::size_t i = 0; i < a.nops(); ++i)
          if (a.op(i).is_equal(ex(1))) return emit(Op::Log1p, compile(a - 1));
      }
      return emit(Op::Log, compile(a));
    }
    static const std::map<std::string, Op> unary = {
        {"exp", Op::Exp},   {"sin", Op::Sin},   {"cos", Op::Cos},   {"tan", Op::Tan},
        {"asin", Op::Asin}, {"acos", Op::Acos}, {"atan", Op::Atan}, {"abs", Op::Abs}};
    auto it = unary.find(name);
    if (it == unary.end())
      throw std::invalid_argument("evaluator: unsupported function '" + name + "'");
    return emit(it->second, compile(a));
  }

  // ---- register allocation -------------------------------------------------------------
  Program allocate(std::uint32_t result) {
    Program p;
    for (const auto& s : inputs_) p.inputs.push_back(s.get_name());
    const std::uint32_t nin = static_cast<std::uint32_t>(inputs_.size());
    std::vector<std::uint32_t> map(kind_.size(), 0);
    for (std::uint32_t i = 0; i < nin; ++i) map[i] = i;
    std::uint32_t next = nin;
    for (std::uint32_t v = nin; v < kind_.size(); ++v)
      if (kind_[v] == Kind::Const) {
        map[v] = next++;
        const GiNaC::numeric& c = const_values_.at(v);
        p.const_double.push_back(round_to_double(c));
        p.const_double_lo.push_back(
            std::isfinite(p.const_double.back())
                ? round_to_double(c - exact_rational(p.const_double.back(), "constant"))
                : 0.0);
        p.const_long_double.push_back(round_to_long_double(c));
        std::ostringstream os;
        os << c;
        p.const_text.push_back(os.str());
      }
    const std::uint32_t first_temp = next;
    // liveness: last instruction reading each virtual temp
    std::vector<long> last_use(kind_.size(), -1);
    for (std::size_t i = 0; i < code_.size(); ++i) {
      last_use[code_[i].a] = static_cast<long>(i);
      last_use[code_[i].b] = static_cast<long>(i);
    }
    std::set<std::uint32_t> free_slots;
    std::uint32_t n_slots = 0;
    for (std::size_t i = 0; i < code_.size(); ++i) {
      Instr in = code_[i];
      Instr out{in.op, 0, map[in.a], map[in.b]};
      std::uint32_t slot;
      if (!free_slots.empty()) {
        slot = *free_slots.begin();
        free_slots.erase(free_slots.begin());
      } else {
        slot = first_temp + n_slots++;
      }
      map[in.dst] = slot;
      out.dst = slot;
      p.code.push_back(out);
      for (std::uint32_t src : {in.a, in.b})
        if (kind_[src] == Kind::Temp && last_use[src] == static_cast<long>(i) && src != result)
          free_slots.insert(map[src]);
      if (last_use[in.dst] < 0 && in.dst != result) free_slots.insert(slot);  // dead (not expected)
    }
    p.result = map[result];
    p.n_registers = first_temp + n_slots;
    return p;
  }

  const std::vector<GiNaC::symbol>& inputs_;
  CompileOptions opt_;
  std::map<std::string, std::uint32_t> input_index_;
  std::map<ex, std::string, GiNaC::ex_is_less> keys_;
  std::map<std::string, std::uint32_t> memo_;
  std::map<std::string, std::uint32_t> consts_;
  std::map<std::uint32_t, GiNaC::numeric> const_values_;
  std::map<std::tuple<Op, std::uint32_t, std::uint32_t>, std::uint32_t> cse_;
  std::vector<Kind> kind_;
  std::vector<Instr> code_;
  ex hypot_a_, hypot_b_;
};

}  // namespace

Program compile(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& inputs,
                const CompileOptions& opt) {
  Compiler c(inputs, opt);
  return c.finish(e);
}

}  // namespace dc::num
