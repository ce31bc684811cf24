// make_tractable: the exp-log form Gruntz's algorithm works on (see gruntz.hpp).
#include <string>

#include "derivations/symbolic/inspect.hpp"
#include "derivations/limit_engine/gruntz.hpp"

namespace dc::limits {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

bool is_exp(const ex& e) {
  return GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "exp";
}

// b^p with p depending on x: exp(p log b). b must be positive near the point for a real
// value; a numeric base <= 0 is refused here (log would be complex).
ex variable_power(const ex& b, const ex& p) {
  if (is_exp(b)) return GiNaC::exp(b.op(0) * p);
  if (GiNaC::is_a<numeric>(b)) {
    const numeric& n = GiNaC::ex_to<numeric>(b);
    if (n.is_equal(1)) return 1;
    if (!n.is_real() || !n.is_positive())
      throw Undecided("a power of a non-positive number with a variable exponent has no real value in general");
  }
  return GiNaC::exp(p * GiNaC::log(b));
}

class Tractable {
 public:
  explicit Tractable(const ex& x) : x_(x) {}

  ex operator()(const ex& e) {
    if (!e.has(x_)) return e;
    if (GiNaC::is_a<GiNaC::add>(e)) {
      ex s = 0;
      for (std::size_t i = 0; i < e.nops(); ++i) s += (*this)(e.op(i));
      return s;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
      ex s = 1;
      for (std::size_t i = 0; i < e.nops(); ++i) s *= (*this)(e.op(i));
      return s;
    }
    if (GiNaC::is_a<GiNaC::power>(e)) {
      ex b = (*this)(e.op(0)), p = (*this)(e.op(1));
      if (p.has(x_)) return (*this)(variable_power(b, p));
      if (is_exp(b)) return GiNaC::exp(b.op(0) * p);
      return GiNaC::pow(b, p);
    }
    if (GiNaC::is_a<GiNaC::function>(e)) return function(e);
    if (GiNaC::is_a<GiNaC::symbol>(e)) return e;
    throw Undecided("the limit algorithm does not handle this kind of expression");
  }

 private:
  ex x_;

  ex function(const ex& e) {
    if (detail::is_abstract_application(e))
      throw Undecided("the limit of an expression with the undetermined function " +
                      GiNaC::ex_to<GiNaC::function>(e).get_name() + " cannot be decided");
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if (e.nops() != 1)
      throw Undecided("the limit algorithm does not handle the function " + name + " of several arguments");
    ex u = (*this)(e.op(0));
    if (name == "exp") return GiNaC::exp(u);
    if (name == "log") return GiNaC::log(u);
    if (name == "tan") return GiNaC::sin(u) / GiNaC::cos(u);   // poles: where cos -> 0
    // asin and acos through atan, so that their branch points +-1 are expanded like any
    // other point (acos(x)/sqrt(1 - x) as x -> 1-): both identities hold on (-1, 1), and
    // for |u| > 1 the square roots are not real, as asin and acos are not
    if (name == "asin") return GiNaC::atan(u / GiNaC::sqrt(1 - GiNaC::pow(u, 2)));
    if (name == "acos") return 2 * GiNaC::atan(GiNaC::sqrt((1 - u) / (1 + u)));
    if (name == "sin" || name == "cos" || name == "atan" || name == "abs")
      return GiNaC::function(GiNaC::ex_to<GiNaC::function>(e).get_serial(), u);
    if (name == "sinh") return (*this)((GiNaC::exp(u) - GiNaC::exp(-u)) / 2);
    if (name == "cosh") return (*this)((GiNaC::exp(u) + GiNaC::exp(-u)) / 2);
    if (name == "tanh") return (*this)(1 - 2 / (GiNaC::exp(2 * u) + 1));
    if (name == "asinh") return GiNaC::log(u + GiNaC::sqrt(GiNaC::pow(u, 2) + 1));
    if (name == "acosh") return GiNaC::log(u + GiNaC::sqrt(GiNaC::pow(u, 2) - 1));
    if (name == "atanh") return (GiNaC::log(1 + u) - GiNaC::log(1 - u)) / 2;
    throw Undecided("the limit algorithm does not handle the function " + name);
  }
};

}  // namespace

ex make_tractable(const ex& f, const ex& x) { return Tractable(x)(f); }

}  // namespace dc::limits
