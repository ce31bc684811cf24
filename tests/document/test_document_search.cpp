// The justification search beyond rewrite (derivations/document/justify_rules.cpp) and the
// doubts that keep a counterexample from refuting what the author did not mean
// (justify_doubts.cpp), each on a short document written for it.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "document/document_rows.hpp"

namespace {

std::vector<document_test::Row> check(const std::string& text) { return document_test::check("search.md", text, true); }
using document_test::at;

}  // namespace

TEST_CASE("document search: a limit the row takes of an earlier row's expression") {
  auto rows = check("$$w = \\frac{(a - b) u}{a + b}$$\n"                                      // 1
                    "\n"
                    "For a very heavy second body:\n"
                    "\n"
                    "$$w = \\lim_{b \\to \\infty} \\frac{(a - b) u}{a + b} = -u$$\n");           // 5
  CHECK(at(rows, 5, 1).verdict == "proved");
  CHECK(at(rows, 5, 1).rule.rfind("limit b -> oo", 0) == 0);
  CHECK(at(rows, 5, 2).verdict == "proved");
}

TEST_CASE("document search: an approximate row in the regime the text states") {
  const std::string doc = "$$y = \\frac{x + k}{x + 1} u$$\n"                                 // 1
                          "\n"
                          "When $x \\approx 0$ this is\n"
                          "\n";
  CHECK(at(check(doc + "$$y \\approx k u$$\n"), 5).verdict == "proved");
  // the wrong leading term is never refuted (an approximate row), but it is not derived either
  CHECK(at(check(doc + "$$y \\approx 2 k u$$\n"), 5).verdict == "undecided");
}

TEST_CASE("document search: the 'where' clause after a display defines its names") {
  auto rows = check("$$p = m v$$\n"                                                           // 1
                    "\n"
                    "$$p = \\frac{M}{2} v$$ where $m = M/2$ is half the total.\n");            // 3
  CHECK(at(rows, 3).verdict == "proved");
}

TEST_CASE("document search: 'neglect D' in the text is a condition D = 0 of the next display") {
  auto rows = check("$$F - D - m g = m a$$\n"                                                  // 1
                    "\n"
                    "Now neglect D and write\n"
                    "\n"
                    "$$m a = F - m g$$\n");                                                    // 5
  CHECK(at(rows, 5).verdict == "proved");
}

TEST_CASE("document search: first order in the Delta quantities when the text neglects the rest") {
  auto rows = check("$$\\Delta p = (m - \\Delta m)(v + \\Delta v) - m v = m \\Delta v - v \\Delta m$$\n"   // 1
                    "\n"
                    "where the higher-order term was neglected.\n");
  CHECK(at(rows, 1, 2).verdict == "proved");
  CHECK(at(rows, 1, 2).rule.rfind("first_order", 0) == 0);
}

TEST_CASE("document search: a root the row chooses is undecided, naming the declaration, and a slip in it is refuted") {
  const std::string doc = "$$h = L (1 - \\cos\\theta)$$\n"   // 1
                          "\n"
                          "and therefore\n"
                          "\n";
  auto right = check(doc + "$$\\theta = \\arccos\\left(1 - \\frac{h}{L}\\right)$$\n");
  CHECK(at(right, 5).verdict == "undecided");
  CHECK(at(right, 5).reason.find("0 <= theta <= pi") != std::string::npos);
  auto slip = check(doc + "$$\\theta = \\arccos\\left(1 - \\frac{2 h}{L}\\right)$$\n");
  CHECK(at(slip, 5).verdict == "refuted");
}

TEST_CASE("document search: one more equation of a system listed in one display is not refuted") {
  auto rows = check("Newton's law, the torque and the rolling condition give\n"   // 1
                    "\n"
                    "$$\\begin{aligned}\n"                                          // 3
                    "m a &= m g \\sin\\beta - f \\\\\n"                              // 4
                    "f r &= I \\alpha \\\\\n"                                       // 5
                    "a &= \\alpha r\n"                                              // 6
                    "\\end{aligned}$$\n");
  CHECK(at(rows, 6).verdict != "refuted");
}

TEST_CASE("document search: a condition stated a paragraph earlier still counts against a refutation") {
  auto rows = check("$$p_1 V_1 = n R T_1$$\n"                                        // 1
                    "\n"
                    "The bath keeps the temperature fixed, $T_2 = T_1$, while the gas expands.\n"
                    "\n"
                    "$$W = n R T_1 \\ln(V_2/V_1)$$\n"                                // 5
                    "\n"
                    "The heat supplied is the same. At the end\n"
                    "\n"
                    "$$p_2 V_2 = n R T_2 = p_1 V_1$$\n");                             // 9
  CHECK(at(rows, 9, 2).verdict != "refuted");
}

