// Deterministic printing of GiNaC expressions (see printer.hpp).
//
// GiNaC's print order follows hash values that change between processes, so the expression is
// first converted into a tree of our own (PNode): sums of terms, each term a rational
// coefficient times factors; every list is sorted with our comparator:
//   terms of a sum:    ascending total degree, then the printed text of the monomial
//                      (so "1 - e^2", "m1 - m2", "m1*v1 + m2*v2 - e*m2*v1 + ...")
//   factors of a term: symbols (and their powers) before functions before sums, then by text
// A sum that appears as a factor (or as the base of an integer power) gets a canonical sign:
// the representative with more positive terms (on a tie: whose first term is positive), the
// sign moving into the coefficient. So -(m1-m2)*x and (m2-m1)*x print identically. Negative
// powers print as fractions.
#include "derivations/symbolic/printer.hpp"

#include "derivations/symbolic/functions.hpp"
#include "derivations/symbolic/integral_atom.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include <cln/cln.h>

namespace dc {

// ---------------------------------------------------------------- names

static const char* const kGreek[] = {"alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta",
                              "eta", "theta", "vartheta", "iota", "kappa", "lambda", "mu", "nu",
                              "xi", "pi", "rho", "sigma", "tau", "upsilon", "phi", "varphi", "chi",
                              "psi", "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi",
                              "Sigma", "Upsilon", "Phi", "Psi", "Omega"};

static bool is_greek(const std::string& s) {
  for (const char* g : kGreek)
    if (s == g) return true;
  return false;
}

// TeX for a name without a declared TeX name: m1 -> m_{1}, theta -> \theta, v_e -> v_{e},
// theta0 -> \theta_{0}.
std::string default_tex_name(const std::string& name) {
  std::string head = name, sub;
  auto us = name.find('_');
  if (us != std::string::npos) {
    head = name.substr(0, us);
    sub = name.substr(us + 1);
  } else {
    std::size_t i = name.size();
    while (i > 1 && std::isdigit(static_cast<unsigned char>(name[i - 1]))) --i;
    if (i < name.size()) {
      head = name.substr(0, i);
      sub = name.substr(i);
    }
  }
  std::string h = is_greek(head) ? "\\" + head : head;
  if (head.size() > 1 && !is_greek(head)) h = "\\mathit{" + head + "}";
  if (sub.empty()) return h;
  std::string s = is_greek(sub) ? "\\" + sub : sub;
  return h + "_{" + s + "}";
}

namespace {

using GiNaC::ex;
using GiNaC::numeric;

enum class Style { Text, Latex };

struct PNode {
  enum class Kind { Number, Symbol, Sum, Product, Power, Function, Derivative } kind = Kind::Number;
  numeric value;                 // Number (non-negative rational or float); Product: coefficient
  std::string text, tex;         // Symbol: the two spellings
  std::string fname;             // Function / Derivative: the function's name
  std::string ftex;              // its TeX name (declared functions)
  std::vector<PNode> kids;       // Sum: terms (Products); Product: factors; Power: base, exponent;
                                 // Function/Derivative: arguments
  std::vector<unsigned> dparams; // Derivative: argument indices differentiated
  std::string key;               // printed text, used for sorting
};

using Kind = PNode::Kind;

// ---------------------------------------------------------------- numbers

std::string int_str(const numeric& n) {
  std::ostringstream os;
  os << cln::the<cln::cl_I>(n.to_cl_N());
  return os.str();
}

int sign_of(const numeric& c) {
  if (c.is_real()) return c.is_zero() ? 0 : (c.is_negative() ? -1 : 1);
  numeric r = c.real();
  if (!r.is_zero()) return r.is_negative() ? -1 : 1;
  return c.imag().is_negative() ? -1 : 1;
}

// Decimal text of a real float/rational with `digits` significant digits, deterministic.
std::string format_real(const numeric& x, int digits) {
  if (x.is_zero()) return "0";
  if (digits < 1) digits = 1;
  cln::cl_RA r = x.is_rational() ? cln::the<cln::cl_RA>(x.to_cl_N())
                                 : cln::rational(cln::the<cln::cl_R>(x.to_cl_N()));
  bool neg = cln::minusp(r);
  if (neg) r = -r;
  // exponent e10 with 10^e10 <= r < 10^(e10+1)
  long e10 = 0;
  cln::cl_RA t = r;
  while (t >= 10) { t = t / 10; ++e10; }
  while (t < 1) { t = t * 10; --e10; }
  // scaled = round(r * 10^(digits-1-e10))
  long shift = digits - 1 - e10;
  cln::cl_RA scaled = shift >= 0 ? r * cln::expt_pos(cln::cl_I(10), shift)
                                 : r / cln::expt_pos(cln::cl_I(10), -shift);
  cln::cl_I m = cln::round1(scaled);
  if (m >= cln::expt_pos(cln::cl_I(10), digits)) {  // rounding carried into a new digit
    m = cln::round1(m / cln::cl_I(10));
    ++e10;
  }
  std::ostringstream ms;
  ms << m;
  std::string mant = ms.str();                 // exactly `digits` digits
  while (mant.size() > 1 && mant.back() == '0') mant.pop_back();
  std::string out;
  if (e10 >= -5 && e10 < digits) {
    if (e10 >= 0) {
      std::string ip = mant.substr(0, std::min<std::size_t>(mant.size(), e10 + 1));
      while (static_cast<long>(ip.size()) < e10 + 1) ip += '0';
      std::string fp = mant.size() > static_cast<std::size_t>(e10 + 1) ? mant.substr(e10 + 1) : "";
      out = fp.empty() ? ip : ip + "." + fp;
    } else {
      out = "0." + std::string(static_cast<std::size_t>(-e10 - 1), '0') + mant;
    }
  } else {
    out = mant.substr(0, 1);
    if (mant.size() > 1) out += "." + mant.substr(1);
    out += "e" + std::to_string(e10);
  }
  return neg ? "-" + out : out;
}

// Non-negative real number (rational or float) as text.
std::string number_text(const numeric& n, int digits = 17) {
  if (n.is_integer()) return int_str(n);
  if (n.is_rational()) return int_str(n.numer()) + "/" + int_str(n.denom());
  return format_real(n, digits);
}

// ---------------------------------------------------------------- conversion

class Builder {
 public:
  explicit Builder(const SymbolTable& t) : table_(t) {}

