# check_guide_fragments.cmake: compiles the guide's complete code fragments
# against the project's headers, in C and in C++ (issue 19, item 7).
#
#   cmake -DGUIDE=karma-userguide.txt -DMANIFEST=fragments.txt
#         -DPRELUDES=dir -DWORK=dir -DCC=cc -DCXX=c++ -DINCLUDES="a;b;c"
#         [-DONLY=name] -P check_guide_fragments.cmake
#
# The manifest (fragments.txt) lists each fragment by its lines in the
# guide; this script cuts those lines out, applies the manifest's listed
# repairs, wraps the text in its prelude and compiles it with
# -fsyntax-only. A fragment fails when it does not compile; the manifest's
# `skip` entries are fragments that cannot compile, each with its reason.
# Every line of the guide's text is compiled as printed: #line directives
# make a compiler message name the guide's line.
#
# Manifest lines (blank lines and lines starting with # are ignored):
#   NAME | FIRST-LAST | file|body | PRELUDE | ANCHOR
#       file: the text is file-scope code after `#include "PRELUDE.h"`;
#       body: the text is the body of an int function after the prelude
#             (which may define GUIDE_FRAGMENT_LEAD, code put before the
#             text: the locals of the function the guide pastes it into).
#       ANCHOR: a piece of line FIRST's text, so a changed guide is noticed.
#   fix NAME | FROM | TO | REASON    replace FROM by TO in NAME's text
#   skip NAME | FIRST-LAST | REASON  listed, not compiled
cmake_minimum_required(VERSION 3.22)

foreach(var GUIDE MANIFEST PRELUDES WORK CC CXX INCLUDES)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_guide_fragments: -D${var}=... is required")
  endif()
endforeach()
if(NOT EXISTS "${GUIDE}")
  message(FATAL_ERROR "check_guide_fragments: the guide is not at ${GUIDE}")
endif()

# Reads a text file into a list of its lines. CMake lists split at ';' and
# treat brackets and backslashes specially, so those four characters travel as
# placeholders until the source is written (restore_text).
function(read_lines path out)
  file(READ "${path}" content)
  string(REPLACE "\\" "@BS@" content "${content}")
  string(REPLACE ";" "@SEMI@" content "${content}")
  string(REPLACE "[" "@LB@" content "${content}")
  string(REPLACE "]" "@RB@" content "${content}")
  string(REPLACE "\r" "" content "${content}")
  string(REPLACE "\n" ";" content "${content}")
  set(${out} "${content}" PARENT_SCOPE)
endfunction()
function(restore_text var)
  set(t "${${var}}")
  string(REPLACE "@SEMI@" ";" t "${t}")
  string(REPLACE "@LB@" "[" t "${t}")
  string(REPLACE "@RB@" "]" t "${t}")
  string(REPLACE "@BS@" "\\" t "${t}")
  set(${var} "${t}" PARENT_SCOPE)
endfunction()

read_lines("${GUIDE}" guide_lines)
list(LENGTH guide_lines guide_count)
read_lines("${MANIFEST}" manifest_lines)
file(MAKE_DIRECTORY "${WORK}")

set(include_flags "")
foreach(dir IN LISTS INCLUDES)
  list(APPEND include_flags "-I${dir}")
endforeach()
list(APPEND include_flags "-I${PRELUDES}")

# Splits "a | b | c" into the list var (fields trimmed).
function(split_fields line out)
  string(REPLACE "|" ";" parts "${line}")
  set(fields "")
  foreach(part IN LISTS parts)
    string(STRIP "${part}" part)
    list(APPEND fields "${part}")
  endforeach()
  set(${out} "${fields}" PARENT_SCOPE)
endfunction()

# Lines FIRST..LAST of the guide, joined with newlines, into var.
function(guide_text first last out)
  math(EXPR i0 "${first} - 1")
  math(EXPR i1 "${last} - 1")
  set(text "")
  foreach(i RANGE ${i0} ${i1})
    list(GET guide_lines ${i} line)
    string(APPEND text "${line}\n")
  endforeach()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

set(names "")
set(skipped 0)
set(failures "")
foreach(raw IN LISTS manifest_lines)
  string(STRIP "${raw}" raw)
  if(raw STREQUAL "" OR raw MATCHES "^#")
    continue()
  endif()
  if(raw MATCHES "^fix ")
    string(REGEX REPLACE "^fix " "" raw "${raw}")
    split_fields("${raw}" f)
    list(GET f 0 name)
    list(GET f 1 from)
    list(GET f 2 to)
    list(APPEND fixes_${name} "${from}")
    list(APPEND fixes_to_${name} "${to}")
    continue()
  endif()
  if(raw MATCHES "^skip ")
    string(REGEX REPLACE "^skip " "" raw "${raw}")
    split_fields("${raw}" f)
    list(GET f 0 name)
    list(GET f 2 reason)
    restore_text(reason)
    message(STATUS "skip ${name}: ${reason}")
    math(EXPR skipped "${skipped} + 1")
    continue()
  endif()
  split_fields("${raw}" f)
  list(LENGTH f n)
  # (placeholders stay in the anchor: it is compared with the guide's line,
  # which carries them too)
  if(NOT n EQUAL 5)
    message(FATAL_ERROR "check_guide_fragments: bad manifest line: ${raw}")
  endif()
  list(GET f 0 name)
  list(GET f 1 range)
  list(GET f 2 kind_${name})
  list(GET f 3 prelude_${name})
  list(GET f 4 anchor_${name})
  if(NOT range MATCHES "^([0-9]+)-([0-9]+)$")
    message(FATAL_ERROR "check_guide_fragments: bad range '${range}' for ${name}")
  endif()
  set(first_${name} ${CMAKE_MATCH_1})
  set(last_${name} ${CMAKE_MATCH_2})
  if(last_${name} GREATER guide_count OR first_${name} GREATER last_${name})
    message(FATAL_ERROR "check_guide_fragments: ${name}: lines ${range} are not in the guide")
  endif()
  list(APPEND names ${name})
