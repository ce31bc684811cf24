#!/usr/bin/env python3
"""Writes tests/data/adversarial.jsonl and checks every expectation independently.

Each claim is checked here with mpmath at high precision, outside derivcheck:
  * expect "false": the given witness lies in the declared domain (domains and the `assume`
    relations hold there) and the two sides differ there: both are real and differ clearly at
    the claim's working precision, or exactly one side is real (the other is undefined over the
    reals: log or a fractional power of a negative number, asin/acos outside [-1, 1]).
  * expect "true": at many random points of the declared domain (magnitudes 1e-10..1e10 and
    1e-300..1e300, both signs as the domain allows; points that violate an `assume` relation
    are redrawn) both sides are real and agree to the working precision.
Semantics (as in derivcheck): symbols are real; an expression is defined where it is real,
with principal branches; a claim is true on its domain when both sides are defined and equal
at every point outside a lower-dimensional set (isolated removable singularities such as x/x
at 0 are allowed).

Usage: python3 tools/gen-adversarial-corpus.py [--check-only]   (needs mpmath and sympy)
"""
import json
import random
import re
import sys
from pathlib import Path

import mpmath
from mpmath import mp, mpf
import sympy
from sympy.parsing.sympy_parser import parse_expr

OUT = Path(__file__).resolve().parent.parent / "tests" / "data" / "adversarial.jsonl"

CLAIMS = []


def claim(cls, expect, id, lhs, rhs, why, doms=None, assume=None, w=None, kind="equal", dps=120, mag=2, **extra):
    """mag and dps only steer the independent check below: random points for true claims have
    magnitudes 10^[-mag, mag] (the identities are elementary; a huge magnitude only tests mpmath),
    evaluated with dps digits."""
    CLAIMS.append(dict(cls=cls, expect=expect, id=id, lhs=lhs, rhs=rhs, why=why, doms=doms or {},
                       assume=assume, w=w, kind=kind, dps=dps, mag=mag, extra=extra))


POS = "positive"
REAL = "real"

# ---------------------------------------------------------------- degenerate / nice points
D = "degenerate"
claim(D, "false", "deg_square_is_x", "x^2", "x", "agrees at x = 0 and x = 1 only", {"x": REAL}, w={"x": "2"})
claim(D, "false", "deg_cube_is_x", "x^3", "x", "agrees at -1, 0, 1", {"x": REAL}, w={"x": "1/2"})
claim(D, "false", "deg_sin_integers", "sin(pi*x)", "0", "zero at every integer, nowhere else", {"x": REAL},
      w={"x": "1/2"})
claim(D, "false", "deg_cos_integers", "cos(2*pi*x)", "1", "one at every integer, nowhere else", {"x": REAL},
      w={"x": "1/2"})
claim(D, "false", "deg_poly_integers", "x*(x-1)*(x-2)*(x-3)*(x-4)*(x-5)*(x-6)*(x-7)*(x-8)*(x-9) + x", "x",
      "agrees at the integers 0..9", {"x": REAL}, w={"x": "1/2"})
claim(D, "false", "deg_equal_masses_exchange", "((m1-m2)*v1+2*m2*v2)/(m1+m2)", "v2",
      "velocities are exchanged only when m1 = m2", {"m1": POS, "m2": POS, "v1": REAL, "v2": REAL},
      w={"m1": "2", "m2": "1", "v1": "1", "v2": "0"})
claim(D, "false", "deg_equal_masses_reduced", "m1*m2/(m1+m2)", "m1/2", "the reduced mass is m1/2 only for m1 = m2",
      {"m1": POS, "m2": POS}, w={"m1": "1", "m2": "2"})
claim(D, "false", "deg_equal_masses_ratio", "(m1-m2)/(m1+m2)", "0", "zero only for equal masses",
      {"m1": POS, "m2": POS}, w={"m1": "2", "m2": "1"})
claim(D, "false", "deg_e0_v1p", "(m1*v1+m2*v2-e*m2*(v1-v2))/(m1+m2)", "(m1*v1+m2*v2)/(m1+m2)",
      "the plastic result; agrees only at e = 0 or v1 = v2", {"m1": POS, "m2": POS, "v1": REAL, "v2": REAL, "e": "in [0, 1]"},
      w={"m1": "1", "m2": "1", "v1": "1", "v2": "0", "e": "1/2"})
claim(D, "false", "deg_e_square", "e^2", "e", "agrees at both ends e = 0 and e = 1 of the declared interval",
      {"e": "in [0, 1]"}, w={"e": "1/2"})
claim(D, "false", "deg_energy_loss_1me", "1/2*m1*m2/(m1+m2)*(1-e^2)*(v1-v2)^2", "1/2*m1*m2/(m1+m2)*(1-e)*(v1-v2)^2",
      "1 - e^2 versus 1 - e: agrees at e = 0, e = 1 and v1 = v2",
      {"m1": POS, "m2": POS, "v1": REAL, "v2": REAL, "e": "in [0, 1]"},
      w={"m1": "1", "m2": "1", "v1": "1", "v2": "0", "e": "1/2"})
claim(D, "false", "deg_sqrt_1me2", "sqrt(1-e^2)", "1-e^2", "agrees at e = 0 and e = 1", {"e": "in [0, 1]"},
      w={"e": "1/2"})
claim(D, "false", "deg_vanishes_at_v1_eq_v2", "(v1-v2)^2*(m1+m2)", "0", "zero only when v1 = v2",
      {"m1": POS, "m2": POS, "v1": REAL, "v2": REAL}, w={"m1": "1", "m2": "1", "v1": "1", "v2": "0"})
claim(D, "false", "deg_relvel_e_squared",
      "(m1*v1+m2*v2+e*m1*(v1-v2))/(m1+m2) - (m1*v1+m2*v2-e*m2*(v1-v2))/(m1+m2)", "e^2*(v1-v2)",
      "restitution gives e*(v1-v2); e^2 agrees at e = 0, 1 and v1 = v2",
      {"m1": POS, "m2": POS, "v1": REAL, "v2": REAL, "e": "in [0, 1]"},
      w={"m1": "1", "m2": "1", "v1": "1", "v2": "0", "e": "1/2"})
claim(D, "false", "deg_binomial_one_off",
      "(x+y)^10",
      "x^10+10*x^9*y+45*x^8*y^2+120*x^7*y^3+210*x^6*y^4+251*x^5*y^5+210*x^4*y^6+120*x^3*y^7+45*x^2*y^8+10*x*y^9+y^10",
      "one binomial coefficient is 251 instead of 252: agrees whenever x = 0 or y = 0", {"x": REAL, "y": REAL},
      w={"x": "1", "y": "1"})
claim(D, "false", "deg_cube_of_difference", "(v1-v2)^3", "v1^3-v2^3", "agrees at v1 = v2, v1 = 0 or v2 = 0",
      {"v1": REAL, "v2": REAL}, w={"v1": "2", "v2": "1"})
claim(D, "false", "deg_orbit_any_angle", "a*(1-e^2)/(1+e*cos(theta))", "a*(1-e)",
      "the perihelion distance: true at theta = 0 (and for e = 0) only",
      {"a": POS, "e": "in [0, 1)", "theta": REAL}, w={"a": "1", "e": "1/2", "theta": "3"})
claim(D, "false", "deg_two_to_x", "2^x", "x^2", "agrees at x = 2 and x = 4", {"x": POS}, w={"x": "3"})
claim(D, "false", "deg_exp_linear", "exp(x)", "1 + x", "agrees at x = 0 (tangent there)", {"x": REAL},
      w={"x": "1"})
claim(D, "false", "deg_pendulum_swapped", "2*pi*sqrt(l/g)", "2*pi*sqrt(g/l)", "agrees when l = g",
      {"l": POS, "g": POS}, w={"l": "1", "g": "4"})
claim(D, "false", "deg_rocket_log_vs_ratio", "u*log(m0/m1)", "u*(m0-m1)/m1", "agrees at m0 = m1 (first order only)",
      {"u": POS, "m0": POS, "m1": POS}, w={"u": "1", "m0": "2", "m1": "1"})
