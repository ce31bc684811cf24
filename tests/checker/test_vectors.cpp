// Vectors (symbolic/vectors.hpp, reader/dc_vectors.cpp): a vector equation is one equation per
// component, each checked by the step's rule; a vector reference gives every component.
#include <catch2/catch.hpp>

#include <string>

#include "derivations/report/latex.hpp"
#include "support/checked.hpp"

namespace {

using test_support::Checked;
using K = dc::VerdictKind;

Checked check_text(const std::string& body) { return test_support::check_text(body, "vectors.dc"); }

const std::string kDecl =
    "symbol m, M : positive [kg]\n"
    "symbol t : real [s]\n"
    "vector F : 3 [N]\n"
    "vector a, g : 3 [m/s^2]\n"
    "vector v, V, u : 3 [m/s]\n"
    "vector p : 3 [kg*m/s]\n"
    "vector r(t) : 3 [m]\n"
    "vector r0 : 3 [m]\n"
    "vector A, B : 3 [1]\n";

std::string input_error(const std::string& body) {
  try {
    (void)dc::parse_derivation(dc::SourceText{"e.dc", body});
  } catch (const dc::InputError& e) {
    return std::to_string(e.pos().line) + ":" + std::to_string(e.pos().col) + ": " + e.message();
  }
  return "no error";
}

}  // namespace

TEST_CASE("vectors: a vector law is its components", "[vectors]") {
  Checked c = check_text(kDecl +
                         "newton: F = m*a\n    by given\n"
                         "mom: p = m*v\n    by given\n"
                         "x_part: F_x = m*a_x\n    by rewrite newton\n"
                         "mixed_up: F_y = m*a_x\n    by rewrite newton\n"
                         "written_out: p = [m*v_x, m*v_y, m*v_z]\n    by rewrite mom\n"
                         "swapped: p = [m*v_x, m*v_z, m*v_y]\n    by rewrite mom\n"
                         "speed: v = p/m\n    by solve mom for v\n"
                         "kinetic: dot(p, p) = m^2*dot(v, v)\n    by rewrite mom\n");
  CHECK(c.kind("newton") == K::Proved);   // a premise (every component)
  CHECK(c.at("newton").premise);
  CHECK(c.kind("x_part") == K::Proved);
  CHECK(c.kind("mixed_up") == K::Refuted);
  CHECK(c.kind("written_out") == K::Proved);
  CHECK(c.at("written_out").verdict.method.find("each component") != std::string::npos);
  CHECK(c.kind("swapped") == K::Refuted);
  // the component at fault is named
  CHECK(c.at("swapped").verdict.method.find("component 2") != std::string::npos);
  CHECK(c.kind("speed") == K::Proved);
  CHECK(c.kind("kinetic") == K::Proved);
  for (const char* label : {"newton", "x_part", "written_out", "swapped", "speed"}) CHECK(c.at(label).errors.empty());
}

TEST_CASE("vectors: identities of dot and cross products", "[vectors]") {
  Checked c = check_text(kDecl +
                         "bac_cab: cross(A, cross(B, A)) = B*dot(A, A) - A*dot(A, B)\n    by rewrite\n"
                         "bac_cab_slip: cross(A, cross(B, A)) = A*dot(A, A) - B*dot(A, B)\n    by rewrite\n"
                         "perpendicular: dot(A, cross(A, B)) = 0\n    by rewrite\n"
                         "anticommutes: cross(A, B) = -cross(B, A)\n    by rewrite\n"
                         "commutes_slip: cross(A, B) = cross(B, A)\n    by rewrite\n"
                         "lagrange: norm(cross(A, B))^2 = dot(A, A)*dot(B, B) - dot(A, B)^2\n    by rewrite\n");
  CHECK(c.kind("bac_cab") == K::Proved);
  CHECK(c.kind("bac_cab_slip") == K::Refuted);
  CHECK(c.kind("perpendicular") == K::Proved);
  CHECK(c.kind("anticommutes") == K::Proved);
  CHECK(c.kind("commutes_slip") == K::Refuted);
  CHECK(c.kind("lagrange") == K::Proved);
}