  PNode build(const ex& e) {
    if (GiNaC::is_a<numeric>(e)) return number(GiNaC::ex_to<numeric>(e));
    if (GiNaC::is_a<GiNaC::symbol>(e)) return symbol(GiNaC::ex_to<GiNaC::symbol>(e));
    if (GiNaC::is_a<GiNaC::constant>(e)) {
      PNode n;
      n.kind = Kind::Symbol;
      std::ostringstream os;
      os << e;  // constants print their own fixed name (Pi, Euler, Catalan)
      std::string name = os.str();
      if (name == "Pi") { n.text = "pi"; n.tex = "\\pi"; }
      else if (name == "Euler") { n.text = "Euler"; n.tex = "\\gamma"; }
      else { n.text = name; n.tex = "\\mathrm{" + name + "}"; }
      n.key = n.text;
      return n;
    }
    if (GiNaC::is_a<GiNaC::add>(e)) return sum(e);
    if (GiNaC::is_a<GiNaC::mul>(e)) return product(e);
    if (GiNaC::is_a<GiNaC::power>(e)) return power(e);
    if (GiNaC::is_a<GiNaC::fderivative>(e)) return derivative(e);
    if (GiNaC::is_a<GiNaC::function>(e)) return function(e);
    throw std::invalid_argument(std::string("print: unsupported expression of class '") +
                                GiNaC::ex_to<GiNaC::basic>(e).class_name() + "'");
  }