claim(D, "false", "deg_quartic_trig", "sin(x)^4 + cos(x)^4", "1 - sin(x)^2*cos(x)^2",
      "agrees at multiples of pi/2 (the factor is 2, not 1)", {"x": REAL}, w={"x": "1"})
claim(D, "false", "deg_x_pow_y", "x^y", "y^x", "agrees on the diagonal x = y (and at 2, 4)", {"x": POS, "y": POS},
      w={"x": "2", "y": "3"})
claim(D, "false", "deg_near_degenerate_shift", "(x + 10^(-10))^2", "x^2 + 2*10^(-10)*x",
      "the dropped term is 10^-20: near-degenerate, never zero", {"x": REAL}, w={"x": "1"})
claim(D, "false", "deg_narrow_spike", "x + 1/(1 + 10^40*(x - 1/3)^2)", "x",
      "a spike of height 1 and width 1e-20 at x = 1/3; elsewhere the difference is below 1e-38", {"x": REAL},
      w={"x": "1/3"})
claim(D, "true", "deg_true_energy_fractions", "(m1-m2)^2/(m1+m2)^2 + 4*m1*m2/(m1+m2)^2", "1",
      "(m1-m2)^2 + 4 m1 m2 = (m1+m2)^2", {"m1": POS, "m2": POS})
claim(D, "true", "deg_true_perihelion", "a*(1-e^2)/(1+e)", "a*(1-e)", "1 - e^2 = (1-e)(1+e)",
      {"a": POS, "e": "in [0, 1]"})
claim(D, "true", "deg_true_restitution",
      "(m1*v1+m2*v2+e*m1*(v1-v2))/(m1+m2) - (m1*v1+m2*v2-e*m2*(v1-v2))/(m1+m2)", "e*(v1-v2)",
      "relative velocity after impact from the general impact formulas",
      {"m1": POS, "m2": POS, "v1": REAL, "v2": REAL, "e": "in [0, 1]"})
claim(D, "true", "deg_true_momentum",
      "m1*(m1*v1+m2*v2-e*m2*(v1-v2))/(m1+m2) + m2*(m1*v1+m2*v2+e*m1*(v1-v2))/(m1+m2)", "m1*v1+m2*v2",
      "momentum is conserved for every e", {"m1": POS, "m2": POS, "v1": REAL, "v2": REAL, "e": "in [0, 1]"})
claim(D, "true", "deg_true_energy_loss",
      "1/2*m1*v1^2+1/2*m2*v2^2-1/2*m1*((m1*v1+m2*v2-e*m2*(v1-v2))/(m1+m2))^2-1/2*m2*((m1*v1+m2*v2-e*m1*(v2-v1))/(m1+m2))^2",
      "(1-e^2)/2*m1*m2/(m1+m2)*(v1-v2)^2", "kinetic energy lost in a partially elastic impact",
      {"m1": POS, "m2": POS, "v1": REAL, "v2": REAL, "e": "in [0, 1]"})
claim(D, "true", "deg_true_binomial",
      "(x+y)^10",
      "x^10+10*x^9*y+45*x^8*y^2+120*x^7*y^3+210*x^6*y^4+252*x^5*y^5+210*x^4*y^6+120*x^3*y^7+45*x^2*y^8+10*x*y^9+y^10",
      "the binomial theorem", {"x": REAL, "y": REAL})
claim(D, "true", "deg_true_removable", "(x^2-1)/(x-1)", "x+1", "removable singularity at x = 1 only",
      {"x": REAL})
claim(D, "true", "deg_true_cube_quotient", "(x^3-y^3)/(x-y)", "x^2+x*y+y^2", "removable on the line x = y",
      {"x": REAL, "y": REAL})
claim(D, "true", "deg_true_x_over_x", "x/x", "1", "an isolated removable singularity at 0 is a side condition, not a counterexample",
      {"x": REAL})
claim(D, "true", "deg_true_equal_masses_written", "((m-m)*v1+2*m*v2)/(m+m)", "v2",
      "equal masses written out: the exchange is right", {"m": POS, "v1": REAL, "v2": REAL})
claim(D, "true", "deg_true_geometric", "(x^20-1)/(x-1)",
      "1+x+x^2+x^3+x^4+x^5+x^6+x^7+x^8+x^9+x^10+x^11+x^12+x^13+x^14+x^15+x^16+x^17+x^18+x^19",
      "geometric sum, high degree, removable at x = 1", {"x": REAL})
claim(D, "true", "deg_true_elastic_e1", "(m1*v1+m2*v2-m2*(v1-v2))/(m1+m2)", "((m1-m2)*v1+2*m2*v2)/(m1+m2)",
      "e = 1 substituted by hand", {"m1": POS, "m2": POS, "v1": REAL, "v2": REAL})

# ---------------------------------------------------------------- overflow / precision loss
P = "precision"
claim(P, "false", "prec_exp_tower", "exp(exp(exp(10)))", "1", "about 10^(10^9565); overflows every float format", dps=60)
claim(P, "false", "prec_sin_huge_argument", "sin(10^400*x)", "0",
      "an argument beyond the working precision must not evaluate to 0", {"x": REAL}, w={"x": "1"}, dps=900)
claim(P, "false", "prec_exp_huge_positive", "exp(10^300*x)", "1", "overflows double; never 1 for x > 0",
      {"x": POS}, w={"x": "1/2"})
claim(P, "false", "prec_one_plus_tiny", "1 + 10^(-40)", "1", "relative difference 1e-40, below a 1e-30 tolerance")
claim(P, "false", "prec_ramanujan_163", "exp(pi*sqrt(163))", "640320^3 + 744", "differs by 7.5e-13 (relative 2.9e-30)")
claim(P, "false", "prec_ramanujan_67", "exp(pi*sqrt(67))", "5280^3 + 744", "differs by 1.3e-6")
claim(P, "false", "prec_ramanujan_58", "exp(pi*sqrt(58))", "396^4 - 104", "differs by 1.8e-7")
claim(P, "false", "prec_exp_pi_minus_pi", "exp(pi) - pi", "20", "19.99909997918947...")
claim(P, "false", "prec_golden_power", "((1+sqrt(5))/2)^40", "228826127", "the Lucas number L40; phi^40 alone is 4.4e-9 short")
claim(P, "false", "prec_sin_2017", "sin(2017*2^(1/5))", "-1", "-0.99999999999999997857 (differs by 2e-17)")
claim(P, "false", "prec_exp_neg_huge_zero", "exp(-10^300*x)", "0",
      "underflows to 0 in every float format but exp is never 0", {"x": POS}, w={"x": "1/2"})
claim(P, "false", "prec_x_plus_tiny", "x + 10^(-40)", "x", "absolute difference 1e-40 everywhere", {"x": REAL},
      w={"x": "1"})
claim(P, "false", "prec_cos_tiny_argument", "cos(10^(-40)*x)", "1",
      "1 - cos(1e-40 x) is about 5e-81 x^2: below any relative tolerance unless x is huge", {"x": REAL},
      w={"x": "1"}, dps=300)
claim(P, "false", "prec_cancellation", "(10^30 + sqrt(2)*x)^2 - 10^60 - 2*10^30*sqrt(2)*x", "0",
      "the left side is 2 x^2, but only after cancelling terms of size 1e60", {"x": REAL}, w={"x": "1"})
claim(P, "false", "prec_near_zero_product", "x^2", "(x + 10^(-20))*(x - 10^(-20))",
      "differs by exactly 1e-40: relative difference 1e-40 at x = 1", {"x": REAL}, w={"x": "1"})
claim(P, "false", "prec_log1p_tiny_interval", "log(1+x)", "x",
      "on (0, 1e-40) the relative difference is about x/2 < 5e-41, yet never zero", {"x": "in (0, 10^(-40))"},
      w={"x": "10^(-41)"}, dps=200)
claim(P, "false", "prec_sqrt_cancel_huge", "sqrt(x^2+1) - x", "0",
      "about 1/(2x): cancels to 0 at any fixed precision once x > 1e25", {}, assume="x > 10^200",
      w={"x": "2*10^200"}, dps=700)
claim(P, "false", "prec_tan_near_pole", "tan(pi/2 - 10^(-30))", "10^30",
      "cot(1e-30) = 1e30 - 3.3e-31: relative difference 3e-61", dps=200)
