// Forwarding header: the rule checkers moved to derivations/rules/ (check_step and
// check_derivation are declared in derivations/rules/check.hpp).
#pragma once
#include "derivations/rules/check.hpp"