 private:
  PNode number(const numeric& v) {
    // A number is a Product with that coefficient and no factors (so signs compose).
    PNode p;
    p.kind = Kind::Product;
    p.value = v;
    finish_product(p);
    return p;
  }

  PNode symbol(const GiNaC::symbol& s) {
    PNode n;
    n.kind = Kind::Symbol;
    if (const SymbolInfo* info = table_.find(s)) {
      n.text = info->name;
      n.tex = info->tex.empty() ? default_tex_name(info->name) : info->tex;
    } else {
      n.text = s.get_name();
      n.tex = default_tex_name(n.text);
    }
    n.key = n.text;
    return n;
  }

  static PNode as_product(PNode n) {
    if (n.kind == Kind::Product) return n;
    PNode p;
    p.kind = Kind::Product;
    p.value = 1;
    p.kids.push_back(std::move(n));
    return p;
  }

  // Total degree of a factor (symbols count 1, functions 0, sums their largest term).
  static numeric degree(const PNode& n) {
    switch (n.kind) {
      case Kind::Symbol: return 1;
      case Kind::Power:
        if (n.kids[1].kind == Kind::Product && n.kids[1].kids.empty())
          return degree(n.kids[0]) * n.kids[1].value;
        return 0;
      case Kind::Sum: {
        numeric d = 0;
        bool first = true;
        for (const auto& t : n.kids) {
          numeric td = degree(t);
          if (first || td > d) d = td;
          first = false;
        }
        return d;
      }
      case Kind::Product: {
        numeric d = 0;
        for (const auto& f : n.kids) d += degree(f);
        return d;
      }
      default: return 0;
    }
  }

  static int factor_rank(const PNode& n) {
    const PNode& b = n.kind == Kind::Power ? n.kids[0] : n;
    switch (b.kind) {
      case Kind::Product: return b.kids.empty() ? 0 : 3;  // a number raised to a power (sqrt(2)) first
      case Kind::Symbol: return 1;
      case Kind::Function:
      case Kind::Derivative: return 2;
      default: return 3;             // sums
    }
  }

  // Text of a term without its coefficient's magnitude: the key used to order sum terms.
  static std::string monomial_key(const PNode& term) {
    std::string k;
    for (const auto& f : term.kids) {
      if (!k.empty()) k += "*";
      k += f.key;
    }
    return k;
  }

  void finish_product(PNode& p);

  PNode sum(const ex& e) {
    PNode s;
    s.kind = Kind::Sum;
    for (std::size_t i = 0; i < e.nops(); ++i) s.kids.push_back(as_product(build(e.op(i))));
    sort_terms(s);
    return s;
  }

  static void sort_terms(PNode& s) {
    std::stable_sort(s.kids.begin(), s.kids.end(), [](const PNode& a, const PNode& b) {
      numeric da = degree(a), db = degree(b);
      if (da != db) return da < db;
      std::string ka = monomial_key(a), kb = monomial_key(b);
      if (ka != kb) return ka < kb;
      return number_text(GiNaC::abs(a.value)) < number_text(GiNaC::abs(b.value));
    });
    s.key = render_key(s);
  }

  // Does this sum prefer to be negated (canonical sign)?
  static bool wants_negation(const PNode& s) {
    int pos = 0, neg = 0;
    for (const auto& t : s.kids) (sign_of(t.value) < 0 ? neg : pos)++;
    if (neg != pos) return neg > pos;
    return !s.kids.empty() && sign_of(s.kids.front().value) < 0;
  }

  static void negate_sum(PNode& s) {
    for (auto& t : s.kids) {
      t.value = -t.value;
      t.key = render_key(t);
    }
    s.key = render_key(s);
  }

  PNode product(const ex& e) {
    PNode p;
    p.kind = Kind::Product;
    p.value = 1;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      PNode f = build(e.op(i));
      absorb_factor(p, std::move(f));
    }
    finish_product(p);
    return p;
  }