TEST_CASE("document search: a row of differentials is read divided by the differential of the display's variable") {
  auto rows = check("$$\\begin{aligned} m \\frac{dv}{dt} &= -b v \\\\\n"   // 1
                    "dv &= -\\frac{b}{m} v\\,dt \\end{aligned}$$\n");          // 2
  CHECK(at(rows, 2).verdict == "proved");
  auto slip = check("$$\\begin{aligned} m \\frac{dv}{dt} &= -b v \\\\\n"
                    "dv &= -\\frac{m}{b} v\\,dt \\end{aligned}$$\n");
  CHECK(at(slip, 2).verdict != "proved");
  // a term without a differential: not read, with the reason
  auto mixed = check("$$\\begin{aligned} m \\frac{dv}{dt} &= -b v \\\\\n"
                     "dv &= -\\frac{b}{m} v \\end{aligned}$$\n");
  CHECK(at(mixed, 2).verdict == "undecided");
  CHECK(at(mixed, 2).reason.find("a differential") != std::string::npos);
}

TEST_CASE("document search: a row that holds for positive names is undecided naming the declaration, and derived once declared") {
  const std::string rows_text = "$$\\omega^2 = \\frac{k}{m}$$\n"                          // 1 (2 with the directive)
                                "\n"
                                "$$T = \\frac{2\\pi}{\\omega} = 2\\pi\\sqrt{\\frac{m}{k}}$$\n";   // 3
  auto plain = check(rows_text);
  CHECK(at(plain, 3, 2).verdict == "undecided");
  CHECK(at(plain, 3, 2).reason.find("positive") != std::string::npos);
  auto declared = check("<!-- derivcheck: symbol k, m, omega : positive -->\n" + rows_text);
  CHECK(at(declared, 4, 2).verdict == "proved");
}

TEST_CASE("document search: a derivative in the text is a derivative, and a definition there lasts its section") {
  // `$\mu = dm/dt$` defines mu as a rate; read with m plain it would say mu = 0, and a row
  // claiming u mu = 0 would follow from it
  const std::string head = "## Rocket\n"
                           "\n"
                           "Fuel leaves at a rate $\\mu = dm/dt$ with speed $u$ relative to the rocket.\n"
                           "\n"
                           "$$F = u \\mu$$\n"                                              // 5
                           "\n"
                           "The thrust in terms of the mass:\n"
                           "\n";
  CHECK(at(check(head + "$$F = u \\frac{dm}{dt}$$\n"), 9).verdict == "proved");
  CHECK(at(check(head + "$$F = 0$$\n"), 9).verdict != "proved");
  // a name given again in a later section is a new quantity there: the definition is over
  auto later = check(head + "## Masses\n\nTwo bodies.\n\n$$\\mu = \\frac{m_1}{m_2}$$\n\n$$F = u \\frac{dm}{dt}$$\n");
  CHECK(at(later, 15).verdict != "proved");
}

TEST_CASE("document search: a numbered heading line in Markdown starts a section") {
  // `9.4 Title` on a line of its own, as in notes converted from PDF: a definition of the
  // section before it is not in force after it
  const std::string head = "9.3 Impact\n"
                           "\n"
                           "The ratio $\\mu = m_1/m_2$ decides it:\n"
                           "\n"
                           "$$w = \\mu v$$\n"                                               // 5
                           "\n";
  CHECK(at(check(head + "Then\n\n$$w = \\frac{m_1}{m_2} v$$\n"), 9).verdict == "proved");
  CHECK(at(check(head + "9.4 Rockets\n\n$$w = \\frac{m_1}{m_2} v$$\n"), 9).verdict != "proved");
}