claim(P, "false", "prec_sin_odd_multiple_pi", "sin((10^60+1)*pi + 1/2)", "sin(1/2)",
      "an odd multiple of pi flips the sign; 50 digits cannot see the argument's fractional part", dps=200)
claim(P, "false", "prec_exp_huge_shift", "exp(10^20)", "exp(10^20 + 10^(-40))",
      "relative difference 1e-40 between two numbers near 10^(4.3e19)", dps=200)
claim(P, "true", "prec_true_exp_cancel", "exp(10^300*x)*exp(-10^300*x)", "1", "overflow times underflow is exactly 1",
      {"x": POS}, dps=60, mag=300)
claim(P, "true", "prec_true_log_exp", "log(exp(x))", "x", "exp(x) > 0 for real x", {"x": REAL})
claim(P, "true", "prec_true_log_exp_huge", "log(exp(10^300*x))", "10^300*x", "exp(x) > 0 for real x; huge exponents",
      {"x": REAL}, dps=700)
claim(P, "true", "prec_true_tiny_exact", "(1 + 10^(-40))^2", "1 + 2*10^(-40) + 10^(-80)", "exact rational arithmetic")
claim(P, "true", "prec_true_huge_cancel", "(10^300 + x)^2 - 10^600 - 2*10^300*x", "x^2",
      "cancellation of terms of size 1e600", {"x": REAL}, dps=1000, mag=8)
claim(P, "true", "prec_true_lucas", "((1+sqrt(5))/2)^20 + ((1-sqrt(5))/2)^20", "15127",
      "L20 = 15127 although phi^20 alone is a near-integer")
claim(P, "true", "prec_true_sin_even_multiple_pi", "sin(10^60*pi + x)", "sin(x)",
      "10^60 pi is an even multiple of pi; the argument needs > 60 digits", {"x": REAL}, dps=400)
claim(P, "true", "prec_true_pythagoras_huge", "sin(10^400*x)^2 + cos(10^400*x)^2", "1",
      "sin^2 + cos^2 = 1 at any argument", {"x": REAL}, dps=1000)
claim(P, "true", "prec_true_conjugate", "sqrt(x^2+1) - x", "1/(sqrt(x^2+1)+x)",
      "each side cancels catastrophically on one sign of x", {"x": REAL}, dps=1300)
claim(P, "true", "prec_true_exp_ratio", "exp(10^300*x + 1)/exp(10^300*x)", "exp(1)", "overflow over overflow",
      {"x": POS}, dps=400)
claim(P, "true", "prec_true_scaled_product", "(10^(-200)*x)*(10^200*y)", "x*y", "tiny times huge", {"x": REAL, "y": REAL})
claim(P, "true", "prec_true_denest", "sqrt(5+2*sqrt(6))", "sqrt(2)+sqrt(3)", "a nested radical that denests")
claim(P, "true", "prec_true_log_tower", "log(exp(exp(exp(10))))", "exp(exp(10))", "log of a tower with 10^9565 digits",
      dps=60)
claim(P, "true", "prec_true_cot_near_zero", "tan(pi/2 - x)", "1/tan(x)",
      "near the pole: pi/2 - x loses the digits of x at fixed precision", {"x": "in (0, 10^(-30))"}, dps=300)
claim(P, "true", "prec_true_exp_sum_huge", "exp(10^20)*exp(10^(-20))", "exp(10^20 + 10^(-20))",
      "exp(a) exp(b) = exp(a + b) with a huge and b tiny", dps=200)
claim(P, "false", "prec_cos_tiny_interval", "cos(x)", "1", "1 - cos x < 5e-41 on (0, 1e-20), but never 0",
      {"x": "in (0, 10^(-20))"}, w={"x": "10^(-21)"}, dps=200)
claim(P, "false", "prec_sin_tiny_interval", "sin(x)", "x", "x - sin x is about x^3/6: relative 2e-31 on (0, 1e-15)",
      {"x": "in (0, 10^(-15))"}, w={"x": "10^(-16)"}, dps=200)
claim(P, "true", "prec_true_double_angle_tiny", "sin(x)^2", "(1-cos(2*x))/2",
      "1 - cos(2x) cancels to 0 at 50 digits for x < 1e-60", {"x": "in (0, 10^(-60))"}, dps=300)
claim(P, "true", "prec_true_half_angle_tiny", "1 - cos(x)", "2*sin(x/2)^2", "1 - cos x cancels completely for x < 1e-30",
      {"x": "in (0, 10^(-30))"}, dps=300)
claim(P, "true", "prec_true_log_difference", "log(1+x) - log(x)", "log(1+1/x)",
      "the left side cancels catastrophically for huge x", {"x": POS}, dps=700, mag=300)
claim(P, "true", "prec_true_huge_argument_square", "cos(10^30*x)^2", "(1+cos(2*10^30*x))/2",
      "double angle at arguments of size 1e30", {"x": REAL}, dps=200)
claim(P, "false", "prec_cubic_correction", "x + 10^(-100)*x^3", "x",
      "relative difference 1e-100 x^2: below 1e-30 unless |x| > 1e35, yet nonzero for every x != 0", {"x": REAL},
      w={"x": "1"}, dps=300)
claim(P, "false", "prec_sqrt_tiny_shift", "sqrt(x^2 + 10^(-80))", "abs(x)", "differs visibly only for |x| below 1e-35",
      {"x": REAL}, w={"x": "10^(-40)"}, dps=300)
claim(P, "true", "prec_true_softplus", "log(exp(x) + 1) - x", "log(1 + exp(-x))",
      "the left side cancels catastrophically for large x; the right side is about exp(-x)", {"x": REAL}, dps=300, mag=2)

# ---------------------------------------------------------------- partial-domain identities
PD = "partial_domain"
claim(PD, "false", "pd_log_product_real", "log(a*b)", "log(a)+log(b)",
      "for a, b < 0 the left side is real and the right side is not", {"a": REAL, "b": REAL},
      w={"a": "-1", "b": "-2"})
claim(PD, "false", "pd_sqrt_product_real", "sqrt(x*y)", "sqrt(x)*sqrt(y)",
      "for x, y < 0 the left side is real and the right side is not (or -sqrt(xy) with complex values)",
      {"x": REAL, "y": REAL}, w={"x": "-1", "y": "-2"})
claim(PD, "false", "pd_sqrt_square_real", "sqrt(x^2)", "x", "sqrt(x^2) = |x|", {"x": REAL}, w={"x": "-1"})
claim(PD, "false", "pd_acos_cos_real", "acos(cos(x))", "x", "acos returns [0, pi]", {"x": REAL}, w={"x": "-1"})
claim(PD, "false", "pd_acos_cos_0_2pi", "acos(cos(x))", "x", "on (pi, 2 pi] acos(cos x) = 2 pi - x",
      {"x": "in [0, 2*pi]"}, w={"x": "4"})
claim(PD, "false", "pd_asin_sin_real", "asin(sin(x))", "x", "asin returns [-pi/2, pi/2]", {"x": REAL}, w={"x": "2"})
claim(PD, "false", "pd_atan_tan_real", "atan(tan(x))", "x", "atan returns (-pi/2, pi/2)", {"x": REAL}, w={"x": "2"})
claim(PD, "false", "pd_power_power_real", "(x^a)^b", "x^(a*b)", "x = -1, a = 2, b = 1/2: 1 versus -1",
      {"x": REAL, "a": REAL, "b": REAL}, w={"x": "-1", "a": "2", "b": "1/2"})
claim(PD, "false", "pd_square_power_real", "(x^2)^b", "x^(2*b)",
      "for x < 0 the left side is real and the right side is not (b not an integer)", {"x": REAL, "b": REAL},
      w={"x": "-1", "b": "1/4"})
claim(PD, "false", "pd_exp_log_real", "exp(log(x))", "x",
      "log(x) is not real for x < 0 (only the complex principal branch gives back x)", {"x": REAL}, w={"x": "-1"})
claim(PD, "false", "pd_atan_reciprocal_real", "atan(x) + atan(1/x)", "pi/2", "it is -pi/2 for x < 0", {"x": REAL},
      w={"x": "-1"})
