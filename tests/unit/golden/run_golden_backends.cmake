# cmake -DDRIVER=<run_golden.cmake> -DGOLDEN_TEST_CMAKE=<KarmaGoldenTest.cmake>
#       -DPROGRAM=<golden_backend_program> -DGOLDEN_TOOL=<karma-golden>
#       -DPLATFORM_TOOL=<karma-platforms> -DPRECISION=single|double
#       -DWORK_DIR=<scratch> -P run_golden_backends.cmake
#
# The golden driver on several platform backends (docs/GOLDEN.md, "Backends
# share goldens"), in a scratch golden root:
#  1. karma-platforms --names lists KarmaGoldenTest.cmake's backends.
#  2. Regenerating the reference writes a real directory; regenerating avx2
#     with the same outputs makes avx2-P the relative link -> reference-P,
#     and checking avx2 through the link passes.
#  3. Regenerating avx2 with different outputs replaces the link by a real
#     directory and leaves the reference's files as they were; checking the
#     reference against avx2's outputs fails; once avx2 agrees again, its
#     regeneration makes the link again.
#  4. A backend the CPU lacks (a platform tool that answers 1) prints the
#     skip message that KarmaGoldenTest.cmake gives CTest, and exits 0; an
#     unknown backend fails.
#  5. karma_add_golden_test in a small project (the tools imported, a
#     platform tool that lacks avx512): one test per backend, named and
#     labelled as documented; after recording, CTest passes reference and
#     avx2 (through its link) and reports avx512 as skipped (step 4 checks
#     the message naming it).
cmake_minimum_required(VERSION 3.22)
foreach(var DRIVER GOLDEN_TEST_CMAKE PROGRAM GOLDEN_TOOL PLATFORM_TOOL PRECISION WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_golden_backends.cmake: ${var} is not set")
  endif()
endforeach()
include("${GOLDEN_TEST_CMAKE}")  # KARMA_GOLDEN_ALL_BACKENDS, KARMA_GOLDEN_SKIP_REGEX

file(REMOVE_RECURSE "${WORK_DIR}")
set(root "${WORK_DIR}/golden")
set(step_dir "${root}/fake/main")
set(ref "${step_dir}/reference-${PRECISION}")
set(avx2 "${step_dir}/avx2-${PRECISION}")

# drive(<backend> <regenerate 0|1> <expected: pass|fail> [program args...]):
# runs the driver; sets DRIVE_OUTPUT.
function(drive backend regenerate expected)
  set(defines -DARG_COUNT=0)
  if(ARGN)
    list(LENGTH ARGN count)
    set(defines -DARG_COUNT=${count})
    set(i 0)
    foreach(arg IN LISTS ARGN)
      list(APPEND defines "-DARG_${i}=${arg}")
      math(EXPR i "${i} + 1")
    endforeach()
  endif()
  if(NOT DEFINED tool)
    set(tool "${PLATFORM_TOOL}")
  endif()
  set(ENV{KARMA_GOLDEN_REGENERATE} ${regenerate})
  execute_process(COMMAND ${CMAKE_COMMAND} -DTEST_NAME=fake -DPROGRAM=${PROGRAM} -DGOLDEN_TOOL=${GOLDEN_TOOL}
    -DPLATFORM_TOOL=${tool} -DGOLDEN_PROGRAM=fake -DSTEP=main -DBACKEND=${backend} -DPRECISION=${PRECISION}
    -DGOLDEN_ROOT=${root} -DSOURCE_ROOT=${WORK_DIR} -DOUTPUT_DIR=${WORK_DIR}/out-${backend} ${defines}
    -DCHECK_ARG_COUNT=0 -P ${DRIVER}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  unset(ENV{KARMA_GOLDEN_REGENERATE})
  if((expected STREQUAL "pass" AND NOT rc EQUAL 0) OR (expected STREQUAL "fail" AND rc EQUAL 0))
    message(FATAL_ERROR "driver on ${backend} (regenerate ${regenerate}, ${ARGN}) should ${expected}, "
      "exit ${rc}:\n${out}")
  endif()
  set(DRIVE_OUTPUT "${out}" PARENT_SCOPE)
endfunction()

function(expect_link path)
  if(NOT IS_SYMLINK "${path}")
    message(FATAL_ERROR "${path} should be a symbolic link")
  endif()
  file(READ_SYMLINK "${path}" target)
  if(NOT target STREQUAL "reference-${PRECISION}")
    message(FATAL_ERROR "${path} -> ${target}, expected -> reference-${PRECISION}")
  endif()
endfunction()

function(expect_real_directory path)
  if(IS_SYMLINK "${path}" OR NOT IS_DIRECTORY "${path}" OR NOT EXISTS "${path}/trajectory.txt")
    message(FATAL_ERROR "${path} should be a real directory holding trajectory.txt")
  endif()
endfunction()

# 1.
execute_process(COMMAND "${PLATFORM_TOOL}" --names OUTPUT_VARIABLE names RESULT_VARIABLE rc)
string(STRIP "${names}" names)
string(REPLACE "\n" ";" names "${names}")
if(NOT rc EQUAL 0 OR NOT names STREQUAL "${KARMA_GOLDEN_ALL_BACKENDS}")
  message(FATAL_ERROR "karma-platforms --names gives '${names}', KarmaGoldenTest.cmake '${KARMA_GOLDEN_ALL_BACKENDS}'")
endif()

# fake_tool(<name> <exit status>): a platform tool that gives every backend
# that answer.
function(fake_tool name status)
  file(WRITE "${WORK_DIR}/${name}" "#!/bin/sh\nexit ${status}\n")
  file(CHMOD "${WORK_DIR}/${name}" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
endfunction()
fake_tool(all-supported 0)
fake_tool(none-supported 1)

# 2. (The CPU may lack avx2: a platform tool that answers "supported" stands
#    in; the program is a stand-in too and runs anywhere.)
set(tool "${WORK_DIR}/all-supported")
drive(reference 1 pass)
expect_real_directory("${ref}")
file(SHA256 "${ref}/trajectory.txt" reference_before)
drive(avx2 1 pass)
expect_link("${avx2}")
drive(avx2 0 pass)
if(NOT DRIVE_OUTPUT MATCHES "backends differ \\(expected reference, actual avx2\\)")
  message(FATAL_ERROR "the check of avx2 through the link should note the backend:\n${DRIVE_OUTPUT}")
endif()

# 3.
drive(avx2 0 fail -differ-on avx2)
drive(avx2 1 pass -differ-on avx2)
expect_real_directory("${avx2}")
file(SHA256 "${ref}/trajectory.txt" reference_after)
if(NOT reference_after STREQUAL reference_before)
  message(FATAL_ERROR "regenerating avx2 changed the reference's trajectory")
endif()
drive(avx2 0 pass -differ-on avx2)
drive(reference 0 pass -differ-on avx2)
drive(avx2 1 pass)
expect_link("${avx2}")

# 4.
set(tool "${WORK_DIR}/none-supported")
drive(avx512 0 pass)
if(NOT DRIVE_OUTPUT MATCHES "${KARMA_GOLDEN_SKIP_REGEX} 'avx512'")
  message(FATAL_ERROR "an unsupported backend should print the skip message naming it:\n${DRIVE_OUTPUT}")
endif()
unset(tool)
drive(bogus 0 fail)

# 5.
set(project "${WORK_DIR}/project")
file(WRITE "${WORK_DIR}/lacks-avx512" "#!/bin/sh\ncase \"$2\" in avx512) exit 1;; reference|sse4|avx2) exit 0;; *) exit 2;; esac\n")
file(CHMOD "${WORK_DIR}/lacks-avx512" PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
file(WRITE "${project}/CMakeLists.txt" "cmake_minimum_required(VERSION 3.22)
project(fake NONE)
enable_testing()
foreach(tool IN ITEMS karma-golden;karma-platforms;fake)
  add_executable(\${tool} IMPORTED)
endforeach()
set_target_properties(karma-golden PROPERTIES IMPORTED_LOCATION [[${GOLDEN_TOOL}]])
set_target_properties(karma-platforms PROPERTIES IMPORTED_LOCATION [[${WORK_DIR}/lacks-avx512]])
set_target_properties(fake PROPERTIES IMPORTED_LOCATION [[${PROGRAM}]])
set(Karma_PRECISION ${PRECISION})
include([[${GOLDEN_TEST_CMAKE}]])
karma_add_golden_test(NAME golden.fake PROGRAM fake STEP main BACKENDS reference avx2 avx512
  GOLDEN_ROOT [[${WORK_DIR}/project-golden]])
")
execute_process(COMMAND ${CMAKE_COMMAND} -S "${project}" -B "${project}/build" RESULT_VARIABLE rc OUTPUT_VARIABLE out
  ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring a project with karma_add_golden_test failed:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --test-dir "${project}/build" -N -L backend-avx2 OUTPUT_VARIABLE out)
if(NOT out MATCHES "golden\\.fake\\.avx2\n" OR NOT out MATCHES "Total Tests: 1\n")
  message(FATAL_ERROR "label backend-avx2 should select golden.fake.avx2 alone:\n${out}")
endif()
set(ENV{KARMA_GOLDEN_REGENERATE} 1)
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --test-dir "${project}/build" RESULT_VARIABLE rc OUTPUT_VARIABLE out)
unset(ENV{KARMA_GOLDEN_REGENERATE})
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "recording the project's goldens failed:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --test-dir "${project}/build" -L golden --output-on-failure
  RESULT_VARIABLE rc OUTPUT_VARIABLE out)
foreach(pattern "golden\\.fake [.]+ +Passed" "golden\\.fake\\.avx2 [.]+ +Passed"
                "golden\\.fake\\.avx512 [.]+\\*+Skipped")
  if(NOT rc EQUAL 0 OR NOT out MATCHES "${pattern}")
    message(FATAL_ERROR "CTest should pass reference and avx2 and skip avx512 (no '${pattern}', exit ${rc}):\n${out}")
  endif()
endforeach()
if(NOT IS_SYMLINK "${WORK_DIR}/project-golden/fake/main/avx2-${PRECISION}")
  message(FATAL_ERROR "recording should have linked avx2-${PRECISION} to the reference")
endif()

file(REMOVE_RECURSE "${WORK_DIR}")
message(STATUS "golden driver: links, real directories, skip, unknown backend and registration as documented")
