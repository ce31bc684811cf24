// The scenes' integrators: Boost.Odeint steppers behind dc::scenes::Integrator (the only
// translation unit of the scenes that includes odeint).
#include "numeric/scenes/integrators.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <Eigen/Dense>
#include <boost/numeric/odeint.hpp>

namespace dc::scenes {

namespace odeint = boost::numeric::odeint;

namespace {

// odeint's rosenbrock4 step (Shampine's 4th-order L-stable Rosenbrock scheme, the coefficients of
// boost::numeric::odeint::default_rosenbrock_coefficients), ported line by line to Eigen:
// Boost 1.74's ublas, which odeint's rosenbrock4 is built on, does not compile as C++20
// (it calls std::allocator::construct, removed in C++20).
struct Rosenbrock4 {
  static constexpr double gamma = 0.25, d1 = 0.25, d2 = -0.1043, d3 = 0.1035, d4 = 0.3620000000000023e-01,
                          c2 = 0.386, c3 = 0.21, c4 = 0.63, c21 = -0.5668800000000000e+01,
                          a21 = 0.1544000000000000e+01, c31 = -0.2430093356833875e+01,
                          c32 = -0.2063599157091915e+00, a31 = 0.9466785280815826e+00,
                          a32 = 0.2557011698983284e+00, c41 = -0.1073529058151375e+00,
                          c42 = -0.9594562251023355e+01, c43 = -0.2047028614809616e+02,
                          a41 = 0.3314825187068521e+01, a42 = 0.2896124015972201e+01,
                          a43 = 0.9986419139977817e+00, c51 = 0.7496443313967647e+01,
                          c52 = -0.1024680431464352e+02, c53 = -0.3399990352819905e+02,
                          c54 = 0.1170890893206160e+02, a51 = 0.1221224509226641e+01,
                          a52 = 0.6019134481288629e+01, a53 = 0.1253708332932087e+02,
                          a54 = -0.6878860361058950e+00, c61 = 0.8083246795921522e+01,
                          c62 = -0.7981132988064893e+01, c63 = -0.3152159432874371e+02,
                          c64 = 0.1631930543123136e+02, c65 = -0.6058818238834054e+01;

  // f(x, t) -> dxdt; jac(x, t) -> (J, df/dt)
  template <class F, class Jac>
  static void step(F&& f, Jac&& jac, Eigen::VectorXd& x, double t, double dt) {
    const Eigen::Index n = x.size();
    Eigen::VectorXd dxdt(n), dfdt(n), fnew(n), xtmp(n);
    Eigen::MatrixXd J(n, n);
    f(x, dxdt, t);
    jac(x, J, dfdt, t);
    const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(n, n) / (gamma * dt) - J;
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(A);
    const Eigen::VectorXd g1 = lu.solve(dxdt + dt * d1 * dfdt);
    xtmp = x + a21 * g1;
    f(xtmp, fnew, t + c2 * dt);
    const Eigen::VectorXd g2 = lu.solve(fnew + dt * d2 * dfdt + c21 * g1 / dt);
    xtmp = x + a31 * g1 + a32 * g2;
    f(xtmp, fnew, t + c3 * dt);
    const Eigen::VectorXd g3 = lu.solve(fnew + dt * d3 * dfdt + (c31 * g1 + c32 * g2) / dt);
    xtmp = x + a41 * g1 + a42 * g2 + a43 * g3;
    f(xtmp, fnew, t + c4 * dt);
    const Eigen::VectorXd g4 = lu.solve(fnew + dt * d4 * dfdt + (c41 * g1 + c42 * g2 + c43 * g3) / dt);
    xtmp = x + a51 * g1 + a52 * g2 + a53 * g3 + a54 * g4;
    f(xtmp, fnew, t + dt);
    const Eigen::VectorXd g5 = lu.solve(fnew + (c51 * g1 + c52 * g2 + c53 * g3 + c54 * g4) / dt);
    xtmp += g5;
    f(xtmp, fnew, t + dt);
    const Eigen::VectorXd err = lu.solve(fnew + (c61 * g1 + c62 * g2 + c63 * g3 + c64 * g4 + c65 * g5) / dt);
    x = xtmp + err;
  }
};

}  // namespace

std::string_view method_name(Method m) {
  switch (m) {
    case Method::euler: return "euler";
    case Method::rk4: return "rk4";
    case Method::dopri5: return "dopri5";
    case Method::verlet: return "verlet";
    case Method::rosenbrock: return "rosenbrock";
  }
  return "?";
}

Method parse_method(std::string_view name) {
  for (Method m : {Method::euler, Method::rk4, Method::dopri5, Method::verlet, Method::rosenbrock})
    if (method_name(m) == name) return m;
  throw std::invalid_argument("unknown method '" + std::string(name) +
                              "'; methods: euler, rk4, dopri5, verlet, rosenbrock");
}

int method_order(Method m) {
  switch (m) {
    case Method::euler: return 1;
    case Method::rk4: return 4;
    case Method::dopri5: return 5;
    case Method::verlet: return 2;
    case Method::rosenbrock: return 4;
  }
  return 0;
}

struct Integrator::Impl {
  using Dopri = odeint::controlled_runge_kutta<odeint::runge_kutta_dopri5<State>>;
  odeint::euler<State> euler;
  odeint::runge_kutta4<State> rk4;
  Dopri dopri;
  double dopri_dt = 0;  // the controller's last step suggestion, kept between advances
  // verlet
  std::vector<double> acc, acc_tmp;
  // rosenbrock scratch
  State sx, sd;

