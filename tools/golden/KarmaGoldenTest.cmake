# karma_add_golden_test(): pin a program's output with a golden (docs/GOLDEN.md).
#
#   karma_add_golden_test(NAME <test> PROGRAM <target> STEP <step>
#                         [GOLDEN_PROGRAM <name>]   # golden/<name>/..., default: <target>
#                         [BACKEND <backend>]       # default: reference
#                         [ARGS <arg>...]           # the program's own arguments
#                         [CHECK_ARGS <arg>...])    # extra `karma-golden check` options
#
# Registers the CTest test <test>, labelled `golden`, which runs run_golden.cmake:
# the program runs with ARGS followed by
#     -platform <backend> -trajectory <out>/trajectory.txt -out <out>
# in a fresh directory <out> of the build tree, and its output is compared with
#     <source>/golden/<GOLDEN_PROGRAM>/<step>/<backend>-<KARMA_PRECISION>/
# by `karma-golden check`. With KARMA_GOLDEN_REGENERATE=1 in the environment
# (set only by scripts/golden-regen) the outputs replace the golden instead.
#
# Arguments travel to the driver one -D variable each (ARG_COUNT, ARG_0, ...),
# so they may contain spaces; they may not contain ';'.
function(karma_add_golden_test)
  cmake_parse_arguments(PARSE_ARGV 0 G "" "NAME;PROGRAM;STEP;GOLDEN_PROGRAM;BACKEND" "ARGS;CHECK_ARGS")
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
  if(NOT KARMA_PRECISION MATCHES "^(single|double)$")
    message(FATAL_ERROR "karma_add_golden_test: KARMA_PRECISION must be single or double")
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
      -DGOLDEN_TOOL=$<TARGET_FILE:karma-golden>
      -DGOLDEN_PROGRAM=${G_GOLDEN_PROGRAM}
      -DSTEP=${G_STEP}
      -DBACKEND=${G_BACKEND}
      -DPRECISION=${KARMA_PRECISION}
      -DGOLDEN_ROOT=${PROJECT_SOURCE_DIR}/golden
      -DSOURCE_ROOT=${PROJECT_SOURCE_DIR}
      -DOUTPUT_DIR=${CMAKE_CURRENT_BINARY_DIR}/golden-output/${G_NAME}
      ${defines}
      -P ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/run_golden.cmake)
  set_tests_properties(${G_NAME} PROPERTIES LABELS golden)
endfunction()
