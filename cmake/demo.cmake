# Demo (see docs/demo.md): scripted vessel motion (rosrun riser_sim vessel_motion.py), the bag plotter,
# and the launch/rviz/scene files behind `make demo`.
catkin_install_python(PROGRAMS scripts/vessel_motion.py scripts/plot_demo.py scripts/rov_circle.py scripts/dp_vessel.py
  DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
install(FILES launch/demo.launch launch/rov_tether.launch launch/dp_station_keeping.launch DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/launch)
install(FILES rviz/riser.rviz rviz/riser_3d.rviz DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/rviz)
install(FILES config/scenes/demo_riser.yaml config/scenes/demo_riser_3d.yaml config/scenes/rov_tether.yaml config/scenes/dp_riser.yaml DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/config/scenes)
