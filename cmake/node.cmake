# riser_sim_node (see src/node, docs/ros_interface.md) and its tests (test/ros).
add_library(riser_sim_ros
  src/node/xmlrpc_yaml.cpp
  src/node/node_params.cpp
  src/node/vessel_input.cpp
  src/node/tf_listener.cpp
  src/node/line_messages.cpp
  src/node/line_markers.cpp
  src/node/sea_markers.cpp
  src/node/section_layout.cpp
  src/node/section_markers.cpp
  src/node/attachment_markers.cpp
  src/node/range_window.cpp
  src/node/node_run.cpp
  src/node/timing_stats.cpp
  src/node/modes_service.cpp
  src/node/master_watch.cpp
  src/node/ros_clock.cpp
  src/node/line_topics.cpp
  src/node/node_diagnostics.cpp
  src/node/reset_handshake.cpp
  src/node/scene_param.cpp
  src/node/riser_sim_node.cpp
)
target_include_directories(riser_sim_ros PUBLIC include ${catkin_INCLUDE_DIRS})
target_link_libraries(riser_sim_ros riser_sim_core ${catkin_LIBRARIES})
add_dependencies(riser_sim_ros ${PROJECT_NAME}_generate_messages_cpp ${catkin_EXPORTED_TARGETS})
# roscpp's headers and Eigen parsed once for the node's files (cmake/core.cmake).
target_precompile_headers(riser_sim_ros PRIVATE <ros/ros.h> ${RISER_SIM_PCH_HEADERS})

add_executable(riser_sim_node src/node/main.cpp)
target_link_libraries(riser_sim_node riser_sim_ros)
# Nodelets riser_sim/RiserSimNodelet and riser_sim/VesselMotionNodelet (nodelet_plugins.xml).
add_library(riser_sim_nodelets SHARED src/node/riser_sim_nodelet.cpp src/node/vessel_motion_nodelet.cpp)
target_link_libraries(riser_sim_nodelets riser_sim_ros ${catkin_LIBRARIES})
install(TARGETS riser_sim_node riser_sim_ros riser_sim_nodelets
  RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION}
  LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
  ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION})
install(DIRECTORY include/riser_sim_ros/ DESTINATION ${CATKIN_GLOBAL_INCLUDE_DESTINATION}/riser_sim_ros)
# Every launch, scene, parameter and rviz file: a new one is installed without a line here.
install(DIRECTORY launch config rviz DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
install(FILES nodelet_plugins.xml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})

