// The scenes' run functions (registered in spec.cpp's table) and the few typed helpers the
// tests use directly. Each scene lives in its own .cpp under numeric/scenes/.
#pragma once
#include "numeric/scenes/spec.hpp"

namespace dc::scenes {

SceneResult run_spring(const Params& p, const RunOptions& opt);      // spring.cpp
SceneResult run_pendulum(const Params& p, const RunOptions& opt);    // pendulum.cpp
SceneResult run_bounce(const Params& p, const RunOptions& opt);      // bounce.cpp
SceneResult run_rocket(const Params& p, const RunOptions& opt);      // rocket.cpp
SceneResult run_chain(const Params& p, const RunOptions& opt);       // chain.cpp
SceneResult run_ladder(const Params& p, const RunOptions& opt);      // ladder.cpp
SceneResult run_cradle(const Params& p, const RunOptions& opt);      // cradle.cpp
SceneResult run_cannon(const Params& p, const RunOptions& opt);      // cannon.cpp
SceneResult run_impact(const Params& p, const RunOptions& opt);      // impact.cpp
SceneResult run_oblique(const Params& p, const RunOptions& opt);     // impact.cpp

void check_pendulum(const Params& p);   // the swing must stay at or below the horizontal

// Example 9.3, exact solution of the linear model (for global errors): the spring's extension
// s = x2 - x1 - L0 obeys s'' = -omega² s, omega² = k (m1 + m2)/(m1 m2), s(0) = 0,
// s'(0) = v0, while x_G moves uniformly. Returns {x1, x2, v1, v2} at t.
struct SpringState { double x1, x2, v1, v2; };
SpringState spring_exact(const Params& p, double t);

// Example 9.7's naive first-order model x' = sqrt(2 g x) from x(0) = 0, integrated with `m`
// and step h to t_end: returns x(t_end). x ≡ 0 solves it too, and every one-step method
// starting at x = 0 evaluates sqrt(0) = 0 at all stages, so this stays exactly 0.
double chain_first_order_naive(double g, Method m, double h, double t_end);

// §9.3.1 impacts solved as linear systems with Eigen (independent of the closed forms):
// (9.6) m1 v1 + m2 v2 = m1 v'1 + m2 v'2 and (9.7) v'2 - v'1 = e (v1 - v2).
struct DirectImpact { double v1p, v2p; };
DirectImpact solve_direct_impact(double m1, double m2, double v1, double v2, double e);
// §9.3.2: momentum in n, momentum in t for each particle, restitution in n (4 equations).
struct ObliqueImpact { double v1n, v1t, v2n, v2t; };
ObliqueImpact solve_oblique_impact(double m1, double m2, double v1n, double v1t, double v2n,
                                   double v2t, double e);

}  // namespace dc::scenes
