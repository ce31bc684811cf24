// The author's own LaTeX or Markdown document, checked as written (docs/documents.md).
//
// A document has no rules: every displayed relation is a step whose justification the
// checker looks for (justify.cpp). The reader (reader.cpp) turns the document into the same
// Derivation a .dc file gives — symbols inferred (real unless a `derivcheck:` directive
// declares them), one step per relation of each displayed row, each step carrying what the
// search may use (DocumentRow): the rows nearby, the inline givens in force, the rows the
// author cites. Reports then print every verdict at the author's line.
#pragma once
#include <string>

#include "derivations/reader/derivation.hpp"
#include "derivations/rules/check.hpp"

namespace dc {

// Read a .tex/.md document into a Derivation (throws InputError for a document that cannot be
// read at all: an unclosed display, a malformed directive, no displayed relation). A row that
// cannot be read is a step of its own that is not checked (DocumentRow::not_read); the other
// rows go on.
Derivation read_document(SourceText source);

// A .dc derivation or a document, by the file's extension (is_document_path).
Derivation load_any(const std::string& path);

// The verdict of a document step: the justification search. Deterministic; it tries, in
// order, that the relation is an identity, that it follows from the rows nearby (with the
// inline givens in force and the rows the author cites), and otherwise takes a relation that
// introduces a new name as a given. A refutation needs a counterexample that satisfies the
// rows it came from, and stands only where the row's reading is not in doubt (see
// justify.cpp); otherwise the row is undecided with the reason.
StepResult justify_step(const Derivation& d, const Step& s, const ProveOptions& opt = {});

// check_step for a .dc step, justify_step for a document step.
StepResult check_any_step(const Derivation& d, const Step& s, const ProveOptions& opt = {});

}  // namespace dc
