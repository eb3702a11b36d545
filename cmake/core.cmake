# ROS-free core: Eigen + yaml-cpp only.
add_library(riser_sim_core
  src/core/line/line_properties.cpp
  src/core/line/line_sections.cpp
  src/core/planar/model.cpp
  src/core/run/force_registry.cpp
  src/core/run/relaxed_statics.cpp
  src/core/line/rfe_inertia.cpp
  src/core/motion/top_motion.cpp
  src/core/motion/external_motion.cpp
  src/core/planar/forces/gravity.cpp
  src/core/planar/forces/axial_spring.cpp
  src/core/planar/forces/bending_spring.cpp
  src/core/planar/forces/buoyancy.cpp
  src/core/planar/forces/morison_drag.cpp
  src/core/planar/forces/hydro_inertia.cpp
  src/core/planar/forces/seabed.cpp
  src/core/planar/forces/end_load.cpp
  src/core/line/attachment.cpp
  src/core/planar/forces/attachments.cpp
  src/core/planar/forces/internal_flow.cpp
  src/core/planar/water.cpp
  src/core/planar/formulation.cpp
  src/core/planar/absolute_formulation.cpp
  src/core/planar/chain_kinematics.cpp
  src/core/planar/chain_formulation.cpp
  src/core/planar/chain_shifted_solver.cpp
  src/core/planar/independent_formulation.cpp
  src/core/planar/recursive_formulation.cpp
  src/core/integrators/integrator.cpp
  src/core/integrators/dopri5.cpp
  src/core/integrators/implicit_integrators.cpp
  src/core/planar/simulator.cpp
  src/core/scene/solver_setup.cpp
  src/core/scene/scene_check.cpp
  src/core/run/stability_estimate.cpp
  src/core/run/force_noise.cpp
  src/core/planar/statics.cpp
  src/core/planar/statics_residual.cpp
  src/core/planar/statics_guess.cpp
  src/core/planar/statics_check.cpp
  src/core/planar/modal.cpp
  src/core/run/modes_report.cpp
  src/core/run/linear_stability.cpp
  src/core/scene/scene.cpp
  src/core/run/initial_velocity.cpp
  src/core/planar/run_builder.cpp
  src/core/run/line_run.cpp
  src/core/run/range_graph.cpp
  src/core/run/section_extremes.cpp
  src/core/spatial/rfe_frames.cpp
  src/core/spatial/joint_bending.cpp
  src/core/scene/scene_sections.cpp
  src/core/scene/scene_line_sections.cpp
  src/core/line/line_sections_check.cpp
  src/core/scene/scene_sea_sections.cpp
  src/core/scene/scene_end_sections.cpp
  src/core/scene/scene_attachments.cpp
  src/core/scene/scene_yaml.cpp
  src/core/spatial/run_builder.cpp
  src/core/spatial/external_motion.cpp
  src/core/spatial/initial_state.cpp
  src/core/spatial/initial_twist.cpp
  src/core/spatial/forces/end_load.cpp
  src/core/spatial/forces/mass_damping.cpp
  src/core/spatial/model.cpp
  src/core/spatial/kinematics.cpp
  src/core/spatial/natural_formulation.cpp
  src/core/spatial/joint_reactions.cpp
  src/core/spatial/natural_state.cpp
  src/core/spatial/shifted_solver.cpp
  src/core/spatial/shifted_linearization.cpp
  src/core/spatial/torsion.cpp
  src/core/spatial/bending_axes.cpp
  src/core/spatial/independent_torsion.cpp
  src/core/spatial/simulator.cpp
  src/core/spatial/independent_formulation.cpp
  src/core/spatial/modal.cpp
  src/core/spatial/statics.cpp
  src/core/spatial/rest_stability.cpp
  src/core/spatial/modal_characters.cpp
  src/core/spatial/forces/gravity.cpp
  src/core/spatial/forces/axial_spring.cpp
  src/core/spatial/forces/bending_spring.cpp
  src/core/spatial/forces/flex_joint.cpp
  src/core/spatial/water.cpp
  src/core/spatial/added_mass.cpp
  src/core/spatial/relaxation.cpp
  src/core/spatial/forces/buoyancy.cpp
  src/core/spatial/forces/morison_drag.cpp
  src/core/spatial/forces/froude_krylov.cpp
  src/core/spatial/forces/added_mass.cpp
  src/core/spatial/forces/seabed.cpp
  src/core/spatial/forces/attachments.cpp
)
target_include_directories(riser_sim_core PUBLIC include ${EIGEN3_INCLUDE_DIR})
target_link_libraries(riser_sim_core PUBLIC yaml-cpp)
# The stepping code at -O3 whatever the build type, except the sanitizer build (tools/test_sanitize.sh:
# its -O1 must win; -O3 under ASan compiled the core ~1.8x slower).
set(RISER_SIM_OPT $<$<NOT:$<CONFIG:Sanitize>>:-O3>)
target_compile_options(riser_sim_core PRIVATE ${RISER_SIM_OPT} -fno-semantic-interposition)
# Most core files spent ~2 of their ~3 s of CPU parsing Eigen: one precompiled header for them all.
set(RISER_SIM_PCH_HEADERS <Eigen/Dense> <algorithm> <cmath> <functional> <memory> <sstream> <stdexcept>
  <string> <vector>)