claim(PD, "false", "pd_abs_real", "abs(x)", "x", "|x| = -x for x < 0", {"x": REAL}, w={"x": "-1"})
claim(PD, "false", "pd_log_square_real", "log(x^2)", "2*log(x)", "for x < 0 the right side is not real",
      {"x": REAL}, w={"x": "-1"})
claim(PD, "false", "pd_sqrt_x2y", "sqrt(x^2*y)", "x*sqrt(y)", "it is |x| sqrt(y)", {"x": REAL, "y": POS},
      w={"x": "-1", "y": "1"})
claim(PD, "false", "pd_sqrt_1mcos2_real", "sqrt(1-cos(x)^2)", "sin(x)", "it is |sin x|", {"x": REAL}, w={"x": "-1"})
claim(PD, "false", "pd_sqrt_1msin2_0pi", "sqrt(1-sin(x)^2)", "cos(x)", "it is |cos x|; cos < 0 on (pi/2, pi)",
      {"x": "in (0, pi)"}, w={"x": "2"})
claim(PD, "false", "pd_atan_addition_positive", "atan(x)+atan(y)", "atan((x+y)/(1-x*y))",
      "valid only when x y < 1", {"x": POS, "y": POS}, w={"x": "2", "y": "2"})
claim(PD, "false", "pd_acos_double_asin_sym", "acos(1-2*z^2)", "2*asin(z)", "for z < 0 the right side is negative",
      {"z": "in [-1, 1]"}, w={"z": "-1/2"})
claim(PD, "false", "pd_acos_atan", "acos(x)", "atan(sqrt(1-x^2)/x)", "for x < 0 they differ by pi",
      {"x": "in (-1, 1)"}, w={"x": "-1/2"})
claim(PD, "false", "pd_power_3_2", "(x^2)^(3/2)", "x^3", "it is |x|^3", {"x": REAL}, w={"x": "-1"})
claim(PD, "false", "pd_abs_sum", "abs(x+y)", "abs(x)+abs(y)", "only when x, y have the same sign",
      {"x": REAL, "y": REAL}, w={"x": "1", "y": "-1"})
claim(PD, "false", "pd_sqrt_perfect_square", "sqrt(x^2 - 2*x + 1)", "x - 1", "it is |x - 1|", {"x": REAL},
      w={"x": "0"})
claim(PD, "false", "pd_series_abs_negative", "abs(x)", "x", "for x < 0, |x| = -x: the series must respect the branch",
      {"x": "negative"}, kind="series_first_order", var="x", point="0", w={"x": "-1/10"})
claim(PD, "false", "pd_limit_abs_over_x_negative", "abs(x)/x", "1", "approached from x < 0 the limit is -1",
      {"x": "negative"}, kind="limit", var="x", point="0", w={"x": "-1/10"})
claim(PD, "false", "pd_antiderivative_abs", "abs(x)", "x^2/2", "d/dx x^2/2 = x, not |x|, for x < 0",
      {"x": REAL}, kind="antiderivative", var="x", w={"x": "-1"})
claim(PD, "false", "pd_asin_sin_shift_wrong_range", "asin(sin(x))", "pi - x", "valid on [pi/2, 3 pi/2] only",
      {"x": "in [0, pi]"}, w={"x": "1/2"})
claim(PD, "true", "pd_true_log_product", "log(a*b)", "log(a)+log(b)", "a, b > 0", {"a": POS, "b": POS})
claim(PD, "true", "pd_true_sqrt_product", "sqrt(x*y)", "sqrt(x)*sqrt(y)", "x, y >= 0",
      {"x": "nonnegative", "y": "nonnegative"})
claim(PD, "true", "pd_true_sqrt_square", "sqrt(x^2)", "x", "x > 0", {"x": POS})
claim(PD, "true", "pd_true_sqrt_abs", "sqrt(x^2)", "abs(x)", "every real x", {"x": REAL})
claim(PD, "true", "pd_true_acos_cos", "acos(cos(x))", "x", "x in [0, pi]", {"x": "in [0, pi]"})
claim(PD, "true", "pd_true_asin_sin", "asin(sin(x))", "x", "x in [-pi/2, pi/2]", {"x": "in [-pi/2, pi/2]"})
claim(PD, "true", "pd_true_asin_sin_shift", "asin(sin(x))", "pi - x", "x in [pi/2, 3 pi/2]",
      {"x": "in [pi/2, 3*pi/2]"})
claim(PD, "true", "pd_true_atan_tan", "atan(tan(x))", "x", "x in (-pi/2, pi/2)", {"x": "in (-pi/2, pi/2)"})
claim(PD, "true", "pd_true_atan_tan_shift", "atan(tan(x))", "x - pi", "x in (pi/2, 3 pi/2)",
      {"x": "in (pi/2, 3*pi/2)"})
claim(PD, "true", "pd_true_power_power", "(x^a)^b", "x^(a*b)", "x > 0", {"x": POS, "a": REAL, "b": REAL})
claim(PD, "true", "pd_true_exp_log", "exp(log(x))", "x", "x > 0", {"x": POS})
claim(PD, "true", "pd_true_atan_reciprocal", "atan(x) + atan(1/x)", "pi/2", "x > 0", {"x": POS})
claim(PD, "true", "pd_true_atan_reciprocal_negative", "atan(x) + atan(1/x)", "-pi/2", "x < 0", {"x": "negative"})
claim(PD, "true", "pd_true_abs_nonnegative", "abs(x)", "x", "x >= 0", {"x": "nonnegative"})
claim(PD, "true", "pd_true_power_abs", "(x^2)^(3/2)", "abs(x)^3", "every real x", {"x": REAL})
claim(PD, "true", "pd_true_acos_double_asin", "acos(1-2*z^2)", "2*asin(z)", "z in [0, 1]", {"z": "in [0, 1]"})
claim(PD, "true", "pd_true_atan_addition_unit", "atan(x)+atan(y)", "atan((x+y)/(1-x*y))", "x, y in (-1, 1): x y < 1",
      {"x": "in (-1, 1)", "y": "in (-1, 1)"})
claim(PD, "true", "pd_true_acos_atan", "acos(x)", "atan(sqrt(1-x^2)/x)", "x in (0, 1]", {"x": "in (0, 1]"})
claim(PD, "true", "pd_true_sqrt_1mcos2", "sqrt(1-cos(x)^2)", "sin(x)", "sin x >= 0 on [0, pi]", {"x": "in [0, pi]"})
claim(PD, "true", "pd_true_series_abs_positive", "abs(x)", "x", "|x| = x for x > 0",
      {"x": POS}, kind="series_first_order", var="x", point="0")
claim(PD, "true", "pd_true_limit_abs_over_x_positive", "abs(x)/x", "1", "approached from x > 0",
      {"x": POS}, kind="limit", var="x", point="0")
claim(PD, "true", "pd_true_antiderivative_log_abs", "1/x", "log(abs(x))", "d/dx log|x| = 1/x on both signs",
      {"x": REAL}, kind="antiderivative", var="x")
claim(PD, "true", "pd_true_sqrt_x2y", "sqrt(x^2*y)", "x*sqrt(y)", "x > 0, y >= 0", {"x": POS, "y": "nonnegative"})
claim(PD, "true", "pd_true_asin_plus_acos", "asin(x) + acos(x)", "pi/2", "x in [-1, 1]", {"x": "in [-1, 1]"})
claim(PD, "true", "pd_true_power_sum", "x^(a+b)", "x^a*x^b", "x > 0", {"x": POS, "a": REAL, "b": REAL})
claim(PD, "true", "pd_true_abs_product", "abs(x*y)", "abs(x)*abs(y)", "every real x, y", {"x": REAL, "y": REAL})
claim(PD, "false", "pd_atan_double_beyond_one", "2*atan(x)", "atan(2*x/(1-x^2)) + pi", "valid for x > 1 only",
      {"x": REAL}, w={"x": "1/2"})
