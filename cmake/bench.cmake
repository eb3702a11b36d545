# Benchmarks (ROS-free executables, run by `make bench`); land in devel/lib/riser_sim. Not part of `all`
# (the test build does not need them): the target riser_sim_benches builds them (`make build` does).
add_executable(riser_sim_bench_formulations EXCLUDE_FROM_ALL bench/formulations.cpp)
target_link_libraries(riser_sim_bench_formulations riser_sim_core)
target_include_directories(riser_sim_bench_formulations PRIVATE test/core)  # validation_util.h: the Table 1 scene
target_compile_options(riser_sim_bench_formulations PRIVATE -O3)
set_target_properties(riser_sim_bench_formulations PROPERTIES
  RUNTIME_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION})

# Speed against accuracy sweep: bench/extra_tradeoff.sh runs it.
add_executable(riser_sim_bench_tradeoff EXCLUDE_FROM_ALL bench/tradeoff.cpp bench/tradeoff_cases.cpp bench/tradeoff_run.cpp)
target_link_libraries(riser_sim_bench_tradeoff riser_sim_core yaml-cpp)
target_include_directories(riser_sim_bench_tradeoff PRIVATE test/core)
target_compile_options(riser_sim_bench_tradeoff PRIVATE -O3)
set_target_properties(riser_sim_bench_tradeoff PROPERTIES
  RUNTIME_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION})

# Cost of one step against n per integrator / formulation / linear solve; the shipped scenes' step cost against
# a saved baseline (--save-baseline, --compare).
add_executable(riser_sim_bench_step_cost EXCLUDE_FROM_ALL bench/step_cost.cpp bench/step_cost_check.cpp)
target_link_libraries(riser_sim_bench_step_cost riser_sim_core yaml-cpp)
target_compile_options(riser_sim_bench_step_cost PRIVATE -O3)
set_target_properties(riser_sim_bench_step_cost PROPERTIES
  RUNTIME_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION})

add_custom_target(riser_sim_benches DEPENDS
  riser_sim_bench_formulations riser_sim_bench_tradeoff riser_sim_bench_step_cost)

# bench/update_docs.py (the tables of docs/benchmarks.md) on a temporary page: a fast test with its own JUnit file
# (catkin_test_results counts it in make test); in the core-only build (make check) a plain CTest.
if(CATKIN_ENABLE_TESTING)
  if(RISER_SIM_CORE_ONLY)
    if(NOT RISER_SIM_TESTS)  # the sanitizer build names its gtests: not this one
      add_test(NAME test_update_docs COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/test/bench/test_update_docs.py)
    endif()
  else()
    set(_update_docs_xml ${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/script-update_docs.xml)
    catkin_run_tests_target(script update_docs script-update_docs.xml
      COMMAND "/usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/test/bench/test_update_docs.py --xml ${_update_docs_xml}")
  endif()
endif()
