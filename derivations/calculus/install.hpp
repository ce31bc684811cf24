// dc::calculus::install(): hands the limit engine and the definite-integral method down to
// to_ginac (symbolic/calculus_hooks.hpp), so that limit(...) and integral(f, x, a, b) inside an
// expression have values. Idempotent and cheap; every entry point above this folder calls it.
// (An explicit call, not a static registrar: a registrar's object file in a static library is
// dropped by the linker when nothing else references it.)
#pragma once

namespace dc::calculus {

void install();

}  // namespace dc::calculus
