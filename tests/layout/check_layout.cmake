# The folder list is the architecture (docs/architecture.md). Run as
#   cmake -DROOT=<source dir> -P check_layout.cmake
# and fails (FATAL_ERROR, listing every offence) when
#   - a file includes a header of a folder that comes later in STAGES than its own folder
#     (folders include only themselves and the folders before them);
#   - a source file in a stage folder is not in any known folder (a new folder must be placed);
#   - a .cpp/.hpp file under derivations/ or numeric/ has more than 800 lines, or a folder more
#     than 4000 lines in the files directly inside it.
cmake_minimum_required(VERSION 3.25)
if(NOT ROOT)
  message(FATAL_ERROR "usage: cmake -DROOT=<source dir> -P check_layout.cmake")
endif()

# Dependency order: each folder may include itself and the folders listed before it.
set(STAGES
  derivations/syntax        # the author's text: positions, the expression tree, units, prose
  derivations/syntax/tex    # TeX math rows as authors write them -> the same expression tree
  derivations/symbolic      # the tree as GiNaC: symbols, domains, conversion, printer, verdict types
  derivations/kernel        # trusted: Arb balls, sampling, ranges, the probe, quadrature
  derivations/decide        # prove_equal's cascade, side conditions, satisfiability
  derivations/limit_engine  # Gruntz's algorithm and the numeric witness
  derivations/calculus      # limit entry, order terms, antiderivatives, definite integrals
  derivations/reader        # the .dc reader -> Derivation
  derivations/steps         # what every rule works with: the step's context and result, elimination, follows
  derivations/rules         # one file per rule; check_step / check_derivation
  derivations/document      # the author's LaTeX/Markdown -> Derivation; the justification search
  derivations/report        # text, JSON, LaTeX
  derivations/claims        # the JSONL claim bank and `equal`
  derivations/exec          # worker processes, budgets, batches, shards
  numeric/reference         # exact inputs and the CLN reference values
  numeric                   # fast evaluation: the tape, the JIT front end, double-double, stable forms, cross-checks
  numeric/certified         # certified evaluation: results with proven error bounds
  numeric/jit_module        # the LLVM module (loaded at run time)
  numeric/scenes            # the simulations
  numeric/charts            # work-precision charts and stability maps
  derivations/catch         # the Catch2 matchers (header-only)
  apps)                     # the CLI

set(MAX_FILE_LINES 800)
set(MAX_FOLDER_LINES 4000)

# The stage folder of a path relative to ROOT ("" when it is in none): the folder that directly
# holds it (or its internal/ subfolder: headers private to that stage, never installed), or for
# derivations/catch anything below it.
function(stage_of path out)
  set(result "")
  get_filename_component(dir "${path}" DIRECTORY)
  string(REGEX REPLACE "/internal$" "" dir "${dir}")
  foreach(s IN LISTS STAGES)
    if(dir STREQUAL s)
      set(result "${s}")
    elseif(s STREQUAL "derivations/catch" AND path MATCHES "^derivations/catch/")
      set(result "${s}")
    endif()
  endforeach()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

set(offences "")
file(GLOB_RECURSE sources RELATIVE "${ROOT}" "${ROOT}/derivations/*.cpp" "${ROOT}/derivations/*.hpp"
     "${ROOT}/numeric/*.cpp" "${ROOT}/numeric/*.hpp" "${ROOT}/apps/*.cpp" "${ROOT}/apps/*.hpp")
list(SORT sources)
set(checked 0)
foreach(src IN LISTS sources)
  stage_of("${src}" from)
  if(from STREQUAL "")
    list(APPEND offences "${src}: not in a stage folder (add its folder to STAGES in tests/layout/check_layout.cmake and docs/architecture.md)")
    continue()
  endif()
  list(FIND STAGES "${from}" from_index)
  # lines: count the newlines (file(STRINGS) would skip empty lines and split at semicolons)
  file(READ "${ROOT}/${src}" content)
  string(REGEX MATCHALL "\n" newlines "${content}")
  list(LENGTH newlines n)
  if(n GREATER MAX_FILE_LINES AND src MATCHES "^(derivations|numeric)/")
    list(APPEND offences "${src}: ${n} lines (at most ${MAX_FILE_LINES})")
  endif()
  if(NOT DEFINED folder_lines_${from_index})
    set(folder_lines_${from_index} 0)
  endif()
  math(EXPR folder_lines_${from_index} "${folder_lines_${from_index}} + ${n}")
  file(STRINGS "${ROOT}/${src}" includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"(derivations|numeric)/")
  foreach(line IN LISTS includes)
    if(line MATCHES "^[ \t]*#[ \t]*include[ \t]+\"((derivations|numeric)/[^\"]+)\"")
      set(target "${CMAKE_MATCH_1}")
      math(EXPR checked "${checked} + 1")
      stage_of("${target}" to)
      if(to STREQUAL "")
        list(APPEND offences "${src}: includes ${target}, which is in no stage folder")
        continue()
      endif()
      if(NOT EXISTS "${ROOT}/${target}")
        list(APPEND offences "${src}: includes ${target}, which does not exist")
      endif()
      list(FIND STAGES "${to}" to_index)
      if(target MATCHES "/internal/" AND NOT to STREQUAL from)
        list(APPEND offences "${src}: includes ${target}, a header internal to ${to}")
      endif()
      if(to_index GREATER from_index)
        list(APPEND offences "${src}: ${from} includes ${target}: ${to} comes after ${from}")
      endif()
    endif()
  endforeach()
endforeach()

set(i 0)
foreach(s IN LISTS STAGES)
  if(s MATCHES "^(derivations|numeric)" AND NOT s STREQUAL "derivations/catch")
    if(folder_lines_${i} GREATER MAX_FOLDER_LINES)
      list(APPEND offences "${s}/: ${folder_lines_${i}} lines in its own files (at most ${MAX_FOLDER_LINES})")
    endif()
  endif()
  math(EXPR i "${i} + 1")
endforeach()

if(NOT DEFINED MIN_INCLUDES)
  set(MIN_INCLUDES 100)
endif()
if(checked LESS MIN_INCLUDES)
  list(APPEND offences "only ${checked} project includes found: the scan is broken")
endif()
list(LENGTH offences n_off)
if(n_off GREATER 0)
  list(JOIN offences "\n  " text)
  message(FATAL_ERROR "layout: ${n_off} offence(s):\n  ${text}")
endif()
list(LENGTH sources n_src)
message(STATUS "layout: ${n_src} files, ${checked} project includes, all one-way")