  // Multiply a factor into product p: numbers and nested products merge; a sum gets its
  // canonical sign.
  static void absorb_factor(PNode& p, PNode f) {
    if (f.kind == Kind::Product) {
      p.value *= f.value;
      for (auto& k : f.kids) p.kids.push_back(std::move(k));
      return;
    }
    if (f.kind == Kind::Sum && wants_negation(f)) {
      negate_sum(f);
      p.value = -p.value;
    }
    if (f.kind == Kind::Power && f.kids[0].kind == Kind::Sum && f.kids[1].kind == Kind::Product &&
        f.kids[1].kids.empty() && f.kids[1].value.is_integer() && wants_negation(f.kids[0])) {
      negate_sum(f.kids[0]);
      if (f.kids[1].value.is_odd()) p.value = -p.value;
      f.key = render_key(f);
    }
    p.kids.push_back(std::move(f));
  }

  PNode power(const ex& e) {
    PNode n;
    n.kind = Kind::Power;
    n.kids.push_back(build(e.op(0)));
    n.kids.push_back(build(e.op(1)));
    // A product base (only a number here: GiNaC distributes powers of products of symbols
    // with integer exponents) stays as it is.
    // Under a non-integer power a sum keeps its own sign: sqrt(2*g*(y2 - r2)) must not become
    // sqrt(-2*g*(r2 - y2)).
    const PNode& ex_node = n.kids[1];
    bool integer_exp = ex_node.kind == Kind::Product && ex_node.kids.empty() && ex_node.value.is_integer();
    if (!integer_exp && n.kids[0].kind == Kind::Product && sign_of(n.kids[0].value) < 0) {
      PNode& b = n.kids[0];
      for (auto& k : b.kids)
        if (k.kind == Kind::Sum) {
          negate_sum(k);
          b.value = -b.value;
          finish_product(b);
          break;
        }
    }
    n.key = render_key(n);
    if (n.kids[0].kind == Kind::Sum) {
      // The sign of a sum under an integer power is canonicalised by absorb_factor; standing
      // alone it is wrapped into a product so the same happens.
      PNode p;
      p.kind = Kind::Product;
      p.value = 1;
      absorb_factor(p, std::move(n));
      finish_product(p);
      if (p.value == 1) return std::move(p.kids.front());
      return p;
    }
    return n;
  }

  // Declared abstract functions are GiNaC pool functions (dcfnK); their users' names come from
  // the table. GiNaC's own functions (exp, log, sin, ...) keep their names.
  std::string function_name(const ex& e, std::string* tex) {
    if (const SymbolInfo* info = declared_function_of(e, table_)) {
      *tex = info->tex.empty() ? default_tex_name(info->name) : info->tex;
      return info->name;
    }
    std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if (pool_function_index(e) >= 0) name = "f" + std::to_string(pool_function_index(e));
    *tex = default_tex_name(name);
    return name;
  }

  PNode function(const ex& e) {
    PNode n;
    n.kind = Kind::Function;
    if (auto partial = unknown_partial_of(e)) {   // D[k](integral(...)), no closed form
      n.fname = "D[" + std::to_string(partial->first) + "]";
      n.ftex = "\\partial_{" + std::to_string(partial->first) + "}";
      n.kids = {build(partial->second)};
      n.key = render_key(n);
      return n;
    }
    if (auto v = integral_view(e)) {   // an integral of a declared function (integral_atom.hpp)
      n.fname = "integral";
      n.ftex = "\\int";
      auto end = [&](const ex& x, int inf) {
        if (!inf) return build(x);
        PNode o;
        o.kind = Kind::Symbol;
        o.text = inf > 0 ? "oo" : "-oo";
        o.tex = inf > 0 ? "\\infty" : "-\\infty";
        o.key = o.text;
        return o;
      };
      n.kids = {build(v->f), build(v->t), end(v->a, v->a_inf), end(v->b, v->b_inf)};
      n.key = render_key(n);
      return n;
    }
    n.fname = function_name(e, &n.ftex);
    for (std::size_t i = 0; i < e.nops(); ++i) n.kids.push_back(build(e.op(i)));
    n.key = render_key(n);
    return n;
  }

