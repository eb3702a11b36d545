# The ROS-free core, the CLI, the benches and their tests without catkin (RISER_SIM_CORE_ONLY=ON): make check
# and the sanitizer build of tools/test_sanitize.sh. cmake/core.cmake and cmake/cli.cmake are used as they are, with
# catkin_add_gtest and catkin's directories supplied here.
find_package(Eigen3 REQUIRED)
find_package(yaml-cpp REQUIRED)
find_package(GTest REQUIRED)
enable_testing()
set(CATKIN_ENABLE_TESTING ON)
set(CATKIN_DEVEL_PREFIX ${CMAKE_BINARY_DIR})
set(CATKIN_PACKAGE_BIN_DESTINATION bin)
set(CATKIN_PACKAGE_LIB_DESTINATION lib)
set(CATKIN_PACKAGE_INCLUDE_DESTINATION include/riser_sim)
if(NOT TARGET gtest_main)
  add_library(gtest_main INTERFACE)
  target_link_libraries(gtest_main INTERFACE GTest::gtest_main GTest::gtest)
endif()

function(catkin_add_gtest name)
  cmake_parse_arguments(ARG "" "WORKING_DIRECTORY" "" ${ARGN})
  add_executable(${name} ${ARG_UNPARSED_ARGUMENTS})
  set_target_properties(${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  add_test(NAME ${name} COMMAND ${name} WORKING_DIRECTORY ${ARG_WORKING_DIRECTORY})
endfunction()

include(cmake/core.cmake)
include(cmake/cli.cmake)
include(cmake/bench.cmake)  # the benches (EXCLUDE_FROM_ALL) and the test of bench/update_docs.py
include(cmake/sweep.cmake)  # riser_sim_sweep: its test (ctest test_sweep)
