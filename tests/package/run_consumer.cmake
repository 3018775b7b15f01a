# Driver for the package.consumer test (see CMakeLists.txt beside it).
#
# 1. Installs this build into a scratch prefix.
# 2. C-only CMake project (consumer_c/, project(... C)): builds collide.c,
#    runs it, records its golden (KARMA_GOLDEN_REGENERATE=1 ctest), checks it
#    (ctest), then changes the program (drop height 2 m -> 2.1 m) and checks
#    that ctest fails with karma-golden's report of the first frame, body
#    and quantity out of tolerance.
# 3. pkg-config: collide.c compiled and linked by the C compiler with
#    `pkg-config --cflags --libs --static karma` and nothing else.
# 4. C++ project (consumer/): main.c, main.cpp and collide.c.
# Every program must print "karma consumer ok".
cmake_minimum_required(VERSION 3.22)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "step failed (${rc}): ${cmd}\n--- stdout\n${out}\n--- stderr\n${err}")
  endif()
  set(RUN_OUTPUT "${out}" PARENT_SCOPE)
endfunction()

function(expect_ok what)
  if(NOT RUN_OUTPUT MATCHES "karma consumer ok")
    message(FATAL_ERROR "${what} printed unexpected output:\n${RUN_OUTPUT}")
  endif()
  message(STATUS "${what}: ${RUN_OUTPUT}")
endfunction()

set(prefix "${WORK_DIR}/prefix")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(compilers -DCMAKE_C_COMPILER=${C_COMPILER} -DCMAKE_CXX_COMPILER=${CXX_COMPILER}
    "-DCMAKE_C_FLAGS=${C_FLAGS}" "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${EXE_LINKER_FLAGS}")

# 1. Install into the scratch prefix.
run(${CMAKE_COMMAND} --install "${KARMA_BINARY_DIR}" --prefix "${prefix}")
foreach(f include/karma/Mdt.h include/karma/MdtPlatform.h include/karma/MeConfig.h include/karma/MePrecision.h
          lib/cmake/Karma/KarmaGoldenTest.cmake lib/cmake/Karma/run_golden.cmake bin/karma-golden
          bin/karma-platforms)
  if(NOT EXISTS "${prefix}/${f}")
    message(FATAL_ERROR "install tree lacks ${f}")
  endif()
endforeach()

# 2. C-only CMake project, with a golden test of its own.
set(source_c "${CONSUMER_SOURCE_DIR}/../consumer_c")
set(build "${WORK_DIR}/build-c")
set(golden_root "${WORK_DIR}/golden")
run(${CMAKE_COMMAND} -S "${source_c}" -B "${build}" -G "${GENERATOR}" ${compilers}
    -DCMAKE_PREFIX_PATH=${prefix} -DCOLLIDE_GOLDEN_ROOT=${golden_root})
run(${CMAKE_COMMAND} --build "${build}")
run("${build}/collide")
expect_ok("C-only CMake project")
set(ENV{KARMA_GOLDEN_REGENERATE} 1)
run(${CMAKE_CTEST_COMMAND} --test-dir "${build}" --output-on-failure)
unset(ENV{KARMA_GOLDEN_REGENERATE})
if(NOT EXISTS "${golden_root}/collide/main/reference-${KARMA_PRECISION}/trajectory.txt")
  message(FATAL_ERROR "recording the golden wrote no ${golden_root}/collide/main/reference-${KARMA_PRECISION}")
endif()
run(${CMAKE_CTEST_COMMAND} --test-dir "${build}" --output-on-failure)
message(STATUS "golden recorded and checked: ${golden_root}/collide/main/reference-${KARMA_PRECISION}")
run(${CMAKE_COMMAND} -S "${source_c}" -B "${build}" -DCOLLIDE_DROP=2.1)
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --test-dir "${build}" --output-on-failure
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
set(report "first difference beyond tolerance: frame [0-9]+ \\(time [^)]*\\), body [0-9]+, [a-z_ ]+\\.[a-z0-9]+")
if(rc EQUAL 0 OR NOT out MATCHES "${report}")
  message(FATAL_ERROR "the changed program (drop 2.1 m) should fail its golden with karma-golden's report "
    "(exit ${rc}):\n${out}")
endif()
string(REGEX MATCH "${report}[^\n]*" first "${out}")
message(STATUS "changed program fails its golden: ${first}")

# 3. pkg-config: the C compiler and karma.pc's flags only.
find_program(PKG_CONFIG pkg-config REQUIRED)
set(ENV{PKG_CONFIG_PATH} "${prefix}/lib/pkgconfig")
run(${PKG_CONFIG} --cflags --libs --static karma)
string(STRIP "${RUN_OUTPUT}" flags)
message(STATUS "pkg-config --static karma: ${flags}")
separate_arguments(flags UNIX_COMMAND "${flags}")
separate_arguments(build_flags UNIX_COMMAND "${C_FLAGS} ${EXE_LINKER_FLAGS}")
run(${C_COMPILER} -std=c11 -Wall -Wextra -Werror ${build_flags} "${CONSUMER_SOURCE_DIR}/collide.c"
    -o "${WORK_DIR}/collide_pc" ${flags})
run("${WORK_DIR}/collide_pc")
expect_ok("pkg-config --static with cc")

# 4. C++ project.
set(build "${WORK_DIR}/build-cmake")
run(${CMAKE_COMMAND} -S "${CONSUMER_SOURCE_DIR}" -B "${build}" -G "${GENERATOR}" ${compilers}
    -DCMAKE_PREFIX_PATH=${prefix} -DEXPECTED_PRECISION=${KARMA_PRECISION})
run(${CMAKE_COMMAND} --build "${build}")
foreach(app consumer_c consumer_cxx collide)
  run("${build}/${app}")
  expect_ok("C++ project: ${app}")
endforeach()
