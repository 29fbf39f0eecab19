# find_package(arbc): the arbc runtime for module authors (docs/runtime.md).
#   add_library(my_modules MODULE my_modules.cc)
#   target_link_libraries(my_modules PRIVATE arbc::arbc_runtime)
# and, for programs that run arbc over DDS themselves, arbc::arbc_dds (docs/distributed.md),
# defined only where Fast-DDS is installed: linking arbc_runtime never needs it.
include(CMakeFindDependencyMacro)
find_dependency(PkgConfig)
pkg_check_modules(LUA REQUIRED IMPORTED_TARGET lua5.4)
find_dependency(Eigen3 NO_MODULE)
find_dependency(nlohmann_json)
find_dependency(Threads)
include("${CMAKE_CURRENT_LIST_DIR}/arbcTargets.cmake")
find_package(fastrtps 2.9 QUIET)
if(fastrtps_FOUND)
  include("${CMAKE_CURRENT_LIST_DIR}/arbcDdsTargets.cmake")
endif()
