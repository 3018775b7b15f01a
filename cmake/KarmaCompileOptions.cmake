# Compile options shared by every target built in this tree (never exported:
# consumers choose their own flags, but the headers must compile cleanly
# under these).
#
#  - warnings on: -Wall -Wextra (plus -Wpedantic for C++), clean in Release;
#  - no fast-math and no floating-point contraction, so that a*b+c is rounded
#    twice everywhere and results are bit-identical across builds;
#  - the check build defines nothing extra here: KARMA_CHECK lives in the
#    generated MeConfig.h so installed headers agree with the library.
add_library(karma_build_flags INTERFACE)
target_compile_options(karma_build_flags INTERFACE
  $<$<OR:$<CXX_COMPILER_ID:GNU>,$<CXX_COMPILER_ID:Clang>>:-Wall -Wextra -ffp-contract=off -fno-fast-math>
  $<$<AND:$<COMPILE_LANGUAGE:CXX>,$<OR:$<CXX_COMPILER_ID:GNU>,$<CXX_COMPILER_ID:Clang>>>:-Wpedantic>)

# The memset and memcpy strategy of karma_library's targets (below), where
# the compiler takes it (GCC on x86).
include(CheckCXXCompilerFlag)
set(_karma_memset_strategy -mmemset-strategy=unrolled_loop:512:noalign,libcall:-1:noalign)
set(_karma_memcpy_strategy -mmemcpy-strategy=unrolled_loop:512:noalign,libcall:-1:noalign)
set(KARMA_STRING_STRATEGY_FLAGS "")
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  check_cxx_compiler_flag(${_karma_memset_strategy} KARMA_HAS_MEMSET_STRATEGY)
  check_cxx_compiler_flag(${_karma_memcpy_strategy} KARMA_HAS_MEMCPY_STRATEGY)
  if(KARMA_HAS_MEMSET_STRATEGY AND KARMA_HAS_MEMCPY_STRATEGY)
    set(KARMA_STRING_STRATEGY_FLAGS ${_karma_memset_strategy} ${_karma_memcpy_strategy})
  endif()
endif()

if(KARMA_WARNINGS_AS_ERRORS)
  target_compile_options(karma_build_flags INTERFACE
    $<$<OR:$<CXX_COMPILER_ID:GNU>,$<CXX_COMPILER_ID:Clang>>:-Werror>)
endif()

# karma_library(<target> <export-name>): a library exported as Karma::<export-name>.
function(karma_library target export_name)
  add_library(Karma::${export_name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  get_target_property(type ${target} TYPE)
  if(NOT type STREQUAL "INTERFACE_LIBRARY")
    target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:karma_build_flags>)
    # The libraries are built position-independent; without this, GCC may
    # not inline an exported (MEPUBLIC) function into its callers in the same
    # file, in case a shared library's user replaces it. Nobody does.
    target_compile_options(${target} PRIVATE
      $<$<OR:$<CXX_COMPILER_ID:GNU>,$<CXX_COMPILER_ID:Clang>>:-fno-semantic-interposition>)
    # GCC on x86 expands a memset or memcpy of known size up to 512 bytes
    # as an unrolled loop of 8-byte stores, and calls the library beyond:
    # its default for mid sizes, `rep stos` / `rep movs`, pays a start-up of
    # tens of cycles on the AMD EPYC the benchmarks run on (docs/NOTES.md,
    # "String instructions in hot loops"). The same bytes are written either
    # way. With KARMA_LTO, GCC's link merges target options, so the whole
    # program linked (the benchmarks' harness too, or a consumer's program
    # linked with link-time optimisation against these archives) gets it.
    if(KARMA_STRING_STRATEGY_FLAGS)
      target_compile_options(${target} PRIVATE ${KARMA_STRING_STRATEGY_FLAGS})
    endif()
    # With KARMA_LTO, ordinary code beside the intermediate form in the
    # archives (KarmaLinkTimeOptimisation.cmake).
    if(KARMA_LTO)
      target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU>:-ffat-lto-objects>)
    endif()
    # The libraries are C++; a program linked by the C compiler (a C-only
    # project) gets the C++ runtime from here.
    target_link_libraries(${target} INTERFACE "$<$<LINK_LANGUAGE:C>:stdc++>")
    set_target_properties(${target} PROPERTIES
      OUTPUT_NAME "karma_${export_name}"
      CXX_VISIBILITY_PRESET hidden
      VISIBILITY_INLINES_HIDDEN ON)
  endif()
  set_property(GLOBAL APPEND PROPERTY KARMA_EXPORTED_TARGETS ${target})
endfunction()