target_precompile_headers(riser_sim_core PRIVATE ${RISER_SIM_PCH_HEADERS})
# Installed for downstream packages: find_package(catkin REQUIRED COMPONENTS riser_sim) gives the headers and
# ${catkin_LIBRARIES} the core (catkin_package in CMakeLists.txt exports it).
install(TARGETS riser_sim_core
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(DIRECTORY include/riser_sim/ DESTINATION ${CATKIN_PACKAGE_INCLUDE_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  # One precompiled header (Eigen, gtest, std) for every core gtest: ~2.5 s less CPU per test file.
  # CONFIGURE, not WRITE: the file keeps its time stamp when CMake runs again (catkin_make run_tests), so its
  # object is not compiled again.
  file(CONFIGURE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/riser_sim_test_pch.cpp CONTENT "")
  add_library(riser_sim_test_pch OBJECT ${CMAKE_CURRENT_BINARY_DIR}/riser_sim_test_pch.cpp)
  target_link_libraries(riser_sim_test_pch PRIVATE riser_sim_core gtest_main)
  # The gtest target catkin_add_gtest links each test to (and so its -DGTEST_HAS_PTHREAD=1): gcc ignores a PCH
  # built with other macros (-Winvalid-pch: "not used because ... defined"), and every test file then
  # parsed Eigen and gtest again.
  if(TARGET GTest::gtest)
    target_link_libraries(riser_sim_test_pch PRIVATE GTest::gtest)
  endif()
  target_compile_definitions(riser_sim_test_pch PRIVATE RISER_SIM_SOURCE_DIR="${CMAKE_CURRENT_SOURCE_DIR}")
  # RISER_SIM_TEST_OPT: the test drivers' optimisation (after the build type's, so it wins), the core library
  # keeping its own (tools/test_sanitize.sh's RISER_SIM_SANITIZE_TEST_OPT). On the PCH target too: gcc and
  # clang refuse a PCH built at another optimisation level (__OPTIMIZE__).
  set(RISER_SIM_TEST_OPT "" CACHE STRING "Optimisation of the core's test drivers (empty: the build type's)")
  target_compile_options(riser_sim_test_pch PRIVATE ${RISER_SIM_TEST_OPT})
  target_precompile_headers(riser_sim_test_pch PRIVATE <Eigen/Dense> <gtest/gtest.h> <algorithm> <cmath>
    <cstdio> <functional> <map> <memory> <random> <sstream> <string> <vector>)
  file(GLOB_RECURSE RISER_SIM_CORE_TESTS ${CMAKE_CURRENT_SOURCE_DIR}/test/core/test_*.cpp)
  foreach(test_src ${RISER_SIM_CORE_TESTS})
    get_filename_component(test_name ${test_src} NAME_WE)
    # RISER_SIM_TESTS (a list of test names) builds only those: the sanitizer build (tools/test_sanitize.sh).
    # RISER_SIM_SKIP_TESTS leaves those out (make test: the ones it runs under the sanitizers instead).
    if((RISER_SIM_TESTS AND NOT test_name IN_LIST RISER_SIM_TESTS) OR test_name IN_LIST RISER_SIM_SKIP_TESTS)
      continue()
    endif()
    catkin_add_gtest(${test_name} ${test_src} WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
    target_link_libraries(${test_name} riser_sim_core gtest_main)
    target_compile_definitions(${test_name} PRIVATE RISER_SIM_SOURCE_DIR="${CMAKE_CURRENT_SOURCE_DIR}")
    target_include_directories(${test_name} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/test/core)  # test utilities
    target_compile_options(${test_name} PRIVATE ${RISER_SIM_TEST_OPT})
    target_precompile_headers(${test_name} REUSE_FROM riser_sim_test_pch)
  endforeach()
endif()

# The scene fuzzer's replay (test/fuzz/): its input path is compiled into the regression test.
if(CATKIN_ENABLE_TESTING AND TARGET test_scene_fuzz_regressions)
  target_sources(test_scene_fuzz_regressions PRIVATE test/fuzz/scene_exercise.cpp)
  target_include_directories(test_scene_fuzz_regressions PRIVATE test/fuzz)
endif()
