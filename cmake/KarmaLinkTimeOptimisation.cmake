# KARMA_LTO: link-time optimisation (GCC's -flto) of everything built here.
#
# What it buys: the step calls many small functions across files and
# libraries (a body's accessors, a constraint's attachment points, the
# bridge's queries through the public API); at link time they are inlined.
# Floating-point code is compiled exactly as without it (no contraction, no
# fast-math), so the results are the same bits; docs/PERFORMANCE.md gives
# the figures and the check. The bench preset turns it on; the other presets
# leave it off, because every test program would pay a whole-program link.
#
# The libraries get fat objects (-ffat-lto-objects: machine code next to
# the compiler's intermediate form), so that installed archives still link
# into a program built without LTO, or by another compiler.
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
# At the link, GCC 12 runs its late warnings again on the whole program and
# reports -Wstringop-overflow on std::string copies inlined from libstdc++
# (char_traits::copy "specified bound ... exceeds maximum object size" on
# a string assignment in MeViewer's menu): a known false positive of that
# analysis after inlining. The builds without LTO (CI's) keep the warning.
add_link_options($<$<CXX_COMPILER_ID:GNU>:-Wno-stringop-overflow>)
