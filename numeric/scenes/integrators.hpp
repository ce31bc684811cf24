// Time integrators for the scenes, behind one small interface so that Boost.Odeint (slow to
// compile: ~2.7 s per translation unit) is included only by integrators.cpp.
//
//   euler       explicit Euler (odeint euler), order 1; unstable for any h on an undamped
//               oscillator (amplification sqrt(1 + (omega h)^2) per step)
//   rk4         classical Runge-Kutta (odeint runge_kutta4), order 4, fixed step
//   dopri5      Dormand-Prince 5(4) with step-size control (odeint runge_kutta_dopri5,
//               controlled, abs = rel = tol); h is then only the output spacing
//   verlet      velocity Verlet, order 2, symplectic (needs a second-order system whose
//               acceleration does not depend on the velocities); stable for omega h < 2
//   rosenbrock  odeint rosenbrock4's scheme (linearly implicit, order 4, L-stable), fixed step,
//               ported to Eigen (Boost 1.74's ublas does not compile as C++20); needs the
//               Jacobian (analytic if the system gives one, else central differences)
#pragma once
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace dc::scenes {

enum class Method { euler, rk4, dopri5, verlet, rosenbrock };

std::string_view method_name(Method m);
// Throws std::invalid_argument("unknown method 'x'; methods: euler, rk4, dopri5, verlet, rosenbrock").
Method parse_method(std::string_view name);
int method_order(Method m);   // 1, 4, 5, 2, 4

using State = std::vector<double>;

// A first-order system x' = f(x, t) of dimension `dim`.
struct OdeSystem {
  std::size_t dim = 0;
  std::function<void(const State& x, State& dxdt, double t)> rhs;
  // Optional Jacobian df/dx, row-major dim x dim, and df/dt (for rosenbrock).
  std::function<void(const State& x, std::vector<double>& jac, State& dfdt, double t)> jacobian;
  // Optional second-order form (for verlet): the first n_pos components are positions q, the
  // next n_pos their velocities (q' = v); accel(q, a, t) gives v' = a(q, t). Any further
  // components (quadratures) are not supported by verlet.
  std::size_t n_pos = 0;
  std::function<void(const double* q, double* a, double t)> accel;
};

class Integrator {
 public:
  // tol: dopri5's absolute and relative tolerance (ignored by the fixed-step methods).
  // Throws std::invalid_argument if the method cannot integrate this system (verlet without
  // a second-order form).
  Integrator(Method m, OdeSystem sys, double tol = 1e-10);
  ~Integrator();
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;

  // Advance x from t to t + h: one fixed step (euler, rk4, verlet, rosenbrock) or an adaptive
  // integration over [t, t+h] (dopri5).
  void advance(State& x, double t, double h);

  Method method() const { return method_; }
  const OdeSystem& system() const { return sys_; }
  long rhs_evaluations() const { return *evals_; }

 private:
  struct Impl;
  Method method_;
  OdeSystem sys_;
  std::shared_ptr<long> evals_;
  std::unique_ptr<Impl> impl_;
};

// Integrate with step h from t0 until t_end (the last step is shortened to land on t_end), or
// until event(x, t) changes sign from its value at t0 (strictly: from > 0 to <= 0). The event
// time is then located by the secant method on the length of the last step, to |g| <= 1e-14
// relative (or 60 iterations), so it is as accurate as the integrator. observer(x, t) is called
// at t0, after each step and at the end. Returns the final time; x holds the final state.
struct EventResult {
  double t = 0;
  bool event = false;   // stopped by the event
  long steps = 0;
};
EventResult integrate(Integrator& ig, State& x, double t0, double t_end, double h,
                      const std::function<double(const State&, double)>& event = nullptr,
                      const std::function<void(const State&, double)>& observer = nullptr);

}  // namespace dc::scenes
