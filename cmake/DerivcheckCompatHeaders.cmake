# Installed include paths of releases before the stage layout (docs/architecture.md): each old
# header is installed as a one-line forwarder to its new home, so that code written against
# "derivations/core/prove.hpp" keeps compiling. Only in the install tree: the source tree has
# no forwarders (the layout test would reject them). Pairs: OLD NEW[,NEW...]
set(DERIVCHECK_COMPAT_HEADERS
  "derivations/integrals/antiderivative.hpp" "derivations/calculus/antiderivative.hpp"
  "derivations/core/big_o.hpp" "derivations/calculus/big_o.hpp"
  "derivations/integrals/definite.hpp" "derivations/calculus/definite.hpp"
  "derivations/core/integral_equal.hpp" "derivations/calculus/integral_equal.hpp"
  "derivations/core/limit.hpp" "derivations/calculus/limit_entry.hpp"
  "derivations/core/claims.hpp" "derivations/claims/claims.hpp"
  "derivations/core/prove.hpp" "derivations/decide/prove.hpp"
  "derivations/core/satisfiable.hpp" "derivations/decide/satisfiable.hpp"
  "derivations/limits/budget.hpp" "derivations/limit_engine/budget.hpp"
  "derivations/limits/gruntz.hpp" "derivations/limit_engine/gruntz.hpp"
  "derivations/limits/limits.hpp" "derivations/limit_engine/limits.hpp"
  "derivations/limits/wseries.hpp" "derivations/limit_engine/wseries.hpp"
  "derivations/core/derivation.hpp" "derivations/reader/derivation.hpp"
  "derivations/core/latex.hpp" "derivations/report/latex.hpp"
  "derivations/core/latex_read.hpp" "derivations/report/latex_read.hpp"
  "derivations/core/report.hpp" "derivations/report/report.hpp"
  "derivations/core/functions.hpp" "derivations/symbolic/functions.hpp"
  "derivations/core/symbols.hpp" "derivations/symbolic/symbols.hpp"
  "derivations/core/verdict.hpp" "derivations/symbolic/verdict.hpp"
  "derivations/core/expr.hpp" "derivations/syntax/expr.hpp"
  "derivations/core/io.hpp" "derivations/syntax/io.hpp"
  "derivations/core/literal.hpp" "derivations/syntax/literal.hpp"
  "derivations/core/prose.hpp" "derivations/syntax/prose.hpp"
  "derivations/core/source.hpp" "derivations/syntax/source.hpp"
  "derivations/core/units.hpp" "derivations/syntax/units.hpp"
  "numeric/certified.hpp" "numeric/certified/certified.hpp"
  "numeric/certified_batch.hpp" "numeric/certified/certified_batch.hpp"
  "numeric/certified_fast.hpp" "numeric/certified/certified_fast.hpp"
  "numeric/certified_steps.hpp" "numeric/certified/certified_steps.hpp"
  "numeric/chart_checker.hpp" "numeric/charts/chart_checker.hpp"
  "numeric/chart_data.hpp" "numeric/charts/chart_data.hpp"
  "numeric/chart_ode_maps.hpp" "numeric/charts/chart_ode_maps.hpp"
  "numeric/chart_plot.hpp" "numeric/charts/chart_plot.hpp"
  "numeric/exact.hpp" "numeric/reference/exact.hpp"
  "numeric/reference.hpp" "numeric/reference/reference.hpp"
  "derivations/core/printer.hpp" "derivations/symbolic/printer.hpp"
  "derivations/core/rules.hpp" "derivations/rules/check.hpp"
  "derivations/core/prove_detail.hpp" "derivations/symbolic/inspect.hpp,derivations/symbolic/printer.hpp,derivations/kernel/range.hpp,derivations/kernel/sample.hpp"
  "derivations/rules/context.hpp" "derivations/steps/context.hpp"
  "derivations/rules/elimination.hpp" "derivations/steps/elimination.hpp"
  "derivations/rules/follows.hpp" "derivations/steps/follows.hpp"
  "derivations/rules/counterexample.hpp" "derivations/steps/counterexample.hpp"
)

list(LENGTH DERIVCHECK_COMPAT_HEADERS _dc_n)
math(EXPR _dc_last "${_dc_n} - 1")
foreach(_dc_i RANGE 0 ${_dc_last} 2)
  math(EXPR _dc_j "${_dc_i} + 1")
  list(GET DERIVCHECK_COMPAT_HEADERS ${_dc_i} _dc_old)
  list(GET DERIVCHECK_COMPAT_HEADERS ${_dc_j} _dc_new)
  string(REPLACE "," ";" _dc_new "${_dc_new}")
  set(_dc_text "// Moved: this path is kept for code written before the stage layout (docs/architecture.md).\n#pragma once\n")
  foreach(_dc_h ${_dc_new})
    string(APPEND _dc_text "#include \"${_dc_h}\"\n")
  endforeach()
  file(WRITE "${PROJECT_BINARY_DIR}/compat-headers/${_dc_old}" "${_dc_text}")
endforeach()
install(DIRECTORY ${PROJECT_BINARY_DIR}/compat-headers/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/derivcheck)
