# The command on a small sweep: two settings, six steps of the car and of
# a user's scene library (the example pendulum), 640x480 plots. Checks the
# exit status, the CSV's header and rows, that every plot is a PNG of the
# stated size, the Markdown, and the message when gnuplot is missing.
file(REMOVE_RECURSE "${OUT}")
execute_process(
  COMMAND "${TOOL}" --scene "car,${USER_SCENE}" --sweep "solver=exact,iterative:10" --seconds 0.1 --repeat 2
          --plot-size 640x480 --out "${OUT}"
  RESULT_VARIABLE status ERROR_VARIABLE progress)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "karma-tradeoff failed (${status}):\n${progress}")
endif()
if(NOT progress MATCHES "car: run 4/4 \\(repetition 2/2\\)")
  message(FATAL_ERROR "no progress line for the last run:\n${progress}")
endif()

file(STRINGS "${OUT}/tradeoff.csv" lines)
list(GET lines 0 header)
set(expected "scene,precision,engine,setting,solver,epsilon,gamma,h,tolerance,cap,projection,warm,reuse,repeats,us_per_step,us_min,us_max,us_per_frame,steps,drift_m,joint_error_m,penetration_m,energy_error_J,momentum_error_Ns,residual,unsolved_steps,max_speed_mps,scene_error,held,front_drift,front_scene,detail")
if(NOT header STREQUAL expected)
  message(FATAL_ERROR "CSV header:\n${header}\nexpected:\n${expected}")
endif()
list(LENGTH lines count)
if(NOT count EQUAL 5)
  message(FATAL_ERROR "expected 4 rows (2 scenes x 2 settings), got ${count} lines:\n${lines}")
endif()
foreach(scene car pendulum)
  foreach(setting "exact h=1/60" "iterative:10 h=1/60")
    if(NOT lines MATCHES "${scene},[a-z]+,karma,\"${setting}\",[^;]*,2,[0-9.e+-]+,[0-9.e+-]+,[0-9.e+-]+,[0-9.e+-]+,6,")
      message(FATAL_ERROR "no row for ${scene} ${setting} with 2 repeats and 6 steps:\n${lines}")
    endif()
  endforeach()
endforeach()

# A PNG: the 8-byte signature, then the IHDR chunk with width and height.
foreach(plot car-drift car-scene pendulum-drift pendulum-scene)
  set(png "${OUT}/${plot}.png")
  if(NOT EXISTS "${png}")
    message(FATAL_ERROR "no plot ${png}")
  endif()
  file(READ "${png}" head LIMIT 24 HEX)
  if(NOT head MATCHES "^89504e470d0a1a0a0000000d49484452(........)(........)$")
    message(FATAL_ERROR "${png} is not a PNG: ${head}")
  endif()
  if(NOT CMAKE_MATCH_1 STREQUAL "00000280" OR NOT CMAKE_MATCH_2 STREQUAL "000001e0")
    message(FATAL_ERROR "${png} is ${CMAKE_MATCH_1} x ${CMAKE_MATCH_2} (hex), not 640 x 480")
  endif()
endforeach()

file(READ "${OUT}/tradeoff.md" markdown)
foreach(needle "### car" "### pendulum" "![car: drift against µs per 1/60 s](car-drift.png)" "Drift front: ")
  string(FIND "${markdown}" "${needle}" at)
  if(at LESS 0)
    message(FATAL_ERROR "tradeoff.md lacks '${needle}':\n${markdown}")
  endif()
endforeach()

# Without gnuplot the tool stops at once and says what to install.
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env KARMA_GNUPLOT=/nonexistent/gnuplot
          "${TOOL}" --scene car --seconds 0.1 --out "${OUT}/nognuplot"
  RESULT_VARIABLE status ERROR_VARIABLE message)
if(NOT status EQUAL 3 OR NOT message MATCHES "gnuplot not found: install the Debian package gnuplot-nox")
  message(FATAL_ERROR "without gnuplot: status ${status}, message:\n${message}")
endif()
