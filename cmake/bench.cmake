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

# Cost of one step against n per integrator / formulation / linear solve.
add_executable(riser_sim_bench_step_cost EXCLUDE_FROM_ALL bench/step_cost.cpp)
target_link_libraries(riser_sim_bench_step_cost riser_sim_core yaml-cpp)
target_compile_options(riser_sim_bench_step_cost PRIVATE -O3)
set_target_properties(riser_sim_bench_step_cost PROPERTIES
  RUNTIME_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION})

add_custom_target(riser_sim_benches DEPENDS
  riser_sim_bench_formulations riser_sim_bench_tradeoff riser_sim_bench_step_cost)