  explicit Impl(double tol) : dopri(odeint::default_error_checker<double, odeint::range_algebra,
                                                                   odeint::default_operations>(tol, tol)) {}
};

Integrator::Integrator(Method m, OdeSystem sys, double tol)
    : method_(m), sys_(std::move(sys)), evals_(std::make_shared<long>(0)), impl_(std::make_unique<Impl>(tol)) {
  if (!sys_.rhs) throw std::invalid_argument("integrator: the system has no right-hand side");
  if (m == Method::verlet && (!sys_.accel || sys_.n_pos == 0 || 2 * sys_.n_pos != sys_.dim))
    throw std::invalid_argument(
        "method verlet needs a second-order system x'' = a(x, t) with no further components");
  if (!(tol > 0) || !std::isfinite(tol))
    throw std::domain_error("tolerance tol = " + std::to_string(tol) + " is out of bounds: need tol > 0");
}

Integrator::~Integrator() = default;

void Integrator::advance(State& x, double t, double h) {
  long* evals = evals_.get();
  auto rhs = [this, evals](const State& s, State& d, double tt) {
    ++*evals;
    sys_.rhs(s, d, tt);
  };
  switch (method_) {
    case Method::euler:
      impl_->euler.do_step(rhs, x, t, h);
      return;
    case Method::rk4:
      impl_->rk4.do_step(rhs, x, t, h);
      return;
    case Method::dopri5: {
      // The FSAL derivative cached by the controller belongs to the state it last produced;
      // callers may restart from another state (event location), so start afresh.
      impl_->dopri.reset();
      double dt = impl_->dopri_dt > 0 ? impl_->dopri_dt : h / 10;
      double tt = t;
      const double t_end = t + h;
      for (;;) {
        bool last = false;
        if (tt + dt >= t_end) {
          dt = t_end - tt;
          last = true;
        }
        int fails = 0;
        while (impl_->dopri.try_step(rhs, x, tt, dt) == odeint::fail) {
          last = false;  // retried with a smaller step: not yet at t_end
          if (++fails > 500) throw std::runtime_error("dopri5: step size underflow");
        }
        if (last) break;
        impl_->dopri_dt = dt;  // the controller's suggestion for the next step
      }
      return;
    }
    case Method::verlet: {
      // velocity Verlet: v += h/2 a(q); q += h v; v += h/2 a(q_new)  (one acceleration per step)
      const std::size_t n = sys_.n_pos;
      auto& a = impl_->acc;
      a.resize(n);
      ++*evals;
      sys_.accel(x.data(), a.data(), t);
      for (std::size_t i = 0; i < n; ++i) x[n + i] += 0.5 * h * a[i];
      for (std::size_t i = 0; i < n; ++i) x[i] += h * x[n + i];
      ++*evals;
      sys_.accel(x.data(), a.data(), t + h);
      for (std::size_t i = 0; i < n; ++i) x[n + i] += 0.5 * h * a[i];
      return;
    }
    case Method::rosenbrock: {
      const std::size_t n = sys_.dim;
      auto& sx = impl_->sx;
      auto& sd = impl_->sd;
      sx.resize(n);
      sd.resize(n);
      auto deriv = [&](const Eigen::VectorXd& s, Eigen::VectorXd& d, double tt) {
        std::copy(s.data(), s.data() + n, sx.begin());
        ++*evals;
        sys_.rhs(sx, sd, tt);
        std::copy(sd.begin(), sd.end(), d.data());
      };
      auto jacobi = [&](const Eigen::VectorXd& s, Eigen::MatrixXd& J, Eigen::VectorXd& dfdt, double tt) {
        State xs(s.data(), s.data() + n), ft(n, 0.0);
        std::vector<double> jac(n * n, 0.0);
        if (sys_.jacobian) {
          sys_.jacobian(xs, jac, ft, tt);
        } else {
          // central differences, step ~ cbrt(eps) scaled by the component
          State fp(n), fm(n);
          for (std::size_t j = 0; j < n; ++j) {
            const double d = 6e-6 * std::max(1.0, std::abs(xs[j]));
            State xp = xs, xm = xs;
            xp[j] += d;
            xm[j] -= d;
            sys_.rhs(xp, fp, tt);
            sys_.rhs(xm, fm, tt);
            *evals += 2;
            for (std::size_t i = 0; i < n; ++i) jac[i * n + j] = (fp[i] - fm[i]) / (2 * d);
          }
          const double dtt = 6e-6 * std::max(1.0, std::abs(tt));
          sys_.rhs(xs, fp, tt + dtt);
          sys_.rhs(xs, fm, tt - dtt);
          *evals += 2;
          for (std::size_t i = 0; i < n; ++i) ft[i] = (fp[i] - fm[i]) / (2 * dtt);
        }
        for (std::size_t i = 0; i < n; ++i) {
          dfdt[i] = ft[i];
          for (std::size_t j = 0; j < n; ++j) J(i, j) = jac[i * n + j];
        }
      };
      Eigen::VectorXd ex = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(n));
      Rosenbrock4::step(deriv, jacobi, ex, t, h);
      std::copy(ex.data(), ex.data() + n, x.begin());
      return;
    }
  }
}

