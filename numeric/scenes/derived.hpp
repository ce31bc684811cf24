// Closed forms loaded from the derivation files by label (no hand-typed copies), evaluated
// with the CLN reference (numeric/reference/reference.hpp) and rounded to double.
//
// The scenes ask for a closed form through closed_form(): it evaluates FILE:LABEL from the
// derivation directory when that is given and holds the label, and otherwise falls back to the
// hand-typed built-in value (closed_forms.hpp), saying why in Comparison::source.
#pragma once
#include <map>
#include <optional>
#include <string>

#include "numeric/scenes/spec.hpp"

namespace dc::scenes {

// The value of formula LABEL of DIR/FILE at `at` (parameter name -> value; names the formula
// does not use are ignored). nullopt, with the reason in *why, when dir is empty, the file is
// missing or malformed, or the label is absent or not of the form `y = expression`. Parameters
// the formula needs but `at` lacks, and values outside the formula's domain, also give nullopt.
// Files are parsed once per process (cached; thread-safe).
std::optional<double> derived_value(const std::string& dir, const std::string& file, const std::string& label,
                                    const std::map<std::string, double>& at, std::string* why = nullptr);

// A comparison whose closed form comes from the derivation file when possible: `builtin` is the
// hand-typed value; with a derived value, Comparison::builtin keeps it for the cross-check.
Comparison closed_form(const RunOptions& opt, std::string quantity, std::string unit, double simulated,
                       double builtin, std::string formula, const std::string& file, const std::string& label,
                       const std::map<std::string, double>& at);

}  // namespace dc::scenes
