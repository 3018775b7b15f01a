# karma_add_golden_test(): pin a program's output with a golden (docs/GOLDEN.md).
#
#   karma_add_golden_test(NAME <test> PROGRAM <target> STEP <step>
#                         [GOLDEN_PROGRAM <name>]   # golden/<name>/..., default: <target>
#                         [BACKENDS <backend>...]   # default: KARMA_GOLDEN_BACKENDS
#                         [ARGS <arg>...]           # the program's own arguments
#                         [CHECK_ARGS <arg>...]     # extra `karma-golden check` options
#                         [GOLDEN_ROOT <dir>])      # default: <project source>/golden
#
# Registers one CTest test per platform backend, labelled `golden` and
# `backend-<backend>`: <test> for `reference`, <test>.<backend> for the
# others (BACKEND <backend> is a synonym of BACKENDS with one backend). Each
# runs run_golden.cmake: the program runs with KARMA_PLATFORM=<backend> in its
# environment and ARGS followed by
#     -platform <backend> -trajectory <out>/trajectory.txt -out <out>
# in a fresh directory <out> of the build tree, and its output is compared with
#     <GOLDEN_ROOT>/<GOLDEN_PROGRAM>/<step>/<backend>-<precision>/
# by `karma-golden check`. A backend this CPU lacks (karma-platforms
# --supported) makes the test SKIPPED, with a message naming the backend.
# With KARMA_GOLDEN_REGENERATE=1 in the environment (Karma's
# scripts/golden-regen sets it) the outputs replace the golden instead; a
# backend whose outputs equal the reference's gets a symbolic link to the
# reference's directory (docs/GOLDEN.md, "Backends share goldens").
#
# KARMA_GOLDEN_BACKENDS (a list; Karma's build has it as a cache option)
# chooses the backends when BACKENDS is not given; unset, it is every
# backend: KARMA_GOLDEN_ALL_BACKENDS, which `karma-platforms --names` lists
# too (a test checks they agree).
#
# In Karma's own build the tools are the targets karma-golden and
# karma-platforms and the precision KARMA_PRECISION; in a project that did
# find_package(Karma), which includes this file, they are Karma::karma-golden,
# Karma::karma-platforms and Karma_PRECISION.
#
# Arguments travel to the driver one -D variable each (ARG_COUNT, ARG_0, ...),
# so they may contain spaces; they may not contain ';'.
#
# _karma_golden_constants(): sets, in the caller's scope, KARMA_GOLDEN_ALL_BACKENDS
# and KARMA_GOLDEN_SKIP_REGEX, the message that makes CTest report a golden
# test as skipped (run_golden.cmake prints it, naming the backend, when the
# CPU lacks the backend). A macro, so that the function below sees them from
# whatever directory calls it.
macro(_karma_golden_constants)
  set(KARMA_GOLDEN_ALL_BACKENDS reference sse4 avx2 avx512)
  set(KARMA_GOLDEN_SKIP_REGEX "SKIPPED: this CPU does not support the platform backend")
endmacro()
_karma_golden_constants()

# _karma_golden_tool(<var> <name>): the target of tool <name>, in Karma's build
# or an installed Karma.
function(_karma_golden_tool var name)
  if(TARGET ${name})
    set(${var} ${name} PARENT_SCOPE)
  elseif(TARGET Karma::${name})
    set(${var} Karma::${name} PARENT_SCOPE)
  else()
    message(FATAL_ERROR "karma_add_golden_test: no ${name} target (find_package(Karma) first)")
  endif()
endfunction()

