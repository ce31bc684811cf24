// Linked into every test binary: the calculus library's hooks for to_ginac (limit(...) and
// definite integrals inside expressions) are installed before any test runs, as the CLI and
// the readers do (derivations/calculus/install.hpp).
#include "derivations/calculus/install.hpp"

namespace {
const bool installed = (dc::calculus::install(), true);
}  // namespace