TEST_CASE("document search: no proof rests on a slip that pins a quantity with the rows beside it") {
  // the garbled second link of (1) with the true law (2) forces LC = 1, and from that the
  // wrong frequency below "follows"; the slip row is left undecided (a given of its own
  // display may be one more law), so it must not carry a proof either
  auto lc = check("$$\\omega_0 = \\frac{1}{\\sqrt{L C}}$$\n"                                  // 1
                  "\n"
                  "The largest current:\n"
                  "\n"
                  "$$i_m = \\omega_0 Q_0 = Q_0 \\sqrt{L C}$$\n"                               // 5
                  "\n"
                  "In hertz,\n"
                  "\n"
                  "$$f_0 = \\frac{\\omega_0}{2\\pi} = \\frac{1}{2\\pi L C}$$\n");               // 9
  CHECK(at(lc, 9, 2).verdict != "proved");
  // an equation of the text pins as well: the lens law of the prose beside a refuted row
  // forces f = 0, from which any multiple of f "follows"
  auto lens = check("$$\\frac{1}{s} + \\frac{1}{s'} = \\frac{1}{f}$$\n"                       // 1
                    "\n"
                    "$$m = -\\frac{s'}{s} = -\\frac{f}{f - s}$$\n"                            // 3
                    "\n"
                    "Since $s s' = f (s + s')$, with $x = s - f$ and $y = s' - f$,\n"
                    "\n"
                    "$$m = -\\frac{f}{x} = -\\frac{f}{y}$$\n");                               // 7
  CHECK(at(lens, 3, 2).verdict == "refuted");
  CHECK(at(lens, 7, 2).verdict != "proved");
}

TEST_CASE("document search: the rates of a balance of increments, when the text takes the derivative") {
  const std::string head = "$$M \\Delta v = u \\Delta m + F \\Delta t$$\n"        // 1
                           "\n"
                           "Dividing by the time step and taking the limit:\n"
                           "\n";
  CHECK(at(check(head + "$$M \\frac{dv}{dt} = u \\frac{dm}{dt} + F$$\n"), 5).verdict == "proved");
  CHECK(at(check(head + "$$M \\frac{dv}{dt} = u \\frac{dm}{dt} - F$$\n"), 5).verdict != "proved");
  // without words for a derivative the increments are not read as rates
  CHECK(at(check("$$M \\Delta v = u \\Delta m + F \\Delta t$$\n\nSo\n\n$$M \\frac{dv}{dt} = u \\frac{dm}{dt} + F$$\n"), 5)
            .verdict != "proved");
  // a relation that is not linear in the increments gives no rates
  CHECK(at(check("$$M \\Delta v = u \\Delta m \\Delta v + F \\Delta t$$\n\nTaking the limit:\n\n"
                 "$$M \\frac{dv}{dt} = F$$\n"), 5).verdict != "proved");
}

TEST_CASE("document search: a law with plain names read at each instant beside the claim's functions") {
  // q is plain in the loop law and a function of t where it is differentiated
  const std::string head = "$$I = \\frac{dq}{dt} \\quad (1)$$\n"                        // 1
                           "\n"
                           "$$E = R I + \\frac{q}{C} \\quad (2)$$\n"                     // 3
                           "\n"
                           "Putting (1) into (2):\n"
                           "\n";
  CHECK(at(check(head + "$$\\frac{dq}{dt} = \\frac{E}{R} - \\frac{q}{R C}$$\n"), 7).verdict == "proved");
  CHECK(at(check(head + "$$\\frac{dq}{dt} = \\frac{E}{R} + \\frac{q}{R C}$$\n"), 7).verdict != "proved");
  // the name a row sets keeps its value at its instant: `v = v_0` does not make v constant
  auto start = check("$$v = v_0 + w$$\n"                                              // 1
                     "\n"
                     "$$m \\frac{dv}{dt} = F$$\n"                                       // 3
                     "\n"
                     "Then\n"
                     "\n"
                     "$$\\frac{dv}{dt} = 0$$\n");                                       // 7
  CHECK(at(start, 3).verdict == "premise");
  CHECK(at(start, 7).verdict != "proved");
}

TEST_CASE("document search: a solution of an earlier rate equation, its new names the constants of integration") {
  const std::string head = "$$m \\frac{dv}{dt} = -u \\frac{dm}{dt} - m g$$\n"          // 1
                           "\n"
                           "which is integrated (taking $v = 0$ at $t = 0$) to find\n"
                           "\n";
  CHECK(at(check(head + "$$v = -u \\ln\\left(\\frac{m}{m_0}\\right) - g t$$\n"), 5).verdict == "proved");
  // no constant makes the wrong sign a solution
  CHECK(at(check(head + "$$v = u \\ln\\left(\\frac{m}{m_0}\\right) - g t$$\n"), 5).verdict == "refuted");
  // a second-order equation and its general solution
  auto shm = check("$$\\frac{d^2x}{dt^2} + w^2 x = 0$$\n"                                 // 1
                   "\n"
                   "Its general solution is\n"
                   "\n"
                   "$$x = A \\cos(w t + \\phi)$$\n");                                      // 5
  CHECK(at(shm, 5).verdict == "proved");
  auto wrong = check("$$\\frac{d^2x}{dt^2} + w^2 x = 0$$\n\nIts general solution is\n\n$$x = A \\cos(w^2 t + \\phi)$$\n");
  CHECK(at(wrong, 5).verdict != "proved");
  // without words for integrating, the row is a given (a law with new names)
  CHECK(at(check("$$m \\frac{dv}{dt} = -u \\frac{dm}{dt} - m g$$\n\nThen\n\n"
                 "$$v = -u \\ln\\left(\\frac{m}{m_0}\\right) - g t$$\n"), 5).verdict == "premise");
}