TEST_CASE("vectors: a vector function of t, substitution, a 2-D cross product", "[vectors]") {
  Checked c = check_text(kDecl +
                         "vector w1 : 2 [m/s] components w1n, w1t\n"
                         "vector w2 : 2 [m/s]\n"
                         "traj: r(t) = r0 + u*t + g*t^2/2\n    by given\n"
                         "velocity: diff(r(t), t) = u + g*t\n    by differentiate traj wrt t\n"
                         "velocity_slip: diff(r(t), t) = u + 2*g*t\n    by differentiate traj wrt t\n"
                         "newton: F = m*a\n    by given\n"
                         "falling: F = m*g\n    by substitute a = g into newton\n"
                         "cons: m*v + M*V = (m + M)*u\n    by given\n"
                         "common: u = (m*v + M*V)/(m + M)\n    by solve cons for u\n"
                         "common_slip: u = (m*v + M*V)/m\n    by solve cons for u\n"
                         "plane: cross(w1, w2) = w1n*w2_y - w1t*w2_x\n    by rewrite\n");
  CHECK(c.kind("velocity") == K::Proved);
  CHECK(c.kind("velocity_slip") == K::Refuted);
  CHECK(c.kind("falling") == K::Proved);
  CHECK(c.kind("common") == K::Proved);
  CHECK(c.kind("common_slip") == K::Refuted);
  CHECK(c.kind("plane") == K::Proved);
}

TEST_CASE("vectors: shape errors are positioned input errors", "[vectors]") {
  const std::string decl = "symbol m : positive [kg]\nvector v, u : 3 [m/s]\nvector q : 2 [m/s]\n";
  CHECK(input_error(decl + "s: v + m = u\n    by given\n") == "4:6: cannot add a vector and a number");
  CHECK(input_error(decl + "s: v*u = m\n    by given\n") ==
        "4:5: a product of two vectors: write dot(u, v) or cross(u, v)");
  CHECK(input_error(decl + "s: v = m\n    by given\n").find("a vector equated with a number") != std::string::npos);
  CHECK(input_error(decl + "s: v = q\n    by given\n").find("vectors of 3 and 2 components") != std::string::npos);
  CHECK(input_error(decl + "s: sin(v) = m\n    by given\n").find("must be a number, not a vector") != std::string::npos);
  CHECK(input_error(decl + "s: dot(v, q) = m\n    by given\n").find("vectors of 3 and 2 components") != std::string::npos);
  CHECK(input_error("vector v : 4 [m]\ns: v = v\n    by given\n").find("2 or 3") != std::string::npos);
  CHECK(input_error("symbol v_x : real [s]\nvector v : 2 [m]\ns: v = v\n    by given\n")
            .find("the component 'v_x' of vector 'v' is already a name of another kind or unit") != std::string::npos);
  // a component of the vector's unit declared before is adopted
  CHECK(input_error("symbol v_x : real [m]\nvector v : 2 [m]\ns: v = v\n    by given\n") == "no error");
  CHECK(input_error("symbol x : real [m]\ns: [x, x, x, x] = [x, x, x, x]\n    by given\n").find("2 or 3 components") !=
        std::string::npos);
}

TEST_CASE("vectors: dimensions are checked per component", "[vectors]") {
  Checked c = check_text("symbol m : positive [kg]\nvector F : 3 [N]\nvector v : 3 [m/s]\n"
                         "wrong: F = m*v\n    by given\n");
  REQUIRE(!c.at("wrong").errors.empty());
  CHECK(c.at("wrong").errors[0].message().find("dimension mismatch") != std::string::npos);
}

TEST_CASE("vectors: the LaTeX prints them bold, or with arrows", "[vectors]") {
  const dc::Derivation bold = dc::parse_derivation(dc::SourceText{
      "b.dc", "symbol m : positive [kg]\nvector p : 3 [kg*m/s]\nvector v, v0 : 3 [m/s]\n"
              "s: p = m*v + m*[v0_x, 0, 0]\n    by given\n"});
  const std::string tex = dc::latex_relation(bold.steps[0].claim, bold.symbols);
  CHECK(tex.find("\\mathbf{p}") != std::string::npos);
  CHECK(tex.find("\\begin{pmatrix}") != std::string::npos);
  const dc::Derivation arrows = dc::parse_derivation(dc::SourceText{
      "a.dc", "symbol m : positive [kg]\nvector p : 3 [kg*m/s]\nvector v0 : 3 [m/s]\nnotation arrows\n"
              "s: p = m*v0\n    by given\n"});
  const std::string tex2 = dc::latex_relation(arrows.steps[0].claim, arrows.symbols);
  CHECK(tex2.find("\\vec{p}") != std::string::npos);
  CHECK(tex2.find("\\vec{v}_{0}") != std::string::npos);
  // a vector literal reads back as written
  CHECK(dc::to_text(bold.steps[0].claim) == "p = m*v + m*[v0_x, 0, 0]");
}