  PNode derivative(const ex& e) {
    const auto& f = GiNaC::ex_to<GiNaC::fderivative>(e);
    PNode n;
    n.kind = Kind::Derivative;
    n.fname = function_name(e, &n.ftex);
    for (std::size_t i = 0; i < e.nops(); ++i) n.kids.push_back(build(e.op(i)));
    for (unsigned p : f.derivatives()) n.dparams.push_back(p);
    std::sort(n.dparams.begin(), n.dparams.end());
    n.key = render_key(n);
    return n;
  }

 public:
  static std::string render_key(const PNode& n);

 private:
  const SymbolTable& table_;
};

// ---------------------------------------------------------------- rendering

class Renderer {
 public:
  explicit Renderer(Style s) : style_(s) {}

  std::string render(const PNode& n) {
    switch (n.kind) {
      case Kind::Number: return number_text(n.value);
      case Kind::Symbol: return style_ == Style::Text ? n.text : n.tex;
      case Kind::Sum: return sum(n);
      case Kind::Product: return product(n);
      case Kind::Power: return power_alone(n);
      case Kind::Function: return function(n);
      case Kind::Derivative: return derivative(n);
    }
    return {};
  }

 private:
  bool latex() const { return style_ == Style::Latex; }
  std::string lp() const { return latex() ? "\\left(" : "("; }
  std::string rp() const { return latex() ? "\\right)" : ")"; }
  std::string paren(const std::string& s) const { return lp() + s + rp(); }

  std::string sum(const PNode& s) {
    // Display order: the sorted order, but lead with the first positive term if any.
    std::vector<const PNode*> terms;
    for (const auto& t : s.kids) terms.push_back(&t);
    if (!terms.empty() && sign_of(terms.front()->value) < 0) {
      auto it = std::find_if(terms.begin(), terms.end(),
                             [](const PNode* t) { return sign_of(t->value) > 0; });
      if (it != terms.end()) std::rotate(terms.begin(), it, it + 1);
    }
    std::string out;
    for (std::size_t i = 0; i < terms.size(); ++i) {
      const PNode& t = *terms[i];
      bool neg = sign_of(t.value) < 0;
      std::string body = product_magnitude(t);
      if (i == 0) out = neg ? "-" + body : body;
      else out += (neg ? " - " : " + ") + body;
    }
    return out;
  }

  std::string product(const PNode& p) {
    std::string body = product_magnitude(p);
    return sign_of(p.value) < 0 ? "-" + body : body;
  }

  // A factor inside a product (positive exponent).
  std::string factor(const PNode& f) {
    if (f.kind == Kind::Sum) return paren(sum(f));
    if (f.kind == Kind::Power) return power_factor(f.kids[0], f.kids[1]);
    if (f.kind == Kind::Product) {  // a bare number base inside a product: cannot happen here
      std::string s = product(f);
      return f.kids.empty() && sign_of(f.value) > 0 && f.value.is_integer() ? s : paren(s);
    }
    return render(f);
  }

  std::string join_factors(const std::vector<std::string>& fs) {
    std::string out;
    for (const auto& s : fs) {
      if (out.empty()) { out = s; continue; }
      if (!latex()) { out += "*" + s; continue; }
      bool digit = !s.empty() && (std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '-');
      out += digit ? " \\cdot " + s : " " + s;
    }
    return out;
  }

