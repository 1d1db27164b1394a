# find_package(opm-common) for Debian 12's libopm-common-dev 2022.10, shared by tests/opm and
# benchmarks/. Include it from any directory that links OPM; afterwards link `cutaway_opm`
# (an INTERFACE target: opmcommon + its SYSTEM include dirs).
#
# Packaging quirks handled here:
#  * opm-common-config.cmake runs OPM's own prerequisite search, which asks for
#    `Boost COMPONENTS system unit_test_framework REQUIRED`, although libopm-common-dev does not
#    depend on libboost-test-dev: scripts/install-deps.sh installs it for that reason alone.
#  * the same prerequisite search runs C compiler checks (FindC99, Findcjson), so C is enabled
#    even though cutaway compiles no C.
#  * the imported target `opmcommon` links fmt::fmt, OpenMP::OpenMP_CXX and Boost::system by
#    name, so those packages are found first.
include_guard(DIRECTORY)

enable_language(C)

find_package(fmt REQUIRED)
find_package(OpenMP REQUIRED)
find_package(Boost REQUIRED COMPONENTS system)

find_package(opm-common REQUIRED)
message(STATUS "opm-common ${opm-common_VERSION}: ${opm-common_LIBRARY}")

if(NOT TARGET cutaway_opm)
  add_library(cutaway_opm INTERFACE)
  # OPM headers are not warning-clean under -Wall -Wextra -Wpedantic: include them as SYSTEM.
  target_include_directories(cutaway_opm SYSTEM INTERFACE ${opm-common_INCLUDE_DIRS})
  target_compile_definitions(cutaway_opm INTERFACE ${opm-common_DEFINITIONS}
                             CUTAWAY_OPM_VERSION="${opm-common_VERSION}")
  target_link_libraries(cutaway_opm INTERFACE opmcommon)
  # Each program linking OPM gets the LeakSanitizer suppressions for OPM's own leaks.
  target_sources(cutaway_opm INTERFACE ${CMAKE_CURRENT_LIST_DIR}/opm_leak_suppressions.cpp)
endif()
