# run_golden.cmake: the driver of one golden test (see KarmaGoldenTest.cmake).
#
#   cmake -DTEST_NAME=... -DPROGRAM=<exe> -DGOLDEN_TOOL=<karma-golden>
#         -DPLATFORM_TOOL=<karma-platforms> -DGOLDEN_PROGRAM=<name> -DSTEP=<step> -DBACKEND=<backend>
#         -DPRECISION=single|double -DGOLDEN_ROOT=<source>/golden
#         -DSOURCE_ROOT=<source> -DOUTPUT_DIR=<fresh dir in the build tree>
#         -DARG_COUNT=n -DARG_0=... -DCHECK_ARG_COUNT=m -DCHECK_ARG_0=...
#         -P run_golden.cmake
#
# 0. Asks `karma-platforms --supported BACKEND`: when this CPU lacks the
#    backend, prints "SKIPPED: this CPU does not support the platform backend
#    'BACKEND'" (the test's SKIP_REGULAR_EXPRESSION) and stops; an unknown
#    backend fails.
# 1. Empties OUTPUT_DIR and runs the program there, with KARMA_PLATFORM=BACKEND
#    in its environment, with its arguments plus
#    -platform BACKEND -trajectory OUTPUT_DIR/trajectory.txt -out OUTPUT_DIR;
#    the program must exit with 0 and write the trajectory. If it prints a
#    "state hash: 0x..." line, that hash must equal the trajectory's final-hash.
# 2. Normally: compares OUTPUT_DIR with the golden directory
#    GOLDEN_ROOT/GOLDEN_PROGRAM/STEP/BACKEND-PRECISION through `karma-golden
#    check`; a missing golden directory fails with instructions.
# 3. With KARMA_GOLDEN_REGENERATE=1 in the environment (scripts/golden-regen
#    sets it; nothing else should): replaces the golden's trajectory.txt and
#    PNG frames with the outputs, then checks the new golden reads back.
#    Backends share goldens (docs/GOLDEN.md): when BACKEND is not the
#    reference and its outputs are the reference golden's, bit for bit (same
#    final state hash, every golden frame byte-identical), the golden
#    directory becomes the relative symbolic link BACKEND-PRECISION ->
#    reference-PRECISION; otherwise it is a real directory of its own (a link
#    is removed first: regeneration never writes through a link).
cmake_minimum_required(VERSION 3.22)