claim(PD, "true", "pd_true_acos_half_angle", "acos(x)", "2*asin(sqrt((1-x)/2))", "x in [-1, 1]", {"x": "in [-1, 1]"})
claim(PD, "true", "pd_true_atan_as_asin", "atan(x)", "asin(x/sqrt(1+x^2))", "every real x", {"x": REAL})
claim(PD, "false", "pd_acos_cos_rational_end", "acos(cos(x))", "x",
      "355/113 > pi: on (pi, 355/113], a sliver of width 2.7e-7, acos(cos x) = 2 pi - x", {"x": "in [0, 355/113]"},
      w={"x": "355/113"})
claim(PD, "true", "pd_true_acos_cos_rational_end", "acos(cos(x))", "x", "311/99 < pi", {"x": "in [0, 311/99]"})
claim(PD, "false", "pd_asin_sin_decimal_end", "asin(sin(x))", "x",
      "1.5708 > pi/2 by 3.7e-6: near the ends asin(sin x) = pi - x or -pi - x", {"x": "in [-1.5708, 1.5708]"},
      w={"x": "1.5708"})
claim(PD, "true", "pd_true_asin_as_atan", "asin(x)", "atan(x/sqrt(1-x^2))", "x in (-1, 1)", {"x": "in (-1, 1)"})
claim(PD, "true", "pd_true_cos_asin", "cos(asin(x))", "sqrt(1-x^2)", "cos is >= 0 on [-pi/2, pi/2]", {"x": "in [-1, 1]"})
claim(PD, "true", "pd_true_cos_atan", "cos(atan(x))", "1/sqrt(1+x^2)", "every real x", {"x": REAL})
claim(PD, "false", "pd_sin_acos", "sin(acos(x))", "x", "it is sqrt(1 - x^2); agrees only at x = 1/sqrt(2)",
      {"x": "in [-1, 1]"}, w={"x": "0"})

# ---------------------------------------------------------------- assumptions
A = "assumptions"
claim(A, "false", "as_sqrt_square_negative", "sqrt(x^2)", "x", "x < 0: sqrt(x^2) = -x", assume="x < 0", w={"x": "-1"})
claim(A, "false", "as_abs_wrong_sign", "abs(x - y)", "y - x", "x > y makes |x - y| = x - y", assume="x > y",
      w={"x": "1", "y": "0"})
claim(A, "false", "as_exp_neg_large_zero", "exp(-x)", "0", "exp(-x) > 0 even for x > 10^6", assume="x > 1000000",
      w={"x": "2000000"}, mag=10)
claim(A, "false", "as_atan_large", "atan(x)", "pi/2", "atan(x) < pi/2; off by about 1/x", assume="x > 1000000",
      w={"x": "2000000"})
claim(A, "false", "as_reciprocal_large", "1/x", "0", "small, not zero", assume="x > 1000000", w={"x": "2000000"})
claim(A, "false", "as_sqrt_cancel_large", "sqrt(x^2+1) - x", "0", "about 1/(2x) > 0", assume="x > 1000000",
      w={"x": "2000000"})
claim(A, "false", "as_compound_interest", "(1+1/x)^x", "exp(1)", "e (1 - 1/(2x) + ...): a limit, not an identity",
      assume="x > 1000000", w={"x": "2000000"})
claim(A, "false", "as_root_large", "x^(1/x)", "1", "about 1 + log(x)/x", assume="x > 1000000", w={"x": "2000000"})
claim(A, "false", "as_tiny_negative_slice", "sqrt(x^2)", "x", "x in (-1e-6, 0) is allowed and there sqrt(x^2) = -x",
      assume="x > -10^(-6)", w={"x": "-1/10000000"})
claim(A, "false", "as_log_sum_real", "log(x-1)+log(x+1)", "log(x^2-1)", "for x < -1 only the right side is real",
      assume="x real", w={"x": "-2"})
claim(A, "false", "as_acos_cos_positive", "acos(cos(x))", "x", "x > 0 is not enough: x = 4", assume="x > 0",
      w={"x": "4"})
claim(A, "false", "as_abs_near_one", "abs(x-1)", "x-1", "x in (1 - 1e-9, 1) is allowed", assume="x > 1 - 10^(-9)",
      w={"x": "1 - 10^(-10)"})
claim(A, "false", "as_mass_order_wrong", "sqrt((m1-m2)^2)", "m1 - m2", "with m2 > m1 it is m2 - m1",
      assume="m1 > 0, m2 > 0, m2 > m1", w={"m1": "1", "m2": "2"})
claim(A, "false", "as_log_large_approx", "log(1+x)", "log(x)", "differs by about 1/x", assume="x > 1000000",
      w={"x": "2000000"})
claim(A, "false", "as_between_wrong_sign", "sqrt((x-1)^2*(x-2)^2)", "(x-1)*(x-2)",
      "on (1, 2) the product is negative", assume="x > 1, x < 3", w={"x": "3/2"})
claim(A, "false", "as_exp_neg_huge", "exp(-x)", "0", "exp(-10^300) is tiny but not zero", assume="x > 10^300",
      w={"x": "2*10^300"})
claim(A, "true", "as_true_sqrt_positive", "sqrt(x^2)", "x", "x > 0", assume="x > 0")
claim(A, "true", "as_true_sqrt_nonnegative", "sqrt(x^2)", "x", "x >= 0", assume="x >= 0")
claim(A, "true", "as_true_sqrt_negative", "sqrt(x^2)", "-x", "x < 0", assume="x < 0")
claim(A, "true", "as_true_abs_order", "abs(x - y)", "x - y", "x > y", assume="x > y")
claim(A, "true", "as_true_sqrt_order", "sqrt((v1-v2)^2)", "v1 - v2", "v1 >= v2", assume="v1 >= v2")
claim(A, "true", "as_true_log_sum", "log(x-1)+log(x+1)", "log(x^2-1)", "x > 1: both factors positive",
      assume="x > 1")
claim(A, "true", "as_true_large_atan", "atan(x) + atan(1/x)", "pi/2", "x > 10^6 > 0", assume="x > 1000000", mag=10)
claim(A, "true", "as_true_large_sqrt", "sqrt(x^2)", "x", "x > 10^6 > 0", assume="x > 1000000", mag=10)
claim(A, "true", "as_true_large_conjugate", "sqrt(x^2+1) - x", "1/(sqrt(x^2+1)+x)",
      "x > 10^6: the left side cancels catastrophically", assume="x > 1000000", dps=1300, mag=10)
claim(A, "true", "as_true_huge_log", "log(x^2)", "2*log(x)", "x > 10^200 > 0", assume="x > 10^200", mag=300)
claim(A, "true", "as_true_mass_order", "sqrt((m1-m2)^2)", "m1 - m2", "m1 > m2",
      assume="m1 > 0, m2 > 0, m1 > m2")
claim(A, "true", "as_true_between", "sqrt((x-1)^2*(x-2)^2)", "(x-1)*(2-x)", "on (1, 2) the product (x-1)(2-x) > 0",
      assume="x > 1, x < 2")
claim(A, "true", "as_true_log_product", "log(a*b)", "log(a)+log(b)", "a > 0, b > 0", assume="a > 0, b > 0")
claim(A, "true", "as_true_acos_cos_interval", "acos(cos(x))", "x", "x in [0, pi]", assume="x in [0, pi]")
claim(A, "true", "as_true_tiny_positive", "sqrt(x^2)", "x", "0 < x < 10^-200", assume="x > 0, x < 10^(-200)", mag=300)
claim(A, "true", "as_true_abs_at_least_one", "abs(x - 1)", "x - 1", "x >= 1", assume="x >= 1")
claim(A, "true", "as_true_large_product", "sqrt(x*y)", "sqrt(x)*sqrt(y)", "x > 10^6 and y > x: both positive",
      assume="x > 1000000, y > x", mag=10)
claim(A, "true", "as_true_atan_double_beyond_one", "2*atan(x)", "atan(2*x/(1-x^2)) + pi", "x > 1",
      assume="x > 1")
claim(A, "false", "as_tinier_negative_slice", "sqrt(x^2)", "x", "x in (-1e-30, 0) is allowed",
      assume="x > -10^(-30)", w={"x": "-10^(-31)"})
claim(A, "false", "as_chain_allows_negative", "abs(x)", "x", "x > y > -1 still allows x in (-1, 0)",
      assume="x > y, y > -1", w={"x": "-1/2", "y": "-3/4"})