function(karma_add_golden_test)
  cmake_parse_arguments(PARSE_ARGV 0 G "" "NAME;PROGRAM;STEP;GOLDEN_PROGRAM;BACKEND;GOLDEN_ROOT" "BACKENDS;ARGS;CHECK_ARGS")
  if(G_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "karma_add_golden_test: unexpected arguments: ${G_UNPARSED_ARGUMENTS}")
  endif()
  foreach(required NAME PROGRAM STEP)
    if(NOT G_${required})
      message(FATAL_ERROR "karma_add_golden_test: ${required} is required")
    endif()
  endforeach()
  if(NOT TARGET ${G_PROGRAM})
    message(FATAL_ERROR "karma_add_golden_test(${G_NAME}): ${G_PROGRAM} is not a target")
  endif()
  if(NOT G_GOLDEN_PROGRAM)
    set(G_GOLDEN_PROGRAM ${G_PROGRAM})
  endif()
  _karma_golden_constants()
  if(G_BACKEND)
    list(APPEND G_BACKENDS ${G_BACKEND})
  endif()
  if(NOT G_BACKENDS)
    if(DEFINED KARMA_GOLDEN_BACKENDS)
      set(G_BACKENDS ${KARMA_GOLDEN_BACKENDS})
    else()
      set(G_BACKENDS ${KARMA_GOLDEN_ALL_BACKENDS})
    endif()
  endif()
  list(REMOVE_DUPLICATES G_BACKENDS)
  if(NOT G_GOLDEN_ROOT)
    set(G_GOLDEN_ROOT ${PROJECT_SOURCE_DIR}/golden)
  endif()
  set(precision "${KARMA_PRECISION}")
  if(NOT precision)
    set(precision "${Karma_PRECISION}")
  endif()
  if(NOT precision MATCHES "^(single|double)$")
    message(FATAL_ERROR "karma_add_golden_test: KARMA_PRECISION (or Karma_PRECISION) must be single or double")
  endif()
  _karma_golden_tool(tool karma-golden)
  _karma_golden_tool(platforms karma-platforms)

  set(defines)
  list(LENGTH G_ARGS count)
  list(APPEND defines -DARG_COUNT=${count})
  set(i 0)
  foreach(arg IN LISTS G_ARGS)
    list(APPEND defines "-DARG_${i}=${arg}")
    math(EXPR i "${i} + 1")
  endforeach()
  list(LENGTH G_CHECK_ARGS count)
  list(APPEND defines -DCHECK_ARG_COUNT=${count})
  set(i 0)
  foreach(arg IN LISTS G_CHECK_ARGS)
    list(APPEND defines "-DCHECK_ARG_${i}=${arg}")
    math(EXPR i "${i} + 1")
  endforeach()

  foreach(backend IN LISTS G_BACKENDS)
    if(backend STREQUAL "reference")
      set(test ${G_NAME})
    else()
      set(test ${G_NAME}.${backend})
    endif()
    add_test(NAME ${test}
      COMMAND ${CMAKE_COMMAND}
        -DTEST_NAME=${test}
        -DPROGRAM=$<TARGET_FILE:${G_PROGRAM}>
        -DGOLDEN_TOOL=$<TARGET_FILE:${tool}>
        -DPLATFORM_TOOL=$<TARGET_FILE:${platforms}>
        -DGOLDEN_PROGRAM=${G_GOLDEN_PROGRAM}
        -DSTEP=${G_STEP}
        -DBACKEND=${backend}
        -DPRECISION=${precision}
        -DGOLDEN_ROOT=${G_GOLDEN_ROOT}
        -DSOURCE_ROOT=${PROJECT_SOURCE_DIR}
        -DOUTPUT_DIR=${CMAKE_CURRENT_BINARY_DIR}/golden-output/${test}
        ${defines}
        -P ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/run_golden.cmake)
    set_tests_properties(${test} PROPERTIES
      LABELS "golden;backend-${backend}"
      SKIP_REGULAR_EXPRESSION "${KARMA_GOLDEN_SKIP_REGEX}")
    # Another backend's regeneration compares with the reference's golden,
    # so the reference runs first when both are selected.
    if(NOT backend STREQUAL "reference" AND "reference" IN_LIST G_BACKENDS)
      set_tests_properties(${test} PROPERTIES DEPENDS ${G_NAME})
    endif()
  endforeach()
endfunction()
