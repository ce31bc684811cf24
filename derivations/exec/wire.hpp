// Results crossing from a worker process to the parent: a step's StepResult (without its Step
// pointer, which the parent restores) and an InputError, as length-prefixed binary fields.
// Both ends are the same binary, so the format has no versioning.
#pragma once
#include <optional>
#include <string>

#include "derivations/core/rules.hpp"
#include "derivations/core/source.hpp"

namespace dc::exec {

std::string encode(const StepResult& r);
StepResult decode_step_result(const std::string& bytes, const Step* step);

std::string encode(const InputError& e);
InputError decode_input_error(const std::string& bytes);

}  // namespace dc::exec