claim(A, "false", "as_square_constraint", "sqrt(x^2)", "x", "x^2 > 1 allows x < -1", assume="x^2 > 1",
      w={"x": "-2"})
claim(A, "false", "as_chain3_allows_negative", "abs(z)", "z", "z > y > x > -1 still allows z in (-1, 0)",
      assume="z > y, y > x, x > -1", w={"x": "-3/4", "y": "-1/2", "z": "-1/4"})
claim(A, "false", "as_chain_upper_allows_positive", "sqrt(x^2)", "-x",
      "x < y < 10^-6 still allows x in (0, 10^-6), where sqrt(x^2) = x", assume="x < y, y < 10^(-6)",
      w={"x": "10^(-8)", "y": "10^(-7)"})
claim(A, "false", "as_chain_scaled_allows_negative", "abs(x)", "x", "2x > y > -1/1000 allows x in (-1/2000, 0)",
      assume="2*x > y, y > -1/1000", w={"x": "-1/4000", "y": "-3/4000"})
claim(A, "true", "as_true_chain_positive", "abs(x)", "x", "x > y > 0", assume="x > y, y > 0")
claim(A, "true", "as_true_chain3_positive", "sqrt(z^2)", "z", "z > y > x > 1/1000",
      assume="z > y, y > x, x > 1/1000")
claim(A, "true", "as_true_cube_constraint", "sqrt(x^2)", "x", "x^3 > 1 means x > 1", assume="x^3 > 1")
claim(A, "true", "as_true_product_positive", "abs(x*y)", "x*y", "x > 0 and y > x make both positive",
      assume="x > 0, y > x")

# ---------------------------------------------------------------- suspicious but true
S = "suspicious_true"
claim(S, "true", "st_cosh_sinh", "((exp(x)+exp(-x))/2)^2 - ((exp(x)-exp(-x))/2)^2", "1", "cosh^2 - sinh^2 = 1",
      {"x": REAL})
claim(S, "true", "st_cosh_double", "((exp(x)+exp(-x))/2)^2 + ((exp(x)-exp(-x))/2)^2", "(exp(2*x)+exp(-2*x))/2",
      "cosh^2 + sinh^2 = cosh 2x", {"x": REAL})
claim(S, "true", "st_sin_triple", "sin(3*x)", "3*sin(x) - 4*sin(x)^3", "triple angle", {"x": REAL})
claim(S, "true", "st_cos_triple", "cos(3*x)", "4*cos(x)^3 - 3*cos(x)", "triple angle", {"x": REAL})
claim(S, "true", "st_half_angle_over_x2", "(1-cos(x))/x^2", "2*sin(x/2)^2/x^2", "1 - cos x = 2 sin^2(x/2)", {"x": REAL})
claim(S, "true", "st_tan_half_1", "tan(x/2)", "sin(x)/(1+cos(x))", "half-angle tangent", {"x": "in (-pi, pi)"})
claim(S, "true", "st_tan_half_2", "tan(x/2)", "(1-cos(x))/sin(x)", "half-angle tangent", {"x": "in (0, pi)"})
claim(S, "true", "st_cos_pi_5", "cos(pi/5)", "(1+sqrt(5))/4", "the golden ratio over 2")
claim(S, "true", "st_sin_pi_10", "sin(pi/10)", "(sqrt(5)-1)/4", "exact value")
claim(S, "true", "st_cos_pi_7_sum", "cos(pi/7) - cos(2*pi/7) + cos(3*pi/7)", "1/2", "heptagon identity")
claim(S, "true", "st_cos_2pi_7_sum", "cos(2*pi/7) + cos(4*pi/7) + cos(6*pi/7)", "-1/2", "heptagon identity")
claim(S, "true", "st_cos_pi_7_product", "cos(pi/7)*cos(2*pi/7)*cos(3*pi/7)", "1/8", "heptagon product")
claim(S, "true", "st_cos_pi_9_product", "cos(pi/9)*cos(2*pi/9)*cos(4*pi/9)", "1/8", "nonagon product")
claim(S, "true", "st_tan_pi_8", "tan(pi/8)", "sqrt(2) - 1", "half of pi/4")
claim(S, "true", "st_denest_3_2sqrt2", "sqrt(3+2*sqrt(2))", "1+sqrt(2)", "a nested radical that denests")
claim(S, "true", "st_machin", "4*atan(1/5) - atan(1/239)", "pi/4", "Machin's formula")
claim(S, "true", "st_euler_atan", "atan(1/2) + atan(1/3)", "pi/4", "atan addition with x y < 1")
claim(S, "true", "st_partial_fractions", "1/(x*(x+1)*(x+2)*(x+3))",
      "1/(6*x) - 1/(2*(x+1)) + 1/(2*(x+2)) - 1/(6*(x+3))", "partial fractions", {"x": REAL})
claim(S, "true", "st_elastic_energy",
      "1/2*m1*(((m1-m2)*v1+2*m2*v2)/(m1+m2))^2 + 1/2*m2*(((m2-m1)*v2+2*m1*v1)/(m1+m2))^2",
      "1/2*m1*v1^2+1/2*m2*v2^2", "energy is conserved in an elastic impact",
      {"m1": POS, "m2": POS, "v1": REAL, "v2": REAL})
claim(S, "true", "st_sum_to_product", "sin(x)+sin(y)", "2*sin((x+y)/2)*cos((x-y)/2)", "sum to product",
      {"x": REAL, "y": REAL})
claim(S, "true", "st_sec_tan", "1/cos(x)^2 - tan(x)^2", "1", "sec^2 - tan^2 = 1", {"x": "in (-pi/2, pi/2)"})
claim(S, "true", "st_exp_product", "exp(x)*exp(y)", "exp(x+y)", "every real x, y", {"x": REAL, "y": REAL})
claim(S, "true", "st_sin2_over_1mcos", "sin(x)^2/(1-cos(x))", "1 + cos(x)", "sin^2 = (1 - cos)(1 + cos)",
      {"x": "in (0, pi)"})
claim(S, "true", "st_binet_fibonacci", "((1+sqrt(5))^10 - (1-sqrt(5))^10)/(2^10*sqrt(5))", "55", "F10 = 55")
claim(S, "true", "st_cyclotomic", "x^8 - 1", "(x-1)*(x+1)*(x^2+1)*(x^4+1)", "factorisation", {"x": REAL})
claim(S, "true", "st_lagrange_identity", "(a^2+b^2)*(c^2+d^2)", "(a*c-b*d)^2 + (a*d+b*c)^2",
      "Brahmagupta-Fibonacci", {"a": REAL, "b": REAL, "c": REAL, "d": REAL})
claim(S, "true", "st_atan_double", "2*atan(x)", "atan(2*x/(1-x^2))", "valid for |x| < 1", {"x": "in (-1, 1)"})
claim(S, "true", "st_gudermann", "atan(exp(x)) - atan(exp(-x))", "2*atan(exp(x)) - pi/2",
      "atan(t) + atan(1/t) = pi/2 for t > 0", {"x": REAL})
claim(S, "true", "st_sqrt_factor", "sqrt(x^2 + 1)", "abs(x)*sqrt(1 + 1/x^2)", "x != 0 (removable at 0)", {"x": REAL})
claim(S, "true", "st_tan_quotient", "tan(x)", "sin(x)/cos(x)", "both undefined at the same poles", {"x": REAL})
claim(S, "false", "st_false_sin_triple", "sin(3*x)", "3*sin(x) - 3*sin(x)^3", "the cubic coefficient is 4",
      {"x": REAL}, w={"x": "1"})
claim(S, "false", "st_false_cos_pi_7_product", "cos(pi/7)*cos(2*pi/7)*cos(4*pi/7)", "1/8", "it is -1/8")
claim(S, "false", "st_false_half_angle", "(1-cos(x))/x^2", "sin(x/2)^2/x^2", "missing factor 2", {"x": REAL},
      w={"x": "1"})
claim(S, "false", "st_false_cosh_plus_sinh", "((exp(x)+exp(-x))/2)^2 + ((exp(x)-exp(-x))/2)^2", "1",
      "that is cosh 2x; agrees at x = 0 only", {"x": REAL}, w={"x": "1"})
