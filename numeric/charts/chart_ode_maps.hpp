// Stability maps of two scenes whose trouble is not round-off but the model or the events
// (`derivcheck chart maps`, docs/charts.md). Both use the scenes API (numeric/scenes/*.hpp).
//
// Chain from rest (Example 9.7): the handout's v = sqrt(2 g x) read as the first-order ODE
// x' = sqrt(2 g x), x(0) = 0 (chain_first_order_naive) never leaves x = 0 with any one-step
// integrator, so its error is the whole fall g t^2/2; the second-order model x'' = g
// (run_chain) follows the fall. Rows: error of x(t) against g t^2/2 over t.
//
// Event location in the bounce (Example 9.6): the same two-ball bounce as run_bounce (which
// solves its event times exactly), integrated instead with an integrator at step h, the ground
// impact and the ball-ball contact either located by dc::scenes::integrate's secant search
// ("located") or taken at the end of the step in which they happen ("step end"). Rows: relative
// error of the tennis ball's rebound velocity v'1 against run_bounce's, over h.
#pragma once
#include <string>
#include <vector>

#include "numeric/charts/chart_data.hpp"

namespace dc::chart {

struct ChainRow {
  std::string model;    // "first order x' = sqrt(2gx)" | "second order x'' = g"
  std::string method;   // integrator name
  double t = 0;         // [s]
  double x = 0;         // simulated fallen length [m]
  double x_exact = 0;   // g t^2/2 [m]
  double abs_error = 0; // |x - x_exact| [m]
};
// Default chain (m = 1 kg, L = 1 m, g = 9.81), step h; `steps` times log-spaced from t_min to
// the landing time sqrt(2L/g). Throws std::invalid_argument for h <= 0 or steps < 2.
std::vector<ChainRow> chain_from_rest_map(double h, int steps);
Table to_table(const std::vector<ChainRow>& rows);

struct BounceEventRow {
  std::string method;     // integrator name
  std::string location;   // "located" | "step end"
  double h = 0;           // step [s] (dopri5: output spacing, tol 1e-10)
  double v1p = 0;         // rebound velocity of the tennis ball [m/s]
  double v1p_exact = 0;   // run_bounce's (exact event times) [m/s]
  double rel_error = 0;
};
// Default bounce parameters; `steps` step sizes log-spaced from 1e-5 s to 1e-1 s.
std::vector<BounceEventRow> bounce_event_map(int steps);
// One run (exposed for the tests).
BounceEventRow bounce_event_run(const std::string& method, bool located, double h);
Table to_table(const std::vector<BounceEventRow>& rows);

}  // namespace dc::chart
