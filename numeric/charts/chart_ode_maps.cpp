#include "numeric/charts/chart_ode_maps.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "numeric/scenes/scenes.hpp"

namespace dc::chart {

namespace sc = dc::scenes;

namespace {
std::vector<double> logspace(double a, double b, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(a * std::pow(b / a, n == 1 ? 0.0 : static_cast<double>(i) / (n - 1)));
  return v;
}
}  // namespace

std::vector<ChainRow> chain_from_rest_map(double h, int steps) {
  if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument("chain map: h = " + fmt(h) + " s is out of bounds: need h > 0");
  if (steps < 2) throw std::invalid_argument("chain map: steps = " + std::to_string(steps) + " is out of bounds: need >= 2");
  const auto& spec = sc::find_scene("chain");
  sc::Params p = sc::defaults(spec);
  const double g = p.at("g"), L = p.at("L");
  p["x"] = L;   // report at the landing: the run then covers the whole fall
  const double t_land = std::sqrt(2 * L / g);
  const auto ts = logspace(std::max(h, t_land * 1e-3), t_land, steps);
  std::vector<ChainRow> out;
  for (sc::Method m : {sc::Method::euler, sc::Method::rk4, sc::Method::dopri5, sc::Method::rosenbrock}) {
    for (double t : ts) {
      ChainRow r;
      r.model = "first order x' = sqrt(2gx)";
      r.method = std::string(sc::method_name(m));
      r.t = t;
      r.x = sc::chain_first_order_naive(g, m, h, t);
      r.x_exact = 0.5 * g * t * t;
      r.abs_error = std::abs(r.x - r.x_exact);
      out.push_back(r);
    }
  }
  for (sc::Method m : spec.methods) {
    sc::RunOptions o;
    o.method = m;
    o.h = h;
    const sc::SceneResult res = sc::run_scene(spec, p, o);
    const auto& cols = res.series.columns;
    const auto ti = static_cast<std::size_t>(std::find(cols.begin(), cols.end(), "t") - cols.begin());
    const auto xi = static_cast<std::size_t>(std::find(cols.begin(), cols.end(), "x") - cols.begin());
    if (ti >= cols.size() || xi >= cols.size()) throw std::logic_error("chain scene series lacks t or x");
    // the sample nearest to each t of the grid (samples are h apart)
    for (double t : ts) {
      const std::vector<double>* best = nullptr;
      for (const auto& row : res.series.rows)
        if (!best || std::abs(row[ti] - t) < std::abs((*best)[ti] - t)) best = &row;
      if (!best) continue;
      ChainRow r;
      r.model = "second order x'' = g";
      r.method = std::string(sc::method_name(m));
      r.t = (*best)[ti];
      r.x = (*best)[xi];
      r.x_exact = 0.5 * g * r.t * r.t;
      r.abs_error = std::abs(r.x - r.x_exact);
      if (!out.empty() && out.back().model == r.model && out.back().method == r.method && out.back().t == r.t) continue;
      out.push_back(r);
    }
  }
  return out;
}

Table to_table(const std::vector<ChainRow>& rows) {
  Table t;
  t.columns = {"model", "method", "t_s", "x_m", "x_exact_m", "abs_error_m"};
  for (const auto& r : rows) t.rows.push_back({r.model, r.method, fmt(r.t), fmt(r.x), fmt(r.x_exact), fmt(r.abs_error)});
  return t;
}

BounceEventRow bounce_event_run(const std::string& method, bool located, double h) {
  if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument("bounce map: h = " + fmt(h) + " s is out of bounds: need h > 0");
  const auto& spec = sc::find_scene("bounce");
  const sc::Params p = sc::defaults(spec);
  const double m1 = p.at("m1"), m2 = p.at("m2"), r1 = p.at("r1"), r2 = p.at("r2"), y2 = p.at("y2"), s = p.at("s"),
               e2 = p.at("e2"), e12 = p.at("e12"), g = p.at("g");
  const sc::Method m = sc::parse_method(method);
  // state: y1, y2, v1, v2; free fall of both balls
  sc::OdeSystem sys;
  sys.dim = 4;
  sys.rhs = [g](const sc::State& x, sc::State& d, double) {
    d[0] = x[2], d[1] = x[3], d[2] = -g, d[3] = -g;
  };
  sys.jacobian = [](const sc::State&, std::vector<double>& J, sc::State& dfdt, double) {
    J.assign(16, 0.0);
    J[0 * 4 + 2] = 1, J[1 * 4 + 3] = 1;
    std::fill(dfdt.begin(), dfdt.end(), 0.0);
  };
  sys.n_pos = 2;
  sys.accel = [g](const double*, double* a, double) { a[0] = -g, a[1] = -g; };
  sc::Integrator ig(m, sys, 1e-10);
  sc::State x = {y2 + r2 + r1 + s, y2, 0, 0};
  auto ground = [r2](const sc::State& u, double) { return u[1] - r2; };
  auto contact = [r1, r2](const sc::State& u, double) { return u[0] - u[1] - (r1 + r2); };
  const double t_guard = 100;
  double t = 0;
  auto until = [&](const std::function<double(const sc::State&, double)>& ev) {
    if (located) {
      t = sc::integrate(ig, x, t, t + t_guard, h, ev).t;
      return;
    }
    // no location: the event is noticed at the end of the step in which it happened
    for (long n = 0; ev(x, t) > 0; ++n) {
      if (n > 100000000) throw std::runtime_error("bounce map: no event");
      ig.advance(x, t, h);
      t += h;
    }
  };
  until(ground);
  x[1] = r2;            // on the ground, as in run_bounce
  x[3] = -e2 * x[3];
  until(contact);
  const sc::DirectImpact imp = sc::solve_direct_impact(m1, m2, x[2], x[3], e12);
  BounceEventRow r;
  r.method = method;
  r.location = located ? "located" : "step end";
  r.h = h;
  r.v1p = imp.v1p;
  r.v1p_exact = sc::run_bounce(p, sc::RunOptions{}).get("v1p").simulated;
  r.rel_error = std::abs(r.v1p - r.v1p_exact) / std::abs(r.v1p_exact);
  return r;
}

std::vector<BounceEventRow> bounce_event_map(int steps) {
  if (steps < 2) throw std::invalid_argument("bounce map: steps = " + std::to_string(steps) + " is out of bounds: need >= 2");
  std::vector<BounceEventRow> out;
  for (const char* m : {"euler", "rk4", "dopri5", "verlet", "rosenbrock"})
    for (bool located : {true, false})
      for (double h : logspace(1e-5, 1e-1, steps)) out.push_back(bounce_event_run(m, located, h));
  return out;
}

Table to_table(const std::vector<BounceEventRow>& rows) {
  Table t;
  t.columns = {"method", "location", "h_s", "v1p_m_per_s", "v1p_exact_m_per_s", "rel_error"};
  for (const auto& r : rows) t.rows.push_back({r.method, r.location, fmt(r.h), fmt(r.v1p), fmt(r.v1p_exact), fmt(r.rel_error)});
  return t;
}

}  // namespace dc::chart