foreach(var TEST_NAME PROGRAM GOLDEN_TOOL PLATFORM_TOOL GOLDEN_PROGRAM STEP BACKEND PRECISION GOLDEN_ROOT OUTPUT_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_golden.cmake: -D${var}=... is required")
  endif()
endforeach()

set(key "${GOLDEN_PROGRAM}/${STEP}/${BACKEND}-${PRECISION}")
set(golden_dir "${GOLDEN_ROOT}/${key}")
file(RELATIVE_PATH golden_rel "${SOURCE_ROOT}" "${golden_dir}")
set(reference_name "reference-${PRECISION}")
set(reference_dir "${GOLDEN_ROOT}/${GOLDEN_PROGRAM}/${STEP}/${reference_name}")

# --- 0. can this CPU run the backend? ----------------------------------------
execute_process(COMMAND "${PLATFORM_TOOL}" --supported "${BACKEND}" RESULT_VARIABLE supported)
if(supported EQUAL 1)
  message("golden ${key}: SKIPPED: this CPU does not support the platform backend '${BACKEND}' "
    "(karma-platforms lists what it supports)")
  return()
elseif(NOT supported EQUAL 0)
  message(FATAL_ERROR "golden ${key}: there is no platform backend '${BACKEND}' "
    "(karma-platforms --supported exit ${supported}; karma-platforms --names lists them)")
endif()

# --- 1. run the program in a fresh output directory -----------------------
file(REMOVE_RECURSE "${OUTPUT_DIR}")
file(MAKE_DIRECTORY "${OUTPUT_DIR}")
set(command "${PROGRAM}")
if(ARG_COUNT GREATER 0)
  math(EXPR last "${ARG_COUNT} - 1")
  foreach(i RANGE ${last})
    list(APPEND command "${ARG_${i}}")
  endforeach()
endif()
list(APPEND command -platform "${BACKEND}" -trajectory "${OUTPUT_DIR}/trajectory.txt" -out "${OUTPUT_DIR}")
list(JOIN command " " command_text)
message(STATUS "golden ${key}: running KARMA_PLATFORM=${BACKEND} ${command_text}")
set(ENV{KARMA_PLATFORM} "${BACKEND}")
execute_process(COMMAND ${command}
  WORKING_DIRECTORY "${OUTPUT_DIR}"
  RESULT_VARIABLE result
  OUTPUT_VARIABLE program_stdout
  ERROR_VARIABLE program_stderr)
file(WRITE "${OUTPUT_DIR}/stdout.txt" "${program_stdout}")
message("${program_stdout}${program_stderr}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "golden ${key}: the program failed (${result})")
endif()
if(NOT EXISTS "${OUTPUT_DIR}/trajectory.txt")
  message(FATAL_ERROR "golden ${key}: the program wrote no trajectory.txt")
endif()

file(STRINGS "${OUTPUT_DIR}/trajectory.txt" final_line REGEX "^final-hash ")
string(REGEX MATCH "state hash: (0x[0-9a-fA-F]+)" printed "${program_stdout}")
if(printed)
  set(printed_hash "${CMAKE_MATCH_1}")
  if(NOT final_line STREQUAL "final-hash ${printed_hash}")
    message(FATAL_ERROR "golden ${key}: the program printed state hash ${printed_hash} "
      "but its trajectory says '${final_line}'")
  endif()
endif()

set(check_command "${GOLDEN_TOOL}" check --golden-dir "${golden_dir}" --actual-dir "${OUTPUT_DIR}")
if(CHECK_ARG_COUNT GREATER 0)
  math(EXPR last "${CHECK_ARG_COUNT} - 1")
  foreach(i RANGE ${last})
    list(APPEND check_command "${CHECK_ARG_${i}}")
  endforeach()
endif()

# --- 3. regenerate ----------------------------------------------------------
# Whether the run's outputs are the reference golden's, bit for bit: the same
# final state hash (which covers every sampled state) and every frame of the
# golden present and byte-identical in the output.
function(outputs_equal_reference result_var)
  set(${result_var} FALSE PARENT_SCOPE)
  if(NOT EXISTS "${reference_dir}/trajectory.txt")
    return()
  endif()
  file(STRINGS "${reference_dir}/trajectory.txt" reference_final REGEX "^final-hash ")
  if(NOT reference_final STREQUAL final_line)
    return()
  endif()
  file(GLOB reference_frames "${reference_dir}/*.png")
  list(FILTER reference_frames EXCLUDE REGEX "\\.diff\\.png$")
  foreach(frame IN LISTS reference_frames)
    get_filename_component(name "${frame}" NAME)
    if(NOT EXISTS "${OUTPUT_DIR}/${name}")
      return()
    endif()
    file(SHA256 "${frame}" expected)
    file(SHA256 "${OUTPUT_DIR}/${name}" actual)
    if(NOT expected STREQUAL actual)
      return()
    endif()
  endforeach()
  set(${result_var} TRUE PARENT_SCOPE)
endfunction()

function(check_regenerated)
  execute_process(COMMAND ${check_command} RESULT_VARIABLE check_result OUTPUT_VARIABLE check_output
    ERROR_VARIABLE check_output)
  if(NOT check_result EQUAL 0)
    message(FATAL_ERROR "golden ${key}: the regenerated golden does not check against its own run:\n${check_output}")
  endif()
endfunction()

if("$ENV{KARMA_GOLDEN_REGENERATE}" STREQUAL "1")
  set(shared FALSE)
  if(NOT BACKEND STREQUAL "reference" AND IS_DIRECTORY "${reference_dir}" AND NOT IS_SYMLINK "${reference_dir}")
    outputs_equal_reference(shared)
  endif()
  if(IS_SYMLINK "${golden_dir}")
    file(REMOVE "${golden_dir}")  # the link itself, never what it points to
  elseif(shared AND EXISTS "${golden_dir}")
    file(REMOVE_RECURSE "${golden_dir}")  # a directory of its own, now equal to the reference's
  endif()
  if(shared)
    file(CREATE_LINK "${reference_name}" "${golden_dir}" SYMBOLIC)
    check_regenerated()
    message(STATUS "golden ${key}: REGENERATED ${golden_rel} -> ${reference_name} "
      "(the same outputs as the reference, ${final_line})")
    return()
  endif()
  file(MAKE_DIRECTORY "${golden_dir}")
  file(GLOB stale "${golden_dir}/*.png" "${golden_dir}/trajectory.txt")
  if(stale)
    file(REMOVE ${stale})
  endif()
  file(GLOB frames "${OUTPUT_DIR}/*.png")
  list(FILTER frames EXCLUDE REGEX "\\.diff\\.png$")
  file(COPY "${OUTPUT_DIR}/trajectory.txt" ${frames} DESTINATION "${golden_dir}")
  check_regenerated()
  list(LENGTH frames frame_count)
  set(why "")
  if(NOT BACKEND STREQUAL "reference")
    set(why ", a directory of its own: the outputs differ from ${reference_name}'s or it has none")
  endif()
  message(STATUS "golden ${key}: REGENERATED ${golden_rel} (trajectory.txt and ${frame_count} frame(s), "
    "${final_line}${why})")
  return()
endif()

# --- 2. compare -----------------------------------------------------------
if(NOT IS_DIRECTORY "${golden_dir}")
  set(share_hint "")
  if(NOT BACKEND STREQUAL "reference")
    set(share_hint "A backend whose outputs are the reference's shares its golden through a link ${BACKEND}-${PRECISION} -> "
      "${reference_name}: scripts/golden-share makes the missing links.\n")
  endif()
  message(FATAL_ERROR
    "golden ${key}: there is no golden directory ${golden_rel}.\n${share_hint}"
    "If this is a new program or step, look at its output in ${OUTPUT_DIR} first; when it is right, create the "
    "golden with\n    KARMA_GOLDEN_REGENERATE=1 ctest -R '^${TEST_NAME}$'\n"
    "(in Karma's own tree: scripts/golden-regen <build-dir> '^${TEST_NAME}$')\n"
    "and commit it saying what the program shows (docs/GOLDEN.md).")
endif()
execute_process(COMMAND ${check_command} RESULT_VARIABLE check_result)
if(NOT check_result EQUAL 0)
  message(FATAL_ERROR
    "golden ${key}: output differs from ${golden_rel} (karma-golden exit ${check_result}).\n"
    "Outputs and diff images: ${OUTPUT_DIR}\n"
    "Review the difference (docs/GOLDEN.md, 'Reviewing a difference'); regenerate only if the change is "
    "understood and intended.")
endif()
message(STATUS "golden ${key}: matches ${golden_rel}")
