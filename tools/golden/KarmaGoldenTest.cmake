# karma_add_golden_test(): pin a program's output with a golden (docs/GOLDEN.md).
#
#   karma_add_golden_test(NAME <test> PROGRAM <target> STEP <step>
#                         [GOLDEN_PROGRAM <name>]   # golden/<name>/..., default: <target>
#                         [BACKEND <backend>]       # default: reference
#                         [ARGS <arg>...]           # the program's own arguments
#                         [CHECK_ARGS <arg>...]     # extra `karma-golden check` options
#                         [GOLDEN_ROOT <dir>])      # default: <project source>/golden
#
# Registers the CTest test <test>, labelled `golden`, which runs run_golden.cmake:
# the program runs with ARGS followed by
#     -platform <backend> -trajectory <out>/trajectory.txt -out <out>
# in a fresh directory <out> of the build tree, and its output is compared with
#     <GOLDEN_ROOT>/<GOLDEN_PROGRAM>/<step>/<backend>-<precision>/
# by `karma-golden check`. With KARMA_GOLDEN_REGENERATE=1 in the environment
# (Karma's scripts/golden-regen sets it) the outputs replace the golden instead.
#
# In Karma's own build the tool is the target karma-golden and the precision
# KARMA_PRECISION; in a project that did find_package(Karma), which includes
# this file, they are Karma::karma-golden and Karma_PRECISION.
#
# Arguments travel to the driver one -D variable each (ARG_COUNT, ARG_0, ...),
# so they may contain spaces; they may not contain ';'.
function(karma_add_golden_test)
  cmake_parse_arguments(PARSE_ARGV 0 G "" "NAME;PROGRAM;STEP;GOLDEN_PROGRAM;BACKEND;GOLDEN_ROOT" "ARGS;CHECK_ARGS")
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
  if(NOT G_BACKEND)
    set(G_BACKEND reference)
  endif()
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
  if(TARGET karma-golden)
    set(tool karma-golden)
  elseif(TARGET Karma::karma-golden)
    set(tool Karma::karma-golden)
  else()
    message(FATAL_ERROR "karma_add_golden_test: no karma-golden target (find_package(Karma) first)")
  endif()

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

  add_test(NAME ${G_NAME}
    COMMAND ${CMAKE_COMMAND}
      -DTEST_NAME=${G_NAME}
      -DPROGRAM=$<TARGET_FILE:${G_PROGRAM}>
      -DGOLDEN_TOOL=$<TARGET_FILE:${tool}>
      -DGOLDEN_PROGRAM=${G_GOLDEN_PROGRAM}
      -DSTEP=${G_STEP}
      -DBACKEND=${G_BACKEND}
      -DPRECISION=${precision}
      -DGOLDEN_ROOT=${G_GOLDEN_ROOT}
      -DSOURCE_ROOT=${PROJECT_SOURCE_DIR}
      -DOUTPUT_DIR=${CMAKE_CURRENT_BINARY_DIR}/golden-output/${G_NAME}
      ${defines}
      -P ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/run_golden.cmake)
  set_tests_properties(${G_NAME} PROPERTIES LABELS golden)
endfunction()
