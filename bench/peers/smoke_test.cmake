# Runs peer_bench on the car for 30 steps, once, on Karma's reference
# backend, and requires exit code 0, the line naming that backend, the
# table's header and one row per engine in ENGINES (a ;-list).
execute_process(COMMAND ${RUNNER} --scenes car --steps 30 --reps 1 --platform reference
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "peer_bench exited with ${code}: ${err}")
endif()
if(NOT out MATCHES "Karma platform backend: reference\n")
  message(FATAL_ERROR "peer_bench did not name Karma's platform backend")
endif()
if(NOT out MATCHES "\\| scene \\(steps\\) \\| engine \\|")
  message(FATAL_ERROR "peer_bench printed no table header")
endif()
foreach(engine IN LISTS ENGINES)
  if(NOT out MATCHES "\\| car \\(30 of 300\\) \\| ${engine} \\| [0-9.,]+ \\[")
    message(FATAL_ERROR "peer_bench printed no row for ${engine}")
  endif()
endforeach()
