// THE CLOSED FORMS THE SCENES ARE COMPARED WITH — the one place they are typed by hand.
//
// Each function cites the handout equation it implements and the derivation-file label that
// derives it (derivations/handout9/FILE.dc, LABEL). Where a derivation file defines the label,
// closed_form_value() evaluates the derived formula instead (see closed_forms.cpp), and the
// hand-typed version below serves only as the fallback and as a cross-check.
#pragma once
#include <map>
#include <string>

namespace dc::scenes::cf {

// Example 9.3: centre-of-mass velocity of the two masses (P = m v_G, §9.2).
double v_G(double m1, double m2, double v1, double v2);

// §9.3.1 general impact (from (9.6) and (9.7)).
double v1p_general(double m1, double m2, double v1, double v2, double e);
double v2p_general(double m1, double m2, double v1, double v2, double e);
// ΔT = (1-e²)/2 · m1 m2/(m1+m2) · (v1-v2)²  (loss of kinetic energy)
double dT_general(double m1, double m2, double v1, double v2, double e);

// Example 9.5: common velocity after the perfectly inelastic impact, m v0 = (M+m) v1.
double pendulum_v1(double m, double M, double v0);
// θ = arccos(1 - (m/(M+m))² v0²/(2Lg)). Evaluated in the half-angle form
// θ = 2 asin( m v0 / ((M+m) · 2 sqrt(gL)) ), equal since 1 - cos θ = 2 sin²(θ/2): for small v0
// the acos argument rounds towards 1 and acos keeps only about half the digits.
double pendulum_theta(double m, double M, double v0, double L, double g);
double pendulum_theta_naive(double m, double M, double v0, double L, double g);  // the acos form

// Example 9.6 (v0 < 0: the velocity of both balls at the ground impact).
double bounce_v0(double y2, double r2, double g);   // v0 = -sqrt(2 g (y2 - r2))
double bounce_v1p(double mu, double e2, double e12, double v0);  // (mu - e2 - e12(1+e2))/(mu+1) v0
double bounce_v2p(double mu, double e2, double e12, double v0);  // (mu - e2 + mu e12(1+e2))/(mu+1) v0

// §9.4: v = -u_e ln(m_r/m0) - g t, with m_r = m0 - mu t; evaluated as -u_e log1p(-mu t/m0) - g t
// (for mu t << m0 the quotient m_r/m0 rounds near 1 and ln keeps few digits).
double rocket_v(double m0, double mu, double u_e, double g, double t);

// Example 9.7: v = sqrt(2 g x) and N = 3 x m g / L.
double chain_v(double g, double x);
double chain_N(double m, double L, double g, double x);

// Example 9.2 (θ measured from the floor): the ladder leaves the wall at sin θ = 2/3 sin θ0,
// with the horizontal momentum m v_Gx = (m/3) sqrt(g l) sin^{3/2} θ0 imparted by the wall.
double ladder_theta_sep(double theta0);
double ladder_wall_impulse(double m, double l, double g, double theta0);

// Example 9.1: v_p/v_c = m_c/m_p, T_p/T_c = m_c/m_p.
double cannon_velocity_ratio(double m_p, double m_c);

// Where each closed form comes from: label -> "derivations/handout9/FILE.dc:LABEL" (what the
// lead's derivation files are asked to define).
const std::map<std::string, std::string>& derivation_labels();

}  // namespace dc::scenes::cf
