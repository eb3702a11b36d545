#include "riser_sim/run/relaxed_statics.h"

#include <cmath>
#include <stdexcept>

#include "riser_sim/scene/in_plane.h"
#include "riser_sim/spatial/relaxation.h"
#include "riser_sim/spatial/run_builder.h"

namespace riser_sim {

StaticsResult relaxedPlanarStatics(const Scene& scene, const Model& model, const StaticsProblem& problem) {
  StaticsResult res;
  // The planar scene is the 3D scene in its x-z plane.
  Scene in3d = scene;
  in3d.space = SpaceKind::kSpatial;
  if (const auto issue = spatial::unsupported(in3d)) {
    res.message = "no 3D relaxation for this scene (" + issue->key + ": " + issue->message + ")";
    return res;
  }
  const spatial::Vec3 top(problem.top.x(), 0.0, problem.top.y());
  spatial::Relaxed3 r;
  try {
    r = spatial::relaxFromFirstGuess(in3d, model, problem, spatial::Mat3::Identity(), spatial::Vec3::Zero(), top,
                                     spatial::restAccelerationBound(scene, model));
  } catch (const std::runtime_error& e) {
    res.message = std::string("relaxed in 3D from the first guess: ") + e.what();
    return res;
  }
  // Back into the plane (y = 0 throughout: nothing loads the line across it), at rest.
  Kinematics kin(model.bodies());
  for (int i = 0; i < model.bodies(); ++i) {
    const spatial::BodyKinematics3& b = r.kin[i];
    BodyKinematics& p = kin[i];
    p.A = Vec2(b.A.x(), b.A.z());
    p.phi = std::atan2(b.e.z(), b.e.x());
    p.c = std::cos(p.phi);
    p.s = std::sin(p.phi);
    p.delta = b.delta;
    p.len = b.len;
  }
  // Newton's start for the end force: the relaxed state's (a pinned end's anchor reaction; a free end's none).
  res = solveStaticsFrom(model, problem, kin, inPlane(r.end_force));
  res.message = "relaxed in 3D from the first guess (" + std::to_string(r.steps) + " steps), then " + res.message;
  return res;
}

}  // namespace riser_sim
