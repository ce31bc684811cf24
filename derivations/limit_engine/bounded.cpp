// Interval enclosures of oscillating expressions and the dominant part of a sum (see
// internal/bounded.hpp).
#include "derivations/limit_engine/internal/bounded.hpp"

#include "derivations/limit_engine/limits.hpp"

namespace dc::limits {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

std::string fname(const ex& e) {
  return GiNaC::is_a<GiNaC::function>(e) ? GiNaC::ex_to<GiNaC::function>(e).get_name() : std::string();
}

// Failure of an enclosure step (not an exception of the engine).
struct NoBound {};

class Encloser {
 public:
  explicit Encloser(Gruntz& G) : G_(G) {}

  Enclosure operator()(const ex& e) {
    if (!e.has(G_.variable())) return {e, e};
    // a part with a finite limit L lies eventually within |L|/16 of L (within 1/16 of 0):
    // the bounds need to hold for all large x only
    if (!GiNaC::is_a<GiNaC::symbol>(e)) {
      try {
        const LimitValue v = G_.limit(e);
        if (!v.finite()) throw NoBound{};
        const int s = sign(v.value);
        const ex d = s == 0 ? ex(numeric(1, 16)) : s * v.value / 16;
        return {v.value - d, v.value + d};
      } catch (const Oscillates&) {
      }
    }
    const std::string n = fname(e);
    if ((n == "sin" || n == "cos") && e.nops() == 1) return {-1, 1};
    if (n == "atan" && e.nops() == 1) return {-GiNaC::Pi / 2, GiNaC::Pi / 2};
    if (n == "abs" && e.nops() == 1) return abs((*this)(e.op(0)));
    if (n == "log" && e.nops() == 1) {
      const Enclosure u = (*this)(e.op(0));
      if (sign(u.lo) <= 0) throw NoBound{};
      return {GiNaC::log(u.lo), GiNaC::log(u.hi)};
    }
    if (n == "exp" && e.nops() == 1) {
      const Enclosure u = (*this)(e.op(0));
      return {GiNaC::exp(u.lo), GiNaC::exp(u.hi)};
    }
    if (GiNaC::is_a<GiNaC::add>(e)) {
      Enclosure s{0, 0};
      for (std::size_t i = 0; i < e.nops(); ++i) {
        const Enclosure t = (*this)(e.op(i));
        s = {s.lo + t.lo, s.hi + t.hi};
      }
      return s;
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
      Enclosure p{1, 1};
      for (std::size_t i = 0; i < e.nops(); ++i) p = times(p, (*this)(e.op(i)));
      return p;
    }
    if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<numeric>(e.op(1)) && !e.op(1).has(G_.variable())) {
      const numeric& p = GiNaC::ex_to<numeric>(e.op(1));
      if (!p.is_rational()) throw NoBound{};
      Enclosure b = (*this)(e.op(0));
      if (p.is_integer()) {
        if (p.is_negative()) b = inverse(b);
        const numeric m = GiNaC::abs(p);
        if (m.is_even()) b = abs(b);
        // odd powers are increasing; even ones on [0, oo)
        return {GiNaC::pow(b.lo, m), GiNaC::pow(b.hi, m)};
      }
      // a fractional power: real only for a nonnegative base
      if (sign(b.lo) < 0) throw NoBound{};
      if (p.is_positive()) return {GiNaC::pow(b.lo, p), GiNaC::pow(b.hi, p)};
      if (sign(b.lo) <= 0) throw NoBound{};
      return {GiNaC::pow(b.hi, p), GiNaC::pow(b.lo, p)};
    }
    throw NoBound{};
  }

 private:
  Gruntz& G_;

  // the sign of an x-free quantity; NoBound when the declarations do not fix it
  int sign(const ex& c) {
    try {
      return G_.constant_sign(c);
    } catch (const BudgetExceeded&) {
      throw;
    } catch (const Undecided&) {
      throw NoBound{};
    }
  }
  ex min2(const ex& a, const ex& b) { return sign(a - b) <= 0 ? a : b; }
  ex max2(const ex& a, const ex& b) { return sign(a - b) >= 0 ? a : b; }

