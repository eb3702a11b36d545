# riser_sim_cli (see src/cli): offline runs of a scene file, no roscore needed.
# Lands in devel/lib/riser_sim so that `rosrun riser_sim riser_sim_cli` finds it.
add_executable(riser_sim_cli
  src/cli/main.cpp
  src/cli/cli_options.cpp
  src/cli/run_output.cpp
  src/cli/modal_output.cpp
  src/cli/output_file.cpp
)
target_link_libraries(riser_sim_cli riser_sim_core)
target_compile_options(riser_sim_cli PRIVATE ${RISER_SIM_OPT})  # cmake/core.cmake
target_precompile_headers(riser_sim_cli PRIVATE ${RISER_SIM_PCH_HEADERS})  # cmake/core.cmake: Eigen, std
set_target_properties(riser_sim_cli PROPERTIES
  RUNTIME_OUTPUT_DIRECTORY ${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION})
install(TARGETS riser_sim_cli RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})

# test/core/test_cli*.cpp (made gtests by cmake/core.cmake's glob) run the built binary.
foreach(t test_cli test_cli_outputs test_cli_spatial test_cli_spatial_ends test_cli_spatial_modes
          test_cli_spatial_torsion test_cli_statics_only test_cli_range_graph test_cli_section_extremes
          test_cli_shipped_scenes)
  if(CATKIN_ENABLE_TESTING AND TARGET ${t})
    target_compile_definitions(${t} PRIVATE
      RISER_SIM_CLI_BINARY="${CATKIN_DEVEL_PREFIX}/${CATKIN_PACKAGE_BIN_DESTINATION}/riser_sim_cli")
    add_dependencies(${t} riser_sim_cli)
  endif()
endforeach()