if(CATKIN_ENABLE_TESTING)
  find_package(rostest REQUIRED)
  # The node's test drivers (rostest gtests and the helpers' gtests) share one precompiled header (roscpp, tf2,
  # the messages, gtest, Eigen, yaml-cpp) and compile at RISER_SIM_ROS_TEST_OPT (-O0): they mostly wait on the
  # node, and the code they exercise is in riser_sim_ros and the core, built at -O3. Each driver took ~15 s of
  # CPU at -O3 parsing the same headers again (docs/hardening.md, "In CI"). gcc uses the PCH only if every
  # driver has its flags and macros: riser_sim_ros_test() gives each the same set, the binaries' paths included.
  set(RISER_SIM_ROS_TEST_OPT -O0 CACHE STRING "Optimisation of the node's test drivers")
  file(CONFIGURE OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/riser_sim_ros_test_pch.cpp CONTENT "")  # cmake/core.cmake
  add_library(riser_sim_ros_test_pch OBJECT EXCLUDE_FROM_ALL ${CMAKE_CURRENT_BINARY_DIR}/riser_sim_ros_test_pch.cpp)
  add_dependencies(riser_sim_ros_test_pch ${PROJECT_NAME}_generate_messages_cpp)  # riser_sim/*.h in the PCH
  target_precompile_headers(riser_sim_ros_test_pch PRIVATE <ros/ros.h> <ros/master.h> <gtest/gtest.h>
    <tf2_ros/buffer.h> <tf2_ros/transform_listener.h> <tf2_ros/transform_broadcaster.h> <tf2_msgs/TFMessage.h>
    <std_srvs/Trigger.h> <diagnostic_msgs/DiagnosticArray.h> <geometry_msgs/PoseStamped.h>
    <geometry_msgs/WrenchStamped.h> <nav_msgs/Odometry.h> <visualization_msgs/MarkerArray.h>
    <rosgraph_msgs/Clock.h> <riser_sim/LineState.h> <riser_sim/Tension.h> <riser_sim/Modes.h>
    <Eigen/Dense> <Eigen/Geometry> <yaml-cpp/yaml.h> <atomic> <cmath> <cstdio> <fstream> <functional> <map>
    <memory> <mutex> <sstream> <string> <vector>)
  function(riser_sim_ros_test target)
    target_link_libraries(${target} riser_sim_ros ${catkin_LIBRARIES} GTest::gtest)
    target_compile_options(${target} PRIVATE ${RISER_SIM_ROS_TEST_OPT})
    target_compile_definitions(${target} PRIVATE RISER_SIM_NODE_BIN="$<TARGET_FILE:riser_sim_node>"
      RISER_SIM_CLI_BIN="$<TARGET_FILE:riser_sim_cli>")
    if(NOT target STREQUAL riser_sim_ros_test_pch)
      target_precompile_headers(${target} REUSE_FROM riser_sim_ros_test_pch)
    endif()
  endfunction()
  riser_sim_ros_test(riser_sim_ros_test_pch)
  # Plain gtests of the ROS-side helpers (no master needed).
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/test/ros/test_node_helpers.cpp)
    catkin_add_gtest(test_node_helpers test/ros/test_node_helpers.cpp)
    riser_sim_ros_test(test_node_helpers)
  endif()
  # The 3D outputs through the node's run (NodeRun: ~state, markers, frames), no master either.
  catkin_add_gtest(test_node_helpers3 test/ros/test_node_helpers3.cpp)
  riser_sim_ros_test(test_node_helpers3)
  # RangeWindow (~range_graph's rolling window), no master either.
  catkin_add_gtest(test_range_window test/ros/test_range_window.cpp)
  riser_sim_ros_test(test_range_window)
  # rosrun finds the programs once and quietly (the workspace is not inside the package tree).
  catkin_add_gtest(test_rosrun test/ros/test_rosrun.cpp)
  riser_sim_ros_test(test_rosrun)
  add_dependencies(test_rosrun riser_sim_cli)
  # Node tests: test/ros/<name>.test launches the node(s) and the gtest built from test/ros/test_<name>.cpp.
  file(GLOB RISER_SIM_ROSTESTS RELATIVE ${CMAKE_CURRENT_SOURCE_DIR}/test/ros ${CMAKE_CURRENT_SOURCE_DIR}/test/ros/*.test)
  foreach(test_file ${RISER_SIM_ROSTESTS})
    get_filename_component(t ${test_file} NAME_WE)
    add_rostest_gtest(test_${t} test/ros/${t}.test test/ros/test_${t}.cpp)
    riser_sim_ros_test(test_${t})
    add_dependencies(test_${t} riser_sim_node riser_sim_nodelets riser_sim_cli)
  endforeach()
  # Master restart and security checks: a script, not a rostest (it kills and restarts the master).
  # It writes its own JUnit file, counted by catkin_test_results like the others.
  set(_master_restart_xml ${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/script-master_restart.xml)
  # catkin's run_tests.py runs each COMMAND argument as one shell command line.
  catkin_run_tests_target(script master_restart script-master_restart.xml
    COMMAND "/usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/test/ros/test_master_restart.py --node $<TARGET_FILE:riser_sim_node> --scene ${CMAKE_CURRENT_SOURCE_DIR}/test/ros/scenes/small_riser.yaml --xml ${_master_restart_xml}"
    DEPENDENCIES riser_sim_node)
  # Relaunching with another scene on a running master: the launch files clear the private namespace.
  set(_relaunch_xml ${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/script-relaunch_scene.xml)
  catkin_run_tests_target(script relaunch_scene script-relaunch_scene.xml
    COMMAND "/usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/test/ros/test_relaunch_scene.py --scenes ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes --xml ${_relaunch_xml}"
    DEPENDENCIES riser_sim_node riser_sim_nodelets)
endif()