TEST_CASE("document search: differentiating a row that sets a quantity, and a slip in it") {
  const std::string head = "$$v = u \\sin a - g t$$\n"          // 1
                           "\n"
                           "Differentiating once more, the acceleration is\n"
                           "\n";
  CHECK(at(check(head + "$$\\frac{dv}{dt} = -g$$\n"), 5).verdict == "proved");
  CHECK(at(check(head + "$$\\frac{dv}{dt} = g$$\n"), 5).verdict == "refuted");
  // without the words the row is a new law about v(t) (a given)
  CHECK(at(check("$$v = u \\sin a - g t$$\n\nThen\n\n$$\\frac{dv}{dt} = g$$\n"), 5).verdict == "premise");
  // a display that follows the differentiated one with no prose between continues its sentence
  const std::string two = "Differentiating once more,\n"
                          "\n"
                          "$$v = u \\sin a - g t$$\n"   // 3
                          "\n";
  CHECK(at(check(two + "$$\\frac{dv}{dt} = -g$$\n"), 5).verdict == "proved");
  CHECK(at(check(two + "$$\\frac{dv}{dt} = g$$\n"), 5).verdict == "refuted");
  // (prose between them starts a new sentence: a new law again)
  CHECK(at(check(two + "Then\n\n$$\\frac{dv}{dt} = g$$\n"), 7).verdict == "premise");
}

// `v(0)` is the value of v at 0, not the product v*0 (which once made `$v(0) = v_0$` pin
// v_0 = 0 and refuted a true `v(0) = v_0`); `x(0)` of a quantity no row makes a function of
// anything is not read.
TEST_CASE("document search: v(0) and v(t) are values of the function v, never products") {
  const std::string text = "$$v(t) = v_0 e^{-k t}$$\n"   // 1
                           "\n"
                           "so at the start\n"
                           "\n"
                           "$$v(0) = v_0$$\n"            // 5
                           "\n"
                           "and a slip\n"
                           "\n"
                           "$$v(0) = 2 v_0$$\n"          // 9
                           "\n"
                           "and a value of nothing\n"
                           "\n"
                           "$$x(0) = 3$$\n";             // 13
  const auto rows = check(text);
  CHECK(at(rows, 1).verdict == "premise");
  CHECK(at(rows, 5).verdict == "proved");
  CHECK(at(rows, 9).verdict == "refuted");
  CHECK(at(rows, 13).verdict == "undecided");
  CHECK(at(rows, 13).reason.find("no row makes x a function") != std::string::npos);
  // the equation of the text `$v(0) = v_0$` is a value of v, not v*0 = v_0 (which pinned v_0 = 0)
  // (read as v*0 = v_0, the two equations of the text "proved" v_0 = 0)
  const auto pinned = check("With $v(0) = v_0$ and $\\frac{dv}{dt} = -k v$ we have\n\n$$v_0 = 0$$\n");
  CHECK(at(pinned, 3).verdict != "proved");
}

// An equation the words set aside is no given: with `$T = 0$` in force, the flight time would
// "follow" only through the pin T = 0 (and a written value is eliminated first).
TEST_CASE("document search: an equation the text discards is not a given") {
  const auto rows = check("$$v_0 T \\sin a - \\frac{1}{2} g T^2 = 0$$\n"   // 1
                          "\n"
                          "Discarding the root $T = 0$, we find\n"
                          "\n"
                          "$$T = \\frac{2 v_0 \\sin a}{g}$$\n");           // 5
  CHECK(at(rows, 5).verdict == "proved");
  // "cannot" asserts what follows it
  const auto pin = document_test::check("pin.md", "The pin cannot take a moment, $M(0) = 0$, and\n\n$$M(x) = R x$$\n");
  bool given = false;
  for (const auto& r : pin) given = given || (r.line == 1 && r.verdict == "premise");
  CHECK(given);
}