  Enclosure abs(const Enclosure& u) {
    if (sign(u.lo) >= 0) return u;
    if (sign(u.hi) <= 0) return {-u.hi, -u.lo};
    return {0, max2(-u.lo, u.hi)};
  }
  Enclosure inverse(const Enclosure& u) {
    if (sign(u.lo) > 0 || sign(u.hi) < 0) return {1 / u.hi, 1 / u.lo};
    throw NoBound{};   // the interval contains 0
  }
  Enclosure times(const Enclosure& a, const Enclosure& b) {
    const ex p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
    ex lo = p[0], hi = p[0];
    for (int i = 1; i < 4; ++i) {
      lo = min2(lo, p[i]);
      hi = max2(hi, p[i]);
    }
    return {lo, hi};
  }
};

// A sum split into its dominant part: whole = R*Q, R -> rs*oo, Q -> 1.
struct Split {
  ex whole;
  ex R, Q;
  int rs = 0;   // 0: not split
};

bool oscillates(Gruntz& G, const ex& t) {
  try {
    G.limit(t);
    return false;
  } catch (const Oscillates&) {
    return true;
  }
}

class Dominant {
 public:
  explicit Dominant(Gruntz& G) : G_(G) {}
  bool changed = false;

  Split operator()(const ex& e) {
    DepthGuard guard(G_.budget(), "dominant part");
    const ex& x = G_.variable();
    if (!e.has(x) || GiNaC::is_a<GiNaC::symbol>(e)) return {e};
    if (GiNaC::is_a<GiNaC::add>(e)) {
      ex sum = 0;
      for (std::size_t i = 0; i < e.nops(); ++i) sum += (*this)(e.op(i)).whole;
      return split_sum(sum);
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
      ex p = 1;
      for (std::size_t i = 0; i < e.nops(); ++i) p *= (*this)(e.op(i)).whole;
      return {p};
    }
    if (GiNaC::is_a<GiNaC::power>(e)) {
      const ex p = e.op(1);
      const Split b = (*this)(e.op(0));
      if (p.has(x)) return {GiNaC::pow(b.whole, (*this)(p).whole)};
      // (R Q)^p = R^p Q^p: for an integer p always, else for R > 0 (Q -> 1 is positive for large x)
      if (b.rs != 0 && (p.info(GiNaC::info_flags::integer) || b.rs > 0))
        return {GiNaC::pow(b.R, p) * GiNaC::pow(b.Q, p)};
      return {GiNaC::pow(b.whole, p)};
    }
    if (GiNaC::is_a<GiNaC::function>(e)) {
      if (fname(e) == "log" && e.nops() == 1) {
        const Split b = (*this)(e.op(0));
        if (b.rs > 0) return {GiNaC::log(b.R) + GiNaC::log(b.Q)};
        return {GiNaC::log(b.whole)};
      }
      struct Args : GiNaC::map_function {
        Dominant& d;
        explicit Args(Dominant& d_) : d(d_) {}
        ex operator()(const ex& a) override { return d(a).whole; }
      } args(*this);
      return {e.map(args)};
    }
    return {e};
  }

 private:
  Gruntz& G_;

  Split split_sum(const ex& sum) {
    if (!GiNaC::is_a<GiNaC::add>(sum)) return {sum};
    ex R = 0, O = 0;
    for (std::size_t i = 0; i < sum.nops(); ++i) (oscillates(G_, sum.op(i)) ? O : R) += sum.op(i);
    if (O.is_zero() || R.is_zero()) return {sum};
    int rs = 0;
    try {
      const LimitValue r = G_.limit(R);
      if (r.finite()) return {sum};
      rs = r.kind == LimitValue::Kind::PlusInfinity ? 1 : -1;
      // O/R -> 0: the oscillating part is negligible next to R
      const LimitOutcome q = reduce_oscillation(G_, O / R);
      if (q.kind != LimitOutcome::Kind::Value || G_.constant_sign(q.value) != 0) return {sum};
    } catch (const BudgetExceeded&) {
      throw;
    } catch (const Undecided&) {
      return {sum};
    } catch (const Oscillates&) {
      return {sum};
    }
    changed = true;
    const ex Q = 1 + O / R;
    return {R * Q, R, Q, rs};
  }
};

}  // namespace

std::optional<Enclosure> enclose(Gruntz& G, const ex& e) {
  try {
    return Encloser(G)(e);
  } catch (const NoBound&) {
    return std::nullopt;
  } catch (const BudgetExceeded&) {
    throw;
  } catch (const Undecided&) {
    return std::nullopt;
  } catch (const std::exception&) {
    return std::nullopt;   // GiNaC on an endpoint (a pole)
  }
}

ex factor_dominant(Gruntz& G, const ex& e, bool& changed) {
  Dominant d(G);
  const ex out = d(e).whole;
  changed = d.changed;
  return out;
}

}  // namespace dc::limits