EventResult integrate(Integrator& ig, State& x, double t0, double t_end, double h,
                      const std::function<double(const State&, double)>& event,
                      const std::function<void(const State&, double)>& observer) {
  if (!(h > 0) || !std::isfinite(h))
    throw std::domain_error("step h = " + std::to_string(h) + " s is out of bounds: need h > 0");
  EventResult r;
  double t = t0;
  if (observer) observer(x, t);
  double g_prev = event ? event(x, t) : 1.0;
  State x_prev;
  while (t < t_end) {
    double step = std::min(h, t_end - t);
    if (t_end - (t + step) < 1e-12 * h) step = t_end - t;  // do not leave a sliver
    x_prev = x;
    ig.advance(x, t, step);
    ++r.steps;
    const double t_new = t + step;
    if (event) {
      const double g_new = event(x, t_new);
      if (g_prev > 0 && g_new <= 0) {
        // secant (regula falsi, Illinois variant) on the length s of the last step: g(s) = 0
        double a = 0, b = step, ga = g_prev, gb = g_new;
        State xs;
        int side = 0;
        const double scale = std::max(std::abs(g_prev), std::abs(g_new));
        double s = b;
        for (int it = 0; it < 80; ++it) {
          s = (ga * b - gb * a) / (ga - gb);
          if (!(s > a && s < b)) s = 0.5 * (a + b);
          xs = x_prev;
          if (s > 0) ig.advance(xs, t, s);
          const double gs = event(xs, t + s);
          if (std::abs(gs) <= 1e-15 * scale || b - a <= 1e-15 * std::max(1.0, std::abs(t))) break;
          if (gs > 0) {
            a = s, ga = gs;
            if (side == 1) gb *= 0.5;
            side = 1;
          } else {
            b = s, gb = gs;
            if (side == -1) ga *= 0.5;
            side = -1;
          }
        }
        x = xs;
        t = t + s;
        r.event = true;
        if (observer) observer(x, t);
        r.t = t;
        return r;
      }
      g_prev = g_new;
    }
    t = t_new;
    if (observer) observer(x, t);
  }
  r.t = t;
  return r;
}

}  // namespace dc::scenes