claim(S, "false", "st_false_machin", "4*atan(1/5) - atan(1/240)", "pi/4", "239, not 240 (differs by 1.7e-5)")
claim(S, "false", "st_false_cot_half", "tan(x/2)", "sin(x)/(1-cos(x))", "that is cot(x/2); agrees at x = pi/2",
      {"x": "in (0, pi)"}, w={"x": "1"})
claim(S, "false", "st_false_pi_355", "pi", "355/113", "differs by 2.7e-7")
claim(S, "false", "st_false_sqrt2_pell", "sqrt(2)", "665857/470832", "a Pell convergent: differs by 1.6e-12")
claim(S, "false", "st_false_lagrange", "(a^2+b^2)*(c^2+d^2)", "(a*c+b*d)^2 + (a*d+b*c)^2", "sign error in a*c - b*d",
      {"a": REAL, "b": REAL, "c": REAL, "d": REAL}, w={"a": "1", "b": "1", "c": "1", "d": "1"})
claim(S, "false", "st_false_partial_fractions", "1/(x*(x+1)*(x+2)*(x+3))",
      "1/(6*x) - 1/(2*(x+1)) + 1/(2*(x+2)) - 1/(4*(x+3))", "last coefficient 1/4 instead of 1/6", {"x": REAL},
      w={"x": "1"})
claim(S, "false", "st_false_elastic_energy",
      "1/2*m1*(((m1-m2)*v1+2*m2*v2)/(m1+m2))^2 + 1/2*m2*(((m2-m1)*v2+2*m2*v1)/(m1+m2))^2",
      "1/2*m1*v1^2+1/2*m2*v2^2", "2 m2 v1 instead of 2 m1 v1: agrees when m1 = m2",
      {"m1": POS, "m2": POS, "v1": REAL, "v2": REAL}, w={"m1": "1", "m2": "2", "v1": "1", "v2": "0"})
claim(S, "false", "st_false_sum_to_product", "sin(x)+sin(y)", "2*sin((x+y)/2)*cos((x+y)/2)",
      "x + y instead of x - y: agrees when y = 0 or x = y", {"x": REAL, "y": REAL}, w={"x": "1", "y": "2"})
claim(S, "false", "st_false_atan_double", "2*atan(x)", "atan(2*x/(1-x^2))", "valid for |x| < 1 only", {"x": REAL},
      w={"x": "2"})
claim(S, "false", "st_false_heptagon_sum", "cos(pi/7) + cos(3*pi/7) + cos(5*pi/7)", "1/3",
      "it is 1/2 (the look-alike of st_cos_pi_7_sum)")

# ---------------------------------------------------------------- integer symbols (issue 24)
# True only because n is an integer (a real n refutes them), and their look-alikes that fail at
# some integers: a checker that samples n off the integers refutes the first kind, one that
# trusts a few lucky integers accepts the second.
I = "integer"
INT, PINT = "integer", "positive integer"
claim(I, "true", "int_sin_n_pi", "sin(n*pi)", "0", "n integer: a zero of sine", {"n": INT})
claim(I, "true", "int_cos_2n_pi", "cos(2*n*pi)", "1", "a whole number of turns", {"n": INT})
claim(I, "true", "int_minus_one_even", "(-1)^(2*n)", "1", "an even power of -1", {"n": INT})
claim(I, "true", "int_cos_n_pi_sign", "cos(n*pi)", "(-1)^n", "cos alternates at the integers", {"n": INT})
claim(I, "true", "int_parity_square", "(-1)^(n^2 + n)", "1", "n^2 + n = n*(n + 1) is even", {"n": INT})
claim(I, "true", "int_shift_by_n_pi", "sin(x + n*pi)", "(-1)^n*sin(x)", "a shift by n half-turns",
      {"n": PINT, "x": REAL})
claim(I, "true", "int_box_edge", "sin(n*pi*l/l)", "0", "the particle in a box vanishes at x = L",
      {"n": PINT, "l": POS})
claim(I, "false", "int_false_half_period", "sin(n*pi/2)", "0", "1 at n = 1: half periods are not periods",
      {"n": INT}, w={"n": "1"})
claim(I, "false", "int_false_cos_n_pi", "cos(n*pi)", "1", "-1 at every odd n", {"n": INT}, w={"n": "3"})
claim(I, "false", "int_false_sign", "(-1)^n", "1", "-1 at every odd n", {"n": PINT}, w={"n": "5"})
claim(I, "false", "int_false_parity_cube", "(-1)^(n^3 + 1)", "1", "n^3 + 1 is odd at even n",
      {"n": INT}, w={"n": "2"})
claim(I, "false", "int_false_real_n", "cos(2*n*pi)", "1", "n real: true only at the integers",
      {"n": REAL}, w={"n": "1/4"})

# ---------------------------------------------------------------- angles in degrees (issue 24)
A = "angles"
claim(A, "true", "ang_sin_30_deg", "sin(30*deg)", "1/2", "deg is pi/180")
claim(A, "true", "ang_degree_sign", "cos(60°)", "1/2", "60° is 60*deg")
claim(A, "true", "ang_tan_45", "tan(45°)", "1", "45° is pi/4")
claim(A, "true", "ang_theta_deg", "sin(theta*deg)", "sin(pi*theta/180)", "an angle given in degrees",
      {"theta": REAL})
claim(A, "false", "ang_false_sin_30", "sin(30*deg)", "sqrt(3)/2", "that is sin(60°)")
claim(A, "false", "ang_false_degrees_as_radians", "sin(theta*deg)", "sin(theta)",
      "degrees are not radians", {"theta": REAL}, w={"theta": "90"})


# ---------------------------------------------------------------- independent checker
class Undefined(Exception):
    pass


LOCALS = {n: sympy.Symbol(n) for n in
          "x y z a b c d e g l u m m0 m1 m2 v1 v2 theta n".split()}
LOCALS["deg"] = sympy.pi / 180
LOCALS.update({"pi": sympy.pi, "abs": sympy.Abs, "log": sympy.log, "exp": sympy.exp, "sqrt": sympy.sqrt,
               "sin": sympy.sin, "cos": sympy.cos, "tan": sympy.tan, "asin": sympy.asin, "acos": sympy.acos,
               "atan": sympy.atan})


def parse(text):
    # decimals are exact, as in derivcheck: 1.5708 -> (15708/10000)
    text = text.replace("°", "*deg")
    text = re.sub(r"(\d+)\.(\d+)", lambda m: f"({m.group(1)}{m.group(2)}/1{'0' * len(m.group(2))})", text)
    return parse_expr(text.replace("^", "**"), local_dict=LOCALS, evaluate=False)


def is_real(v):
    return not isinstance(v, mpmath.mpc) or v.imag == 0


def ev(e, env):
    """Evaluate over the reals; raises Undefined where the expression is not real."""
    if e.is_Integer:
        return mpf(int(e))
    if e.is_Rational:
        return mpf(int(e.p)) / int(e.q)
    if e == sympy.pi:
        return +mp.pi
    if e.is_Symbol:
        return env[e.name]
    if e.is_Add:
        return mpmath.fsum(ev(a, env) for a in e.args)
    if e.is_Mul:
        r = mpf(1)
        for a in e.args:
            r *= ev(a, env)
        return r
    if e.is_Pow:
        b = ev(e.args[0], env)
        if e.args[1].is_Integer:
            k = int(e.args[1])
            if b == 0 and k < 0:
                raise Undefined()
            return b ** k
        x = ev(e.args[1], env)
        if mpmath.isint(x):
            if b == 0 and x < 0:
                raise Undefined()
            return b ** int(x)
        if b < 0 or (b == 0 and x <= 0):
            raise Undefined()
        return mpmath.power(b, x)
    f = e.func
    args = [ev(a, env) for a in e.args]
    t = args[0]
    if f == sympy.Abs:
        return abs(t)
    if f == sympy.exp:
        return mpmath.exp(t)
    if f == sympy.log:
        if t <= 0:
            raise Undefined()
        return mpmath.log(t)
    if f == sympy.sin:
        return mpmath.sin(t)
    if f == sympy.cos:
        return mpmath.cos(t)
    if f == sympy.tan:
        if mpmath.cos(t) == 0:
            raise Undefined()
        return mpmath.tan(t)
    if f in (sympy.asin, sympy.acos):
        if abs(t) > 1:
            raise Undefined()
        return mpmath.asin(t) if f == sympy.asin else mpmath.acos(t)
    if f == sympy.atan:
        return mpmath.atan(t)
    raise ValueError(f"unknown function {f}")


