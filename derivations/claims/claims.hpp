// One-off claims: `derivcheck equal` and the JSONL claim bank of `derivcheck claims`
// (docs/cli.md). A claim names its symbols implicitly: every identifier of its expressions is
// a symbol, real unless an assumption gives it a domain.
#pragma once
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "derivations/decide/prove.hpp"
#include "derivations/symbolic/symbols.hpp"
#include "derivations/symbolic/verdict.hpp"

namespace dc {

// An assumption list as written for `equal --assume`: "m1>0, v1 real, e in [0,1], v1 > v2".
// Items: `x > 0` (positive), `x >= 0` (nonnegative), `x < 0` (negative), `x real`,
// `x positive|nonnegative|negative`, `x in [a,b]` (also (a,b), half-open), and relations
// between expressions with < <= > >= != (constraints). Positions refer to `origin`.
struct AssumptionItem {
  std::string name;             // for domain items
  Domain domain;
  bool is_constraint = false;   // a relation between expressions
  Node lhs, rhs;                // for constraints
  Constraint::Op op = Constraint::Op::Gt;
  std::string text;
  SourcePos pos;
};
std::vector<AssumptionItem> parse_assumptions(const std::string& text, const SourcePos& origin);

// Build a symbol table for expressions: every identifier (not a builtin, not pi) in order of
// first appearance becomes a symbol (real, dimensionless), with domains from `domains`
// (name -> domain; the position is where that domain was written) and the constraints of
// `items`. Throws InputError for conflicting domains and for assumptions that cannot all hold.
// `functions` ({name, parameter}) are declared after the symbols as functions of one declared
// symbol, as `function y(t) : real` declares them in a .dc file (a solves_ode claim's y).
struct DomainAt {
  Domain domain;
  SourcePos pos;
};
SymbolTable claim_table(const std::vector<const Node*>& exprs, const std::map<std::string, DomainAt>& domains,
                        const std::vector<AssumptionItem>& items, const SourcePos& assume_pos,
                        const std::vector<std::pair<std::string, std::string>>& functions = {});

// `derivcheck equal`: parse both sides and the assumption list, then check `lhs = rhs` as a
// one-step derivation (by rewrite, or by integrate when a side has an integral): the code of
// the .dc rules (derivations/claims/internal/claim_steps.hpp).
Verdict check_equal(const std::string& lhs, const std::string& rhs, const std::string& assume,
                    const ProveOptions& opt = {});
// The same check on sides already read into `table` (the Catch2 matchers). Throws InputError
// when a side cannot be checked (the error's position is in the side it comes from).
Verdict check_equal_in(const SymbolTable& table, const Node& lhs, const Node& rhs, const ProveOptions& opt = {});

// One line of a claim bank. Never throws: a malformed line gives a result with "error". Each
// kind of claim is checked as the one-step derivation of internal/claim_steps.hpp.
// Keys in order: id (when the line has one), line, kind, verdict, method, (evidence), seconds | error.
nlohmann::ordered_json check_claim_line(const std::string& line, int line_no, const std::string& file,
                                        const ProveOptions& opt = {});

// The result of a line that is not a claim at all (e.g. longer than the line limit):
// {"id" (when known), "line", "verdict": "error", "error": "file:N: error: message"}.
nlohmann::ordered_json claim_line_error(int line_no, const std::string& file, const std::string& message,
                                        const nlohmann::json* id = nullptr);

// The result of a claim that was tried but not finished (its budget ran out): {"id", "line",
// "kind", "verdict": "undecided", "method", "reason"}.
nlohmann::ordered_json claim_line_undecided(const std::string& line, int line_no, const std::string& method,
                                            const std::string& reason);

}  // namespace dc
