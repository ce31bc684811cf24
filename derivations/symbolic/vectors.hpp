// Vectors: `vector F, a : 3 [N]` (2 or 3 components), literals `[a, b, c]`, `dot(u, v)`,
// `cross(u, v)`, `norm(u)`, a vector function of t (`vector r(t) : 3 [m]`) and its derivative
// `diff(r(t), t)`.
//
// A vector is its components: `v` declared with 3 components is the three real symbols v_x,
// v_y, v_z (or the names after `components`), each with the vector's unit. Everything here is a
// rewriting of the author's tree, before GiNaC sees it:
//   - vector_component(n, k): the k-th component of a vector-valued expression, a scalar tree
//     (`m*v` -> `m*v_y`, `cross(r, p)` -> `r_z*p_x - r_x*p_z`, `diff(r(t), t)` -> `diff(r_y(t), t)`);
//   - scalar_form(n): a scalar expression with its dot products and norms written out
//     (`dot(u, v)` -> `u_x*v_x + u_y*v_y + u_z*v_z`, `norm(u)` -> `sqrt(u_x^2 + ...)`).
// So a vector equation is one equation per component, checked by the step's rule each
// (rules/vectors.hpp), and a vector reference gives a rule all its components as equations.
// The cross product of two 2-D vectors is the scalar u_x*v_y - u_y*v_x (the z component of
// the 3-D product), as plane mechanics uses it.
//
// Shape errors are input errors at the operator: adding a vector and a number, a product of two
// vectors (write dot or cross), a vector where a number is needed (an argument of sin, an
// exponent, a denominator), vectors of 2 and of 3 components together.
#pragma once
#include "derivations/symbolic/symbols.hpp"

namespace dc {

// Does n use vector notation (a declared vector, a literal, dot, cross or norm)?
bool has_vector_notation(const Node& n, const SymbolTable& table);

// 0 for a scalar expression, else its number of components. Throws InputError on a shape error.
int vector_shape(const Node& n, const SymbolTable& table);
// The number of components of a relation (all sides alike), 0 when scalar; InputError when
// the sides differ.
int vector_shape(const Relation& r, const SymbolTable& table);

// Component k (1-based) of the vector-valued n, as a scalar tree.
Node vector_component(const Node& n, const SymbolTable& table, int k);
Relation vector_component(const Relation& r, const SymbolTable& table, int k);

// The scalar n with dot products and norms written out; InputError when n is a vector.
Node scalar_form(const Node& n, const SymbolTable& table);

// The component names a declaration gets by default: v_x, v_y (, v_z).
std::vector<std::string> default_component_names(const std::string& vector_name, int dim);

}  // namespace dc