def value(text, env):
    try:
        v = ev(parse(text), env)
    except (Undefined, ZeroDivisionError):
        return None
    return v


def in_domain(dom, v):
    if dom.endswith("integer") or dom.startswith("integer"):
        rest = dom.replace("integer", "").strip() or "real"
        return mpmath.isint(v) and in_domain(rest, v)
    if dom == "real":
        return True
    if dom == "positive":
        return v > 0
    if dom == "nonnegative":
        return v >= 0
    if dom == "negative":
        return v < 0
    m = re.fullmatch(r"(?:in\s*)?([\[(])(.*),(.*)([\])])", dom)
    lo, hi = ev(parse(m.group(2)), {}), ev(parse(m.group(3)), {})
    return (v > lo if m.group(1) == "(" else v >= lo) and (v < hi if m.group(4) == ")" else v <= hi)


def split_assume(text):
    items, depth, cur = [], 0, ""
    for ch in text:
        depth += ch in "([" and 1 or 0
        depth -= ch in ")]" and 1 or 0
        if ch == "," and depth == 0:
            items.append(cur.strip())
            cur = ""
        else:
            cur += ch
    if cur.strip():
        items.append(cur.strip())
    return items


def assumptions_of(c):
    """(domains by symbol, relations as (lhs, op, rhs))"""
    doms = dict(c["doms"])
    rels = []
    for item in split_assume(c["assume"] or ""):
        m = re.fullmatch(r"(.+?)\s*(<=|>=|!=|<|>)\s*(.+)", item)
        if m:
            lhs, op, rhs = m.groups()
            if re.fullmatch(r"[A-Za-z]\w*", lhs) and rhs == "0" and op in (">", ">=", "<"):
                doms[lhs] = {">": "positive", ">=": "nonnegative", "<": "negative"}[op]
            else:
                rels.append((lhs, op, rhs))
            continue
        name, dom = item.split(None, 1)
        doms[name] = dom
    return doms, rels


def holds(env, doms, rels):
    for n, d in doms.items():
        if n in env and not in_domain(d, env[n]):
            return False
    for lhs, op, rhs in rels:
        a, b = value(lhs, env), value(rhs, env)
        if a is None or b is None:
            return False
        if not {"<": a < b, "<=": a <= b, ">": a > b, ">=": a >= b, "!=": a != b}[op]:
            return False
    return True


def sides(c, env):
    if c["kind"] == "equal":
        return value(c["lhs"], env), value(c["rhs"], env)
    if c["kind"] == "antiderivative":
        x = c["extra"]["var"]
        f = lambda t: value(c["rhs"], {**env, x: t})
        try:
            d = mpmath.diff(f, env[x])
        except TypeError:
            d = None
        return value(c["lhs"], env), d
    raise ValueError("no pointwise check")


def symbols_of(c):
    names = set()
    texts = [c["lhs"], c["rhs"]] + [r for rel in assumptions_of(c)[1] for r in (rel[0], rel[2])]
    for t in texts:
        names |= {s.name for s in parse(t).free_symbols}
    return sorted(names | set(assumptions_of(c)[0]))


def random_value(dom, rng, mag):
    if "integer" in dom:
        v = mpf(rng.choice([rng.randint(0, 12), rng.randint(0, 10 ** 6)]))
        if dom.startswith("positive"):
            return v + 1
        if dom.startswith("negative"):
            return -v - 1
        if dom.startswith("nonnegative"):
            return v
        return v if rng.random() < 0.5 else -v
    if dom.startswith("in") or dom[0] in "[(":
        m = re.fullmatch(r"(?:in\s*)?([\[(])(.*),(.*)([\])])", dom)
        lo, hi = ev(parse(m.group(2)), {}), ev(parse(m.group(3)), {})
        return lo + (hi - lo) * mpf(rng.uniform(1e-6, 1 - 1e-6))
    v = mpf(10) ** mpf(rng.uniform(-mag, mag)) * mpf(rng.uniform(1, 1.001))
    if dom == "negative" or (dom == "real" and rng.random() < 0.5):
        v = -v
    return v


def agree(c, env, dps):
    """Both sides at dps and at 2 dps digits: they agree when the difference is below the
    precision or shrinks with it (a difference made by rounding)."""
    mp.dps = dps
    a, b = sides(c, env)
    if a is None or b is None:
        return a is None and b is None, a, b
    d1 = abs(a - b)
    if d1 <= mpf(10) ** (-(dps - 25)) * max(abs(a), abs(b)) or d1 == 0:
        return True, a, b
    mp.dps = 2 * dps
    a2, b2 = sides(c, env)
    mp.dps = dps
    d2 = abs(a2 - b2)
    return d2 <= d1 * mpf(10) ** (-(dps // 2)), a, b


def differ(a, b, dps):
    return abs(a - b) > mpf(10) ** (-(dps // 2)) * max(abs(a), abs(b))


def check(c):
    mp.dps = c["dps"]
    doms, rels = assumptions_of(c)
    names = symbols_of(c)
    if c["kind"] in ("limit", "series_first_order"):
        return None  # checked by hand: abs(x) = -x for x < 0, = x for x > 0
    if c["expect"] == "false":
        if not names:
            a, b = sides(c, {})
            if a is None or b is None or not is_real(a) or not is_real(b):
                return "constant claim not real"
            return None if differ(a, b, c["dps"]) else f"constant sides agree: {a} {b}"
        if not c["w"]:
            return "false claim without a witness"
        env = {n: ev(parse(v), {}) for n, v in c["w"].items()}
        for n in names:
            env.setdefault(n, None)
        if any(v is None for v in env.values()):
            return f"witness does not give every symbol: {names}"
        if not holds(env, doms, rels):
            return "witness outside the declared domain"
        a, b = sides(c, env)
        if (a is None) != (b is None):
            return None
        if a is None:
            return "both sides undefined at the witness"
        if not differ(a, b, c["dps"]):
            return f"sides agree at the witness: {a} {b}"
        return None
    rng = random.Random(c["id"])
    good = 0
    for _ in range(4000):
        env = {n: random_value(doms.get(n, "real"), rng, c["mag"]) for n in names}
        if not holds(env, doms, rels):
            continue
        ok, a, b = agree(c, env, c["dps"])
        if a is None and b is None:
            # both undefined: must only happen on a lower-dimensional set (poles); rare draws
            continue
        if (a is None) != (b is None):
            return f"one side undefined at {env}"
        if not ok:
            return f"sides differ at {env}: {a} {b}"
        good += 1
        if good >= (12 if c["dps"] > 300 else 40) or not names:
            break
    if good == 0:
        return "no point of the domain found"
    return None


def main():
    ids = set()
    failures = 0
    lines = []
    for c in CLAIMS:
        assert c["id"] not in ids, c["id"]
        ids.add(c["id"])
        problem = check(c)
        if problem:
            failures += 1
            print(f"{c['id']}: {problem}", file=sys.stderr)
        j = {"id": c["id"], "kind": c["kind"], "lhs": c["lhs"], "rhs": c["rhs"]}
        for k in ("var", "point"):
            if k in c["extra"]:
                j[k] = c["extra"][k]
        if c["doms"]:
            j["assumptions"] = c["doms"]
        if c["assume"]:
            j["assume"] = c["assume"]
        j.update({"expect": c["expect"], "class": c["cls"], "why": c["why"]})
        if c["w"]:
            j["witness"] = c["w"]
        lines.append(json.dumps(j, ensure_ascii=False))
    counts = {}
    for c in CLAIMS:
        counts.setdefault(c["cls"], [0, 0])[c["expect"] == "false"] += 1
    for k, (t, f) in counts.items():
        print(f"{k}: {t} true, {f} false", file=sys.stderr)
    print(f"{len(CLAIMS)} claims, {failures} failed the independent check", file=sys.stderr)
    if failures:
        sys.exit(1)
    if "--check-only" not in sys.argv:
        OUT.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