TEST_CASE("document search: a derivative of constants that is false alone is a slip, whatever the text around it") {
  // The display names an operation ("differentiating"), and the row takes a derivative: both
  // kept a counterexample from refuting. When the row is false read alone and nothing in its
  // derivative can vary, neither is a reason to doubt it.
  const std::string before = "The tank drains at the steady rate $q$, so $M = M_0 - q t$.\n"       // 1
                             "\n"
                             "Differentiating the logarithm of the mass ratio we use\n"              // 3
                             "\n";
  auto slip = check(before + "$$\\frac{d}{dt} \\ln\\frac{M_0}{M_0 - q t} = -\\frac{q}{M_0 - q t}$$\n");
  CHECK(at(slip, 5).verdict == "refuted");
  auto right = check(before + "$$\\frac{d}{dt} \\ln\\frac{M_0}{M_0 - q t} = \\frac{q}{M_0 - q t}$$\n");
  CHECK(at(right, 5).verdict != "refuted");   // (the log's condition M_0/(M_0 - q t) > 0 is not declared)
  // a name the document makes a function of t (dM/dt elsewhere) may vary inside the derivative
  auto varying = check("The mass changes: $\\frac{dM}{dt} = -q$.\n"
                       "\n"
                       "$$\\frac{d}{dt} (M u) = M \\frac{du}{dt} + q u$$\n");
  CHECK(at(varying, 3).verdict != "refuted");
  // a regime the text names still withholds it: the row may be an approximation written with =
  auto regime = check("For small $q t$ compared with $M_0$ we may write\n"
                      "\n"
                      "$$\\frac{d}{dt} \\ln\\frac{M_0}{M_0 - q t} = \\frac{q}{M_0}$$\n");
  CHECK(at(regime, 3).verdict != "refuted");
}

// A row left undecided only for want of a sign (`v = \sqrt{2 g h}` holds once v is positive) is
// no slip: a later slip that rests on it is refuted (in the reading where the names are
// positive), where it was withheld as "resting on a row that is not derived".
TEST_CASE("document search: a row that holds once its names are positive carries a later refutation") {
  const std::string head = "$$\\frac{1}{2} m v^2 = m g h$$\n"   // 1
                           "\n"
                           "Solving for the speed,\n"
                           "\n"
                           "$$v = \\sqrt{2 g h}$$\n"             // 5
                           "\n"
                           "The momentum at the bottom is therefore\n"
                           "\n";
  const auto rows = check(head + "$$m v = m \\sqrt{g h}$$\n");   // 9
  CHECK(at(rows, 5).verdict == "undecided");
  CHECK(at(rows, 5).reason.find("holds if v is positive") != std::string::npos);
  CHECK(at(rows, 9).verdict == "refuted");
  // the right momentum is never refuted
  CHECK(at(check(head + "$$m v = m \\sqrt{2 g h}$$\n"), 9).verdict != "refuted");
}

// A name set by a row the reader could not read (an integral of a quantity that varies) is not
// free: a counterexample that gives it any value may contradict that row. Here Q stands for the
// work of an isotherm written as an integral; a true row about Q is never refuted.
TEST_CASE("document search: a name set by an unread row keeps a counterexample from refuting") {
  const std::string text = "$$p = \\frac{n R T}{V}, \\quad \\frac{V_2}{V_1} = r$$\n"   // 1
                           "\n"
                           "$$W = \\int_{V_1}^{V_2} p\\, dV$$\n"                          // 3
                           "\n"
                           "$$Q = W$$\n"                                                  // 5
                           "\n"
                           "so\n"
                           "\n"
                           "$$\\frac{Q}{T} = n R \\ln r$$\n";                            // 9
  const auto rows = check(text);
  CHECK(at(rows, 3).verdict == "undecided");   // not read yet
  // (it was refuted: Q = W with W free)
  CHECK(at(rows, 9).verdict == "undecided");
  CHECK(at(rows, 9).reason.find("'W' is set by L3, which is not read") != std::string::npos);
}