  // |coefficient| * factors, negative powers as a fraction.
  std::string product_magnitude(const PNode& p) {
    numeric c = p.value;
    if (sign_of(c) < 0) c = -c;
    std::vector<std::string> num, den;
    bool complex = !c.is_real();
    if (complex) {
      // i, 2*i, (1+2i): print the coefficient as a whole
      std::string cs;
      numeric re = c.real(), im = c.imag();
      std::string istr = latex() ? "i" : "I";
      auto imag_text = [&](const numeric& v) {
        return v == 1 ? istr : number_text(v) + (latex() ? " " : "*") + istr;
      };
      if (re.is_zero()) cs = imag_text(im);
      else cs = paren(number_text(re) + (im.is_negative() ? " - " : " + ") + imag_text(GiNaC::abs(im)));
      num.push_back(cs);
    } else if (c.is_rational()) {
      if (c.numer() != 1 || p.kids.empty()) num.push_back(int_str(c.numer()));
      if (c.denom() != 1) den.push_back(int_str(c.denom()));
    } else {
      num.push_back(number_text(c));
    }
    // Square roots of several factors merge into one radical: sqrt(2)*sqrt(g*x) -> sqrt(2*g*x).
    std::vector<std::string> root_num, root_den;
    bool bare_num_sum = false, bare_den_sum = false;
    for (const auto& f : p.kids) {
      bool numeric_exp = f.kind == Kind::Power && f.kids[1].kind == Kind::Product && f.kids[1].kids.empty() &&
                         f.kids[1].value.is_real();
      if (numeric_exp && (f.kids[1].value == numeric(1, 2) || f.kids[1].value == numeric(-1, 2))) {
        const PNode& b = f.kids[0];
        bool plain = b.kind == Kind::Product && sign_of(b.value) > 0;  // a product needs no group here
        (f.kids[1].value.is_negative() ? root_den : root_num).push_back(plain ? render(b) : factor(b));
      } else if (numeric_exp && f.kids[1].value.is_negative()) {
        PNode e = f.kids[1];
        e.value = -e.value;
        den.push_back(power_factor(f.kids[0], e));
        bare_den_sum = f.kids[0].kind == Kind::Sum && e.value == 1;
      } else {
        num.push_back(factor(f));
        bare_num_sum = f.kind == Kind::Sum;
      }
    }
    auto radical = [&](const std::vector<std::string>& fs) {
      std::string inner = join_factors(fs);
      return latex() ? "\\sqrt{" + inner + "}" : "sqrt(" + inner + ")";
    };
    if (!root_num.empty()) num.push_back(radical(root_num));
    if (!root_den.empty()) den.push_back(radical(root_den));
    if (num.size() == 1 && num[0] == "1" && !den.empty()) num.clear();
    if (den.empty()) return num.empty() ? "1" : join_factors(num);
    if (latex()) {
      // \frac groups its parts: a lone sum needs no parentheses there
      auto strip = [&](std::vector<std::string>& v, bool bare) {
        if (v.size() == 1 && bare && v[0].rfind(lp(), 0) == 0)
          v[0] = v[0].substr(lp().size(), v[0].size() - lp().size() - rp().size());
      };
      strip(num, bare_num_sum);
      strip(den, bare_den_sum);
    }
    std::string n = num.empty() ? "1" : join_factors(num);
    std::string d = join_factors(den);
    if (latex()) return "\\frac{" + n + "}{" + d + "}";
    bool d_single = den.size() == 1 && (den[0].find_first_of("*/") == std::string::npos || den[0].front() == '(');
    // a*b/c parses as (a*b)/c: the numerator needs no parentheses
    return n + "/" + (d_single ? d : paren(d));
  }

