// The spellings and exit codes of verdicts (verdict.hpp).
#include "derivations/symbolic/verdict.hpp"

#include <ginac/ginac.h>

namespace dc {

DigitsGuard::DigitsGuard(long digits) : saved_(GiNaC::Digits) { GiNaC::Digits = digits; }
DigitsGuard::~DigitsGuard() { GiNaC::Digits = saved_; }

const char* to_string(VerdictKind k) {
  switch (k) {
    case VerdictKind::Proved: return "proved";
    case VerdictKind::HoldsNumerically: return "holds_numerically";
    case VerdictKind::Refuted: return "refuted";
    case VerdictKind::Undecided: return "undecided";
  }
  return "undecided";
}

const char* verdict_words(VerdictKind k) {
  switch (k) {
    case VerdictKind::Proved: return "proved";
    case VerdictKind::HoldsNumerically: return "holds numerically";
    case VerdictKind::Refuted: return "refuted";
    case VerdictKind::Undecided: return "undecided";
  }
  return "undecided";
}

int exit_code_of(VerdictKind k) {
  switch (k) {
    case VerdictKind::Proved:
    case VerdictKind::HoldsNumerically: return kExitOk;
    case VerdictKind::Refuted: return kExitRefuted;
    case VerdictKind::Undecided: return kExitUndecided;
  }
  return kExitInternal;
}

}  // namespace dc
