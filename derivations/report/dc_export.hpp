// `derivcheck dc`: a checked LaTeX or Markdown document written as the equivalent .dc file,
// each row with the rule the search found (docs/documents.md), for an author who wants to
// keep the derivation in the checker's own language.
#pragma once
#include <string>

#include "derivations/reader/derivation.hpp"
#include "derivations/rules/check.hpp"

namespace dc {

// The .dc text of document derivation `d` with its check `summary`. Every name the document
// uses is declared as it was read (real and dimensionless unless a `derivcheck:` directive
// said otherwise); every displayed relation and equation of the text is a step, labelled by
// its line (`L38_2` for the second relation of line 38, `I15_124` for an equation of the text
// at line 15, column 124), with the tag of its row. A derived row gets the rule line that was
// checked; a refuted row the rule it was refuted against (so checking the .dc file refutes it
// too); a row with no justification found, or refuted by a rule no .dc line states, is written
// `by given` with a TODO note that says so and why. Rows the .dc language cannot state (≈, inequalities, rows
// not read) are comments. Deterministic.
std::string document_as_dc(const Derivation& d, const CheckSummary& summary);

}  // namespace dc
