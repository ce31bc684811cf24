// The pool of abstract GiNaC functions (see functions.hpp).
#include "derivations/symbolic/functions.hpp"

#include <array>
#include <stdexcept>
#include <string>

namespace dc {
namespace {

// Registered on first use (not at static initialisation, so the order of static
// constructors across translation units cannot matter). No eval/evalf/derivative functions
// are set, so GiNaC keeps applications unevaluated and differentiates to fderivative.
const std::array<unsigned, kFunctionPoolSize>& serials() {
  static const std::array<unsigned, kFunctionPoolSize> table = [] {
    std::array<unsigned, kFunctionPoolSize> s{};
    for (int i = 0; i < kFunctionPoolSize; ++i) {
      std::string name = "dcfn" + std::to_string(i);
      s[static_cast<std::size_t>(i)] = GiNaC::function::register_new(GiNaC::function_options(name, 1));
    }
    return s;
  }();
  return table;
}

}  // namespace

GiNaC::ex apply_pool_function(int index, const GiNaC::ex& arg) {
  if (index < 0 || index >= kFunctionPoolSize)
    throw std::out_of_range("abstract function index " + std::to_string(index) + " outside the pool of " +
                            std::to_string(kFunctionPoolSize));
  return GiNaC::function(serials()[static_cast<std::size_t>(index)], arg);
}

int pool_function_index(const GiNaC::ex& e) {
  if (!GiNaC::is_a<GiNaC::function>(e)) return -1;
  unsigned serial = GiNaC::ex_to<GiNaC::function>(e).get_serial();
  const auto& s = serials();
  for (int i = 0; i < kFunctionPoolSize; ++i)
    if (s[static_cast<std::size_t>(i)] == serial) return i;
  return -1;
}

int pool_derivative_order(const GiNaC::ex& e) {
  if (pool_function_index(e) < 0) return -1;
  if (GiNaC::is_a<GiNaC::fderivative>(e))
    return static_cast<int>(GiNaC::ex_to<GiNaC::fderivative>(e).derivatives().size());
  return 0;
}

const SymbolInfo* pool_function_info(int index, const SymbolTable& table) {
  for (const SymbolInfo& info : table.all())
    if (info.is_function && table.function_index(info.name) == index) return &info;
  return nullptr;
}

}  // namespace dc