endforeach()

if(DEFINED ONLY)
  set(names ${ONLY})
endif()

foreach(name IN LISTS names)
  set(first ${first_${name}})
  set(last ${last_${name}})
  guide_text(${first} ${last} text)
  math(EXPR i0 "${first} - 1")
  list(GET guide_lines ${i0} first_line)
  string(FIND "${first_line}" "${anchor_${name}}" at)
  if(at EQUAL -1)
    list(APPEND failures "${name}: line ${first} no longer reads '${anchor_${name}}'")
    continue()
  endif()
  # The listed repairs; each must still apply.
  list(LENGTH fixes_${name} nfix)
  if(nfix GREATER 0)
    math(EXPR last_fix "${nfix} - 1")
    foreach(k RANGE ${last_fix})
      list(GET fixes_${name} ${k} from)
      list(GET fixes_to_${name} ${k} to)
      string(FIND "${text}" "${from}" at)
      if(at EQUAL -1)
        list(APPEND failures "${name}: the repair of '${from}' no longer applies")
      endif()
      string(REPLACE "${from}" "${to}" text "${text}")
    endforeach()
  endif()
  set(source "/* ${name}: the guide's lines ${first}-${last} (generated) */\n")
  string(APPEND source "#include \"${prelude_${name}}.h\"\n")
  if(kind_${name} STREQUAL "body")
    # int: some fragments end their function with `return 0;`.
    string(APPEND source "int guide_fragment_${name}(void);\n")
    string(APPEND source "int guide_fragment_${name}(void) {\n#ifdef GUIDE_FRAGMENT_LEAD\nGUIDE_FRAGMENT_LEAD\n#endif\n")
    string(APPEND source "#line ${first} \"karma-userguide.txt\"\n${text}return 0;\n}\n")
  elseif(kind_${name} STREQUAL "file")
    string(APPEND source "#line ${first} \"karma-userguide.txt\"\n${text}")
  else()
    message(FATAL_ERROR "check_guide_fragments: ${name}: kind must be file or body")
  endif()
  restore_text(source)
  file(WRITE "${WORK}/${name}.c" "${source}")
  file(WRITE "${WORK}/${name}.cpp" "${source}")
  list(APPEND c_sources "${WORK}/${name}.c")
  list(APPEND cxx_sources "${WORK}/${name}.cpp")
  set(range_${name} "${first}-${last}")
endforeach()

set(c_flags -std=c11 -fsyntax-only -Werror=implicit-function-declaration -Werror=implicit-int
    -Werror=incompatible-pointer-types -Werror=int-conversion)
set(cxx_flags -std=c++20 -fsyntax-only -w)

# One compiler run per language for all fragments (each file is its own
# translation unit); only when one fails, each fragment again on its own,
# to name the ones that fail.
function(compile_all compiler flags sources out)
  execute_process(COMMAND ${compiler} ${flags} ${include_flags} ${sources}
                  RESULT_VARIABLE result OUTPUT_QUIET ERROR_QUIET)
  set(${out} ${result} PARENT_SCOPE)
endfunction()
set(c_batch 0)
set(cxx_batch 0)
if(c_sources)
  compile_all(${CC} "${c_flags}" "${c_sources}" c_batch)
  compile_all(${CXX} "${cxx_flags}" "${cxx_sources}" cxx_batch)
endif()

foreach(name IN LISTS names)
  if(NOT DEFINED range_${name})
    continue()  # already reported (anchor or repair)
  endif()
  foreach(lang C CXX)
    if(lang STREQUAL "C")
      set(batch ${c_batch})
      set(compiler ${CC})
      set(flags ${c_flags})
      set(file "${WORK}/${name}.c")
    else()
      set(batch ${cxx_batch})
      set(compiler ${CXX})
      set(flags ${cxx_flags})
      set(file "${WORK}/${name}.cpp")
    endif()
    if(batch EQUAL 0)
      continue()
    endif()
    execute_process(COMMAND ${compiler} ${flags} ${include_flags} "${file}"
                    RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
    if(NOT result EQUAL 0)
      string(REPLACE ";" "," out "${out}")
      string(REPLACE "[" "(" out "${out}")
      string(REPLACE "]" ")" out "${out}")
      list(APPEND failures "${name} (${lang}, lines ${range_${name}}):\n${out}")
    endif()
  endforeach()
endforeach()

list(LENGTH names compiled)
list(LENGTH failures failed)
message(STATUS "${compiled} fragments compiled in C and C++: ${failed} compilations failed; ${skipped} fragments listed as not compilable")
if(failed GREATER 0)
  string(REPLACE ";" "\n" report "${failures}")
  message(FATAL_ERROR "guide fragments that do not compile:\n${report}")
endif()
