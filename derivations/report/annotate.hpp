// `derivcheck annotate`: the author's own document, unchanged except for a note after each
// displayed equation with the checker's verdict on each of its rows (docs/documents.md).
#pragma once
#include <string>

#include "derivations/reader/derivation.hpp"
#include "derivations/rules/check.hpp"

namespace dc {

// The text of the document `d` was read from (a .tex or .md file), with a note inserted after
// every display: per row, its line, the verdict and the justification or the evidence against
// it. LaTeX notes are plain paragraphs (no package needed), Markdown notes block quotes.
// Deterministic.
std::string annotate_document(const Derivation& d, const CheckSummary& summary);

}  // namespace dc
