# riser_sim_sweep (src/riser_sim_sweep, docs/sweep.md): load-case sweeps and --tune through riser_sim_cli on
# Dask. The program is installed beside riser_sim_cli (lib/riser_sim), its package under lib/riser_sim/python;
# in the devel space catkin's relay runs the source file, which finds the package beside it.
# Its end-to-end test (test/sweep/test_sweep.py, ~1-2 min) writes a JUnit file: a catkin script test in the
# catkin build, a ctest in the core-only build (skipped by make check unless RISER_SIM_LONG=1).
if(RISER_SIM_CORE_ONLY)
  add_test(NAME test_sweep COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/test/sweep/test_sweep.py
    --cli $<TARGET_FILE:riser_sim_cli> --xml ${CMAKE_BINARY_DIR}/test_results/sweep.xml)
  return()
endif()
catkin_install_python(PROGRAMS src/riser_sim_sweep/riser_sim_sweep DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
install(DIRECTORY src/riser_sim_sweep/ DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION}/python/riser_sim_sweep
  FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
if(CATKIN_ENABLE_TESTING)
  set(_sweep_xml ${CATKIN_TEST_RESULTS_DIR}/${PROJECT_NAME}/script-sweep.xml)
  catkin_run_tests_target(script sweep script-sweep.xml
    COMMAND "/usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/test/sweep/test_sweep.py --cli $<TARGET_FILE:riser_sim_cli> --xml ${_sweep_xml}"
    DEPENDENCIES riser_sim_cli)
endif()
