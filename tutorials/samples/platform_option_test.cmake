# platform_option_test.cmake: a tutorial program's -platform option.
#   cmake -DPROGRAM=<sample exe> -DWORK_DIR=<scratch dir> -P platform_option_test.cmake
# For each backend name the program runs to the end (status 0) and prints
# "platform backend: B"; B is the name asked for when the CPU runs it, else
# a warning names it as unsupported and B is another one; the trajectory's
# header records the same B. An unknown name is refused: a non-zero status
# and a message naming it.
foreach(var PROGRAM WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "platform_option_test.cmake: -D${var}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

foreach(name reference sse4 avx2 avx512)
  set(trajectory "${WORK_DIR}/${name}.txt")
  execute_process(COMMAND "${PROGRAM}" -null -frames 3 -platform ${name} -trajectory "${trajectory}"
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("-platform ${name}:\n${out}${err}")
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "-platform ${name}: the program failed (${code})")
  endif()
  if(NOT out MATCHES "platform backend: ([a-z0-9]+)\n")
    message(FATAL_ERROR "-platform ${name}: no 'platform backend:' line")
  endif()
  set(ran "${CMAKE_MATCH_1}")
  if(NOT ran STREQUAL name AND NOT err MATCHES "'${name}' is not available \\(this CPU does not support it\\): using '${ran}'")
    message(FATAL_ERROR "-platform ${name}: ran on ${ran} without saying why")
  endif()
  file(STRINGS "${trajectory}" header REGEX "^backend ")
  if(NOT header STREQUAL "backend ${ran}")
    message(FATAL_ERROR "-platform ${name}: the trajectory says '${header}', the program ran on ${ran}")
  endif()
endforeach()

execute_process(COMMAND "${PROGRAM}" -null -frames 3 -platform neon
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("-platform neon:\n${out}${err}")
if(code EQUAL 0)
  message(FATAL_ERROR "-platform neon: accepted (status 0)")
endif()
if(NOT "${out}${err}" MATCHES "'neon' for -platform")
  message(FATAL_ERROR "-platform neon: refused without naming it")
endif()