  // base^exponent as a factor; exponent is a Product node (number or general).
  std::string power_factor(const PNode& base, const PNode& expo) {
    bool numeric_exp = expo.kind == Kind::Product && expo.kids.empty() && expo.value.is_real();
    if (numeric_exp && expo.value == 1) return factor_base(base, false);
    if (numeric_exp && expo.value == numeric(1, 2)) {
      std::string inner = render(base);
      return latex() ? "\\sqrt{" + inner + "}" : "sqrt(" + inner + ")";
    }
    if (latex() && base.kind == Kind::Function && base.kids.size() == 1 && numeric_exp &&
        expo.value.is_pos_integer() && trig_head(base.fname)) {
      // \cos^{2} \theta, \sin^{2}\left(a + b\right)
      const PNode& a = base.kids[0];
      std::string head = std::string(trig_head(base.fname)) + "^{" + int_str(expo.value) + "}";
      return atomic_arg(a) ? head + " " + render(a) : head + paren(render(a));
    }
    std::string b = factor_base(base, true);
    std::string e;
    if (numeric_exp && expo.value.is_rational() && !expo.value.is_integer()) {
      e = latex() ? "\\frac{" + int_str(expo.value.numer()) + "}{" + int_str(expo.value.denom()) + "}"
                  : "(" + number_text(expo.value) + ")";
      if (expo.value.is_negative() && !latex()) e = "(" + int_str(expo.value.numer()) + "/" + int_str(expo.value.denom()) + ")";
    } else {
      e = render(expo);
      bool atomic = (numeric_exp && expo.value.is_integer() && !expo.value.is_negative()) ||
                    expo.kind == Kind::Symbol;
      if (!latex() && !atomic) e = paren(e);
    }
    if (latex()) return b + "^{" + e + "}";
    return b + "^" + e;
  }

  // A power base: atoms bare, everything else parenthesized; TeX names with ' or ^ braced.
  std::string factor_base(const PNode& base, bool under_power) {
    if (base.kind == Kind::Symbol) {
      std::string s = render(base);
      if (latex() && under_power && s.find_first_of("'^") != std::string::npos) return "{" + s + "}";
      return s;
    }
    if (base.kind == Kind::Product && base.kids.empty() && base.value.is_integer() &&
        !base.value.is_negative())
      return render(base);
    if (!under_power && (base.kind == Kind::Function || base.kind == Kind::Derivative)) return render(base);
    // f(x)^2 reads unambiguously in text and for declared functions, |x| and roots in LaTeX
    if (base.kind == Kind::Function && (!latex() || (!trig_head(base.fname) && base.fname != "exp")))
      return render(base);
    return paren(render(base));
  }

  std::string power_alone(const PNode& n) {
    const PNode& expo = n.kids[1];
    if (expo.kind == Kind::Product && expo.kids.empty() && expo.value.is_real() && expo.value.is_negative()) {
      PNode p;
      p.kind = Kind::Product;
      p.value = 1;
      p.kids.push_back(n);
      return product_magnitude(p);
    }
    return power_factor(n.kids[0], expo);
  }

  std::string args_text(const PNode& n) {
    std::string out;
    for (std::size_t i = 0; i < n.kids.size(); ++i) {
      if (i) out += ", ";
      out += render(n.kids[i]);
    }
    return out;
  }

  bool atomic_arg(const PNode& a) const {
    return a.kind == Kind::Symbol ||
           (a.kind == Kind::Product && a.kids.empty() && a.value.is_integer() && !a.value.is_negative());
  }

  static const char* trig_head(const std::string& f) {
    static const std::pair<const char*, const char*> kTex[] = {
        {"log", "\\ln"}, {"sin", "\\sin"}, {"cos", "\\cos"}, {"tan", "\\tan"},
        {"asin", "\\arcsin"}, {"acos", "\\arccos"}, {"atan", "\\arctan"},
        {"sinh", "\\sinh"}, {"cosh", "\\cosh"}, {"tanh", "\\tanh"}};
    for (const auto& [g, t] : kTex)
      if (f == g) return t;
    return nullptr;
  }

  std::string function(const PNode& n) {
    if (!latex()) return n.fname + "(" + args_text(n) + ")";
    if (n.fname == "integral" && n.kids.size() == 4)
      return "\\int_{" + render(n.kids[2]) + "}^{" + render(n.kids[3]) + "} " + render(n.kids[0]) + " \\, \\mathrm{d}" +
             render(n.kids[1]);
    if (n.fname == "exp" && n.kids.size() == 1) return "\\mathrm{e}^{" + render(n.kids[0]) + "}";
    if (n.fname == "abs" && n.kids.size() == 1) return "\\left|" + render(n.kids[0]) + "\\right|";
    if (const char* t = trig_head(n.fname); t && n.kids.size() == 1) {
      if (atomic_arg(n.kids[0])) return std::string(t) + " " + render(n.kids[0]);
      return std::string(t) + paren(render(n.kids[0]));
    }
    return n.ftex + "(" + args_text(n) + ")";
  }

