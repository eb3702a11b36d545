// node_scene_check.test: the node runs a 3D scene the loader accepts (spatial_swing.yaml with
// solver.jacobian structured): it starts from the statics at the vessel's pose and publishes tension.
#include "node_test_util.h"
#include "riser_sim/scene/scene_yaml.h"
#include "riser_sim/spatial/run_builder.h"

using namespace riser_sim_test;

namespace {

TEST(NodeSceneCheck, SpatialSceneWithStructuredJacobianRuns) {
  ros::NodeHandle nh, pnh("~");
  std::string scene_file;
  ASSERT_TRUE(pnh.getParam("scene_file", scene_file));
  // The vessel holds the top where the scene has it at t = 0.
  const riser_sim::Scene scene = riser_sim::loadSceneFile(scene_file, {"solver.jacobian=structured"});
  const Eigen::Vector3d top = riser_sim::spatial::buildTopMotion3(scene.top)->at(0.0).p;
  PosePublisher pose(nh, "/vessel/pose", 20.0, [&](double, geometry_msgs::Pose& p) {
    p.position.x = top.x(), p.position.y = top.y(), p.position.z = top.z();
  });
  Recorder<riser_sim::Tension> tension(nh, "/riser_sim/tension");
  ASSERT_TRUE(waitFor([&] { return pose.subscribers() > 0; }, 20.0));
  pose.start();
  ASSERT_TRUE(tension.waitCount(5, 30.0)) << "the node did not publish tension";
  for (const auto& m : tension.all()) EXPECT_TRUE(finite(m));
  const riser_sim::Tension last = tension.last();
  ASSERT_EQ(last.axial_force.size(), size_t(scene.elements) + 1);
  // The 50 kg end mass and the 111 kg pipe hang from the top: about 1.6 kN there.
  EXPECT_GT(last.top, 1000.0);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_node_scene_check");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const int rc = RUN_ALL_TESTS();
  spinner.stop();
  return rc;
}
