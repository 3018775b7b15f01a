# KARMA_LTO: link-time optimisation (GCC's -flto) of everything built here.
#
# What it buys: the step calls many small functions across files and
# libraries (a body's accessors, a constraint's attachment points, the
# bridge's queries through the public API); at link time they are inlined.
# Floating-point code is compiled exactly as without it (no contraction, no
# fast-math), so the results are the same bits; docs/PERFORMANCE.md gives
# the figures and how that was checked. The bench preset turns it on; the
# other presets, and so CI's tests, leave it off, because every test program
# would pay a whole-program link.
#
# With GCC the libraries get fat objects (-ffat-lto-objects: machine code
# next to the compiler's intermediate form), so that an installed archive
# still holds ordinary code for a link that does not run GCC's link-time
# compiler. GCC's own link does run it on the intermediate form (through
# its linker plugin), so a program linked from these archives is link-time
# optimised, with the warnings of the whole program at its link. (Clang's
# archives would hold bitcode only: link them with Clang's LTO.)
if(NOT KARMA_LTO)
  return()
endif()

include(CheckIPOSupported)
check_ipo_supported(RESULT karma_lto_supported OUTPUT karma_lto_output LANGUAGES C CXX)
if(NOT karma_lto_supported)
  message(WARNING "KARMA_LTO: link-time optimisation is not available here; building without it.\n"
                  "${karma_lto_output}")
  set(KARMA_LTO OFF)
  return()
endif()
set(CMAKE_INTERPROCEDURAL_OPTIMIZATION ON)