  std::string derivative(const PNode& n) {
    // One argument that is a symbol: d^k f / dt^k. Otherwise GiNaC's D[i](f)(args) notation.
    bool single = n.kids.size() == 1 && n.kids[0].kind == Kind::Symbol;
    std::size_t k = n.dparams.size();
    if (single) {
      std::string t = render(n.kids[0]);
      if (!latex()) {
        std::string f = n.fname + "(" + t + ")";
        return "diff(" + f + ", " + t + (k > 1 ? ", " + std::to_string(k) : "") + ")";
      }
      std::string ks = k > 1 ? "^{" + std::to_string(k) + "}" : "";
      return "\\frac{\\mathrm{d}" + ks + " " + n.ftex + "}{\\mathrm{d} " + t + ks + "}";
    }
    std::string idx;
    for (unsigned p : n.dparams) idx += (idx.empty() ? "" : ",") + std::to_string(p);
    if (!latex()) return "D[" + idx + "](" + n.fname + ")(" + args_text(n) + ")";
    if (n.kids.size() == 1) return n.ftex + std::string(k, '\'') + paren(args_text(n));
    return "\\partial_{" + idx + "} " + n.ftex + paren(args_text(n));
  }

  Style style_;
};

std::string Builder::render_key(const PNode& n) { return Renderer(Style::Text).render(n); }

void Builder::finish_product(PNode& p) {
  std::stable_sort(p.kids.begin(), p.kids.end(), [](const PNode& a, const PNode& b) {
    int ra = factor_rank(a), rb = factor_rank(b);
    if (ra != rb) return ra < rb;
    return a.key < b.key;
  });
  p.key = render_key(p);
}

std::string print(const ex& e, const SymbolTable& table, Style style) {
  Builder b(table);
  PNode n = b.build(e);
  return Renderer(style).render(n);
}

}  // namespace

std::string print_text(const GiNaC::ex& e, const SymbolTable& table) {
  return print(e, table, Style::Text);
}

std::string print_latex(const GiNaC::ex& e, const SymbolTable& table) {
  return print(e, table, Style::Latex);
}

std::string print_number(const GiNaC::ex& e, int digits) {
  ex v = e;
  if (!GiNaC::is_a<numeric>(v)) {
    long saved = GiNaC::Digits;
    GiNaC::Digits = std::max<long>(digits + 10, 20);
    try {
      v = GiNaC::evalf(e);
    } catch (...) {
      GiNaC::Digits = saved;
      throw;
    }
    GiNaC::Digits = saved;
    if (!GiNaC::is_a<numeric>(v))
      throw std::invalid_argument("print_number: the expression is not a number");
  }
  const numeric& n = GiNaC::ex_to<numeric>(v);
  auto real_text = [&](const numeric& x) {
    if (x.is_rational()) {
      if (x.is_integer()) return int_str(x);
      return int_str(x.numer()) + "/" + int_str(x.denom());
    }
    return format_real(x, digits);
  };
  if (n.is_real()) return real_text(n);
  numeric re = n.real(), im = n.imag();
  std::string is = real_text(GiNaC::abs(im)) + "*I";
  if (re.is_zero()) return (im.is_negative() ? "-" : "") + is;
  return real_text(re) + (im.is_negative() ? " - " : " + ") + is;
}

std::string text_up_to_sign(std::string t1, std::string t2) {
  const bool n1 = !t1.empty() && t1[0] == '-', n2 = !t2.empty() && t2[0] == '-';
  return (n1 != n2) ? (n1 ? t2 : t1) : std::min(t1, t2);
}

std::string print_text_up_to_sign(const GiNaC::ex& e, const SymbolTable& table) {
  return text_up_to_sign(print_text(e, table), print_text(-e, table));
}

}  // namespace dc
