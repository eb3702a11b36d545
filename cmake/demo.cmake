# Demo (see docs/demo.md): scripted vessel motion (rosrun riser_sim vessel_motion.py), the bag plotter,
# installed beside the node (its launch, rviz and scene files: cmake/node.cmake).
catkin_install_python(PROGRAMS scripts/vessel_motion.py scripts/plot_demo.py scripts/rov_circle.py scripts/dp_vessel.py
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
