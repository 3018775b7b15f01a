# Installation and the exported CMake package / pkg-config file.
#
# Installed layout:
#   include/karma/*.h            every public header (MeConfig.h included)
#   include/karma/golden/*.h     the golden-output toolkit
#   lib/libkarma_*.a|so          the libraries
#   lib/cmake/Karma/             KarmaConfig.cmake, version file, targets
#   lib/pkgconfig/karma.pc
#   share/karma/                 data (textures, ...) found at run time
# Both include/ and include/karma/ are on the exported include path, so the
# guide's `#include "Mdt.h"` and `#include <karma/Mdt.h>` both work.
include(CMakePackageConfigHelpers)

set(KARMA_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/Karma")

install(DIRECTORY "${PROJECT_SOURCE_DIR}/engine/include/karma"
                  "${PROJECT_SOURCE_DIR}/meviewer/include/karma"
                  "${PROJECT_SOURCE_DIR}/tools/golden/include/karma"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}"
        FILES_MATCHING PATTERN "*.h")
install(FILES "${KARMA_GENERATED_INCLUDE_DIR}/karma/MeConfig.h"
        DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/karma")

get_property(karma_targets GLOBAL PROPERTY KARMA_EXPORTED_TARGETS)
install(TARGETS ${karma_targets} KarmaKarma karma-golden karma-platforms
        EXPORT KarmaTargets
        ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
        LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}"
        RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}"
        INCLUDES DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}" "${CMAKE_INSTALL_INCLUDEDIR}/karma")
install(EXPORT KarmaTargets
        NAMESPACE Karma::
        DESTINATION "${KARMA_INSTALL_CMAKEDIR}")

configure_package_config_file(
  "${PROJECT_SOURCE_DIR}/cmake/KarmaConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/KarmaConfig.cmake"
  INSTALL_DESTINATION "${KARMA_INSTALL_CMAKEDIR}")
write_basic_package_version_file(
  "${PROJECT_BINARY_DIR}/KarmaConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/KarmaConfig.cmake"
              "${PROJECT_BINARY_DIR}/KarmaConfigVersion.cmake"
        DESTINATION "${KARMA_INSTALL_CMAKEDIR}")

# karma.pc lists the real (non-interface) libraries, each before every
# library it links (a depth-first walk of the link graph), so a static link
# resolves in one pass; the dependencies outside Karma come from their own
# .pc files (Requires.private), and the C++ runtime from Libs.private, so a
# C program links with `cc ... $(pkg-config --static --libs karma)`.
function(karma_visit_links target)
  get_property(seen GLOBAL PROPERTY KARMA_LINK_SEEN)
  if(target IN_LIST seen)
    return()
  endif()
  set_property(GLOBAL APPEND PROPERTY KARMA_LINK_SEEN ${target})
  get_target_property(links ${target} LINK_LIBRARIES)
  get_target_property(interface_links ${target} INTERFACE_LINK_LIBRARIES)
  foreach(link IN LISTS links interface_links)
    string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" link "${link}")
    if(TARGET "${link}")
      get_target_property(real "${link}" ALIASED_TARGET)
      if(NOT real)
        set(real "${link}")
      endif()
      if(real IN_LIST karma_targets)
        karma_visit_links(${real})
      endif()
    endif()
  endforeach()
  set_property(GLOBAL APPEND PROPERTY KARMA_LINK_ORDER ${target})
endfunction()
foreach(t IN LISTS karma_targets)
  karma_visit_links(${t})
endforeach()
get_property(karma_link_order GLOBAL PROPERTY KARMA_LINK_ORDER)
list(REVERSE karma_link_order) # dependents first
set(KARMA_PC_LIBS "")
foreach(t IN LISTS karma_link_order)
  get_target_property(type ${t} TYPE)
  if(NOT type STREQUAL "INTERFACE_LIBRARY")
    get_target_property(out ${t} OUTPUT_NAME)
    string(APPEND KARMA_PC_LIBS " -l${out}")
  endif()
endforeach()
file(RELATIVE_PATH KARMA_PC_TO_PREFIX "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
string(REGEX REPLACE "/$" "" KARMA_PC_TO_PREFIX "${KARMA_PC_TO_PREFIX}")
configure_file("${PROJECT_SOURCE_DIR}/cmake/karma.pc.in" "${PROJECT_BINARY_DIR}/karma.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/karma.pc" DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig")

# The golden tool (exported as Karma::karma-golden), the backend query
# (Karma::karma-platforms: the golden driver skips a backend the CPU lacks)
# and karma_add_golden_test() with its driver, for users who pin their own programs' outputs
# (docs/GOLDEN.md, "Golden-test your own program"); KarmaConfig.cmake
# includes KarmaGoldenTest.cmake.
install(FILES "${PROJECT_SOURCE_DIR}/tools/golden/KarmaGoldenTest.cmake"
              "${PROJECT_SOURCE_DIR}/tools/golden/run_golden.cmake"
        DESTINATION "${KARMA_INSTALL_CMAKEDIR}")
