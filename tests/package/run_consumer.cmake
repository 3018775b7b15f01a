# Driver for the package.consumer test (see CMakeLists.txt beside it).
# Every step must succeed; the consumer program itself checks that both
# include styles resolve to the installed headers and that the library links.
cmake_minimum_required(VERSION 3.22)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "step failed (${rc}): ${cmd}\n--- stdout\n${out}\n--- stderr\n${err}")
  endif()
  set(RUN_OUTPUT "${out}" PARENT_SCOPE)
endfunction()

set(prefix "${WORK_DIR}/prefix")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# 1. Install into the scratch prefix.
run(${CMAKE_COMMAND} --install "${KARMA_BINARY_DIR}" --prefix "${prefix}")
foreach(f include/karma/Mdt.h include/karma/MeConfig.h include/karma/MePrecision.h)
  if(NOT EXISTS "${prefix}/${f}")
    message(FATAL_ERROR "install tree lacks ${f}")
  endif()
endforeach()

# 2. find_package(Karma) consumer.
set(build "${WORK_DIR}/build-cmake")
run(${CMAKE_COMMAND} -S "${CONSUMER_SOURCE_DIR}" -B "${build}" -G "${GENERATOR}"
    -DCMAKE_C_COMPILER=${C_COMPILER} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
    "-DCMAKE_C_FLAGS=${C_FLAGS}" "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${EXE_LINKER_FLAGS}"
    -DCMAKE_PREFIX_PATH=${prefix} -DEXPECTED_PRECISION=${KARMA_PRECISION})
run(${CMAKE_COMMAND} --build "${build}")
foreach(app consumer_c consumer_cxx)
  run("${build}/${app}")
  if(NOT RUN_OUTPUT MATCHES "karma consumer ok")
    message(FATAL_ERROR "${app} printed unexpected output:\n${RUN_OUTPUT}")
  endif()
  message(STATUS "${app}: ${RUN_OUTPUT}")
endforeach()

# 3. pkg-config consumer: compile the C program by hand with karma.pc's flags.
find_program(PKG_CONFIG pkg-config REQUIRED)
set(ENV{PKG_CONFIG_PATH} "${prefix}/lib/pkgconfig")
run(${PKG_CONFIG} --cflags --libs --static karma)
string(STRIP "${RUN_OUTPUT}" flags)
separate_arguments(flags UNIX_COMMAND "${flags}")
separate_arguments(build_flags UNIX_COMMAND "${C_FLAGS} ${EXE_LINKER_FLAGS}")
run(${C_COMPILER} -std=c11 -Wall -Wextra -Werror ${build_flags} "${CONSUMER_SOURCE_DIR}/main.c"
    -o "${WORK_DIR}/consumer_pc" ${flags} -lstdc++)
run("${WORK_DIR}/consumer_pc")
if(NOT RUN_OUTPUT MATCHES "karma consumer ok")
  message(FATAL_ERROR "pkg-config consumer printed unexpected output:\n${RUN_OUTPUT}")
endif()
message(STATUS "pkg-config consumer: ${RUN_OUTPUT}")
