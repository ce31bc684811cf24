// The sign a '±' is read with (symbols.hpp): one process-wide choice, like GiNaC's Digits, set
// by a scoped PlusMinusSign while a step with ± is checked for that sign.
#include "derivations/symbolic/symbols.hpp"

namespace dc {

namespace {
int g_plus_minus_sign = 0;
}  // namespace

int plus_minus_sign() { return g_plus_minus_sign; }
PlusMinusSign::PlusMinusSign(int sign) : saved_(g_plus_minus_sign) { g_plus_minus_sign = sign; }
PlusMinusSign::~PlusMinusSign() { g_plus_minus_sign = saved_; }

bool has_plus_minus(const Node& n) {
  if (n.kind == NodeKind::Call && (n.text == "pm" || n.text == "mp")) return true;
  for (const auto& a : n.args)
    if (has_plus_minus(a)) return true;
  return false;
}

}  // namespace dc