// No elimination undoes an exponential: a slip in a quantity solved out of one is refuted by
// substituting the claim back into the row (`solve`), with the doubts of any refutation; a
// claimed root of the wrong sign is no evidence (the signs are the reading's, not the author's).
TEST_CASE("document search: a slip in a quantity solved out of an exponential") {
  const std::string head = "$$\\tau = R C$$\n"                       // 1
                           "\n"
                           "The current has halved at $t_h$, where\n"
                           "\n"
                           "$$e^{-t_h/\\tau} = \\tfrac12$$\n"          // 5
                           "\n"
                           "so\n"
                           "\n";
  CHECK(at(check(head + "$$t_h = \\tau / \\ln 2$$\n"), 9).verdict == "refuted");
  // (the right one is not refuted; it is not proved either: `solve` does not exclude other roots
  // of e^{-t_h/\\tau} = 1/2 yet)
  CHECK(at(check(head + "$$t_h = \\tau \\ln 2$$\n"), 9).verdict != "refuted");
  // the sign of a root: t_h = -\tau\ln 2 fails only because t_h is read positive
  CHECK(at(check(head + "$$t_h = (m_0 - m)/\\mu$$\n"), 9).verdict != "refuted");
}

// A later link of a chain that computes the quantity its first link names is no new law of the
// display: its slip is refuted with the display's other givens. A link whose left side is a
// name the display introduces may still be one (here \dot q, read as a new name).
TEST_CASE("document search: a chain that computes a quantity, beside the display's givens") {
  const std::string cyclotron = "The ion leaves on the outermost orbit, so\n"
                                "\n"
                                "\\begin{gather}\n"
                                "  R = \\frac{m v}{q B} , \\\\\n"                                // 4
                                "  K = \\tfrac12 m v^2 = \\frac{q^2 B R^2}{2 m} .\n"              // 5
                                "\\end{gather}\n";
  const auto rows = check(cyclotron);
  CHECK(at(rows, 5, 1).verdict == "premise");
  CHECK(at(rows, 5, 2).verdict == "refuted");
  CHECK(at(check(cyclotron.substr(0, cyclotron.find("q^2 B R^2")) + "q^2 B^2 R^2}{2 m} .\n\\end{gather}\n"), 5, 2)
            .verdict != "refuted");
  const auto current = check("$$\\omega_0 = \\frac{1}{\\sqrt{LC}}$$\n"                       // 1
                             "\n"
                             "$$q = Q_0\\cos\\omega_0 t$$\n"                                   // 3
                             "\n"
                             "$$i = \\dot{q} = -\\omega_0 Q_0 \\sin\\omega_0 t$$\n");         // 5
  CHECK(at(current, 5, 2).verdict != "refuted");
}

// A link that solves for the name its row's given introduces is computed, not a new law:
// `\tfrac12 m v^2 = G M m/R, \qquad v = \sqrt{G M/R}` (the 2 dropped) is refuted against the
// first link, which the refutation keeps.
TEST_CASE("document search: a link solved for the name the row's first link introduces") {
  const std::string head = "<!-- derivcheck: symbol G, M, m, R : positive -->\n"   // 1
                           "\n"
                           "$$ F = \\frac{G M m}{R^2} $$\n"                           // 3
                           "\n"
                           "The escape speed:\n"
                           "\n";
  CHECK(at(check(head + "$$ \\tfrac12 m v^2 = \\frac{G M m}{R} , \\qquad v = \\sqrt{\\frac{G M}{R}} $$\n"), 7, 2)
            .verdict == "refuted");
  CHECK(at(check(head + "$$ \\tfrac12 m v^2 = \\frac{G M m}{R} , \\qquad v = \\sqrt{\\frac{2 G M}{R}} $$\n"), 7, 2)
            .verdict != "refuted");
}

// `W = F d = \tfrac12 m v^2`: d is new in the first link and nothing else relates it, so the
// second link may be the law that fixes it (work and energy); it was refuted with d chosen
// freely. A name a given introduces alone is determined by it, and a row whose difference
// fixes another name (the cyclotron's slip above fixes B) is still refuted.
TEST_CASE("document search: a law about a name its own display introduces is not refuted") {
  const auto rows = check("The block of mass $m$ starts from rest and accelerates uniformly,\n"
                          "\n"
                          "$$v = a t, \\qquad p = m v$$\n"                 // 3
                          "\n"
                          "$$F = m a$$\n"                                   // 5
                          "\n"
                          "The work done on it is\n"
                          "\n"
                          "$$W = F d = \\tfrac12 m v^2$$\n");               // 9
  CHECK(at(rows, 9, 2).verdict == "undecided");
  CHECK(at(rows, 9, 2).reason.find("'d' is new in this display") != std::string::npos);
}
