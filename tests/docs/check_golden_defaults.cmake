# docs/GOLDEN.md quotes `karma-golden defaults` between two markers; the quote
# must equal what the tool prints, so the documented tolerances are the real ones.
execute_process(COMMAND "${TOOL}" defaults RESULT_VARIABLE rc OUTPUT_VARIABLE printed)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "karma-golden defaults failed (${rc})")
endif()
file(READ "${DOC}" doc)
string(REGEX MATCH "<!-- karma-golden defaults -->\n```\n(.*)```\n<!-- end karma-golden defaults -->" found "${doc}")
if(NOT found)
  message(FATAL_ERROR "${DOC} lacks the quoted block of `karma-golden defaults`")
endif()
if(NOT CMAKE_MATCH_1 STREQUAL printed)
  message(FATAL_ERROR "${DOC} quotes defaults that differ from the tool's.\nDocumented:\n${CMAKE_MATCH_1}\nPrinted:\n${printed}")
endif()
