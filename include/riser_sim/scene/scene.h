// A scene: everything a run needs, as plain data (loaded from YAML by scene_yaml.h, or built in code).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "riser_sim/line/attachment.h"
#include "riser_sim/run/build_options.h"
#include "riser_sim/scene/choices.h"
#include "riser_sim/line/line_properties.h"
#include "riser_sim/line/line_sections.h"
#include "riser_sim/planar/model.h"
#include "riser_sim/planar/simulator.h"
#include "riser_sim/planar/statics.h"
#include "riser_sim/planar/forces/internal_flow.h"
#include "riser_sim/planar/forces/seabed.h"
#include "riser_sim/motion/top_motion.h"
#include "riser_sim/planar/water.h"
#include "riser_sim/scene/in_plane.h"
#include "riser_sim/scene/water_spec.h"

namespace riser_sim {

// Vectors are 3D, [x, y, z] with z up (REP 103). A planar scene is the 3D scene in its vertical x-z plane
// (y = 0): the planar engine reads inPlane(v) = (x, z) (scene/in_plane.h). A scene's 2-vector [a, b] is
// (a, 0, b); a 3-vector [x, y, z] with y != 0 is refused in a planar scene.
struct TopMotionSpec {
  struct Knot {
    double t;           // [s]
    Eigen::Vector3d v;  // [m/s]
  };
  MotionKind type = MotionKind::kFixed;                 // top.motion.type
  Eigen::Vector3d position = Eigen::Vector3d::Zero();   // top.position: A_0 at t = 0 (centre of a sinusoid) [m]
  Eigen::Vector3d amplitude = Eigen::Vector3d::Zero();  // sinusoid [m]
  double period = 1.0;                                  // sinusoid [s]
  // sinusoid, per axis [rad] (top.motion.phase: a number, the same on every axis, or a 3-vector in 3D); the
  // planar engine reads phase.x() (a planar scene has one phase).
  Eigen::Vector3d phase = Eigen::Vector3d::Zero();
  std::vector<Knot> knots;  // velocity_profile: (t, v)
  // sinusoid, spatial: the holder's attitude, roll/pitch/yaw (Z-Y-X) = attitude ∘ cos(2π t / period +
  // attitude_phase) [rad] (top.motion.attitude [deg], attitude_phase [rad]); zero: the holder does not turn.
  Eigen::Vector3d attitude = Eigen::Vector3d::Zero();
  Eigen::Vector3d attitude_phase = Eigen::Vector3d::Zero();
};

// A flex joint at an end (space: spatial; spatial/forces/flex_joint.h): a rotational spring k and damper c
// between the end rfe and the holder's axis. Absent: the end is pinned (free rotation).
struct FlexJointSpec {
  bool enabled = false;                            // top.flex_joint / bottom.flex_joint present
  double stiffness = 0.0;                          // k [N m/rad] > 0
  double damping = 0.0;                            // c [N m s/rad] >= 0
  bool has_axis = false;                           // axis given; else the line's direction there in the initial state
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();  // along the line, away from the holder
  double torsional_stiffness = 0.0;                // k_t [N m/rad] about the line's axis (top, line.torsion); 0: none
  double torsional_damping = 0.0;                  // c_t [N m s/rad] beside k_t: moment c_t m_t' on the twist rate
};

struct InitialSpec {
  InitialKind type = InitialKind::kHanging;  // initial.type
  double end_dx = 0.0;                       // displaced: x_end - x_top [m]
  // displaced, 3D: horizontal offset (x, y) of the end from the top [m]: initial.end_offset, or
  // (end_dx, 0) when only end_dx is given.
  Vec2 end_offset = Vec2::Zero();
  double heading = 0.0;      // straight, 3D: azimuth of the line's vertical plane from +x towards +y [rad]
  double angle = -M_PI / 2;  // straight: φ [rad] (-π/2 = hanging straight down)
  double tolerance = 1e-9;   // statics: residual relative to the line's weight
  // displaced: "release" drops the statics' horizontal end force at t = 0 (the end is let go);
  // "hold" keeps it as a constant end load (EndLoad), so the initial state is an exact equilibrium.
  EndForceKind end_force = EndForceKind::kRelease;
  // initial.velocity (initial_velocity.h): a rigid motion of the whole line given to the start, after the
  // statics or the straight line: a rotation about the vertical through the top (+z, counter-clockwise seen
  // from above) and a uniform translation. has_velocity false: the start is at rest (no velocity code runs).
  bool has_velocity = false;
  double rotation = 0.0;                                  // initial.velocity.rotation [rad/s]
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();  // initial.velocity.translation [m/s], z up
};

// line.torsion (space: spatial only): off when absent (the spin about the line's axis is then no degree of freedom).
struct TorsionSpec {
  bool enabled = false;
  double stiffness = 0.0;          // GJ [N m^2]
  double polar_inertia = 0.0;      // ρ I_p per length [kg m]
  double damping = 0.0;            // c_GJ [N m^2 s]
  double end_polar_inertia = 0.0;  // the end body's, about the line's axis [kg m^2]
  bool free_top = false;           // top.torsion: free (the hang-off leaves the spin free)
};

// line.EI: [EI_1, EI_2] with line.bending_axis (space: spatial, line.torsion): bending stiffness about the rfes'
// two material axes (spatial/bending_axes.h); LineProperties::EI holds their mean.
struct BendingAxesSpec {
  bool enabled = false;
  double EI1 = 0.0, EI2 = 0.0;  // about axis 1, about axis 2 = e × axis 1 [N m^2]
  Eigen::Vector3d axis =
      Eigen::Vector3d::Zero();  // axis 1 at the hang-off at t = 0 (world; its part normal to the top rfe)
};

struct HydroSpec {
  bool enabled = false;
  double drag_tangential = 0.0;      // D_ξ
  double drag_normal = 0.0;          // D_η
  double inertia_coefficient = 1.0;  // C_M (added mass C_M - 1 across the line)
  double axial_added_mass = 0.0;     // C_a,t along the line (Froude-Krylov along it: 1 + C_a,t)
};

struct Scene {
  std::string name;
  SpaceKind space = SpaceKind::kPlanar;  // space: planar (2D core) or spatial (3D core, spatial/run_builder.h)
  double length = 0.0;                   // line.length [m]
  int elements = 0;                      // line.elements: n segments (n + 1 rfes)
  LineProperties line;
  // line.sections from the top (empty: one uniform section, the line's); the sections' lengths add up to
  // length and their elements to elements. line.bend_stiffener: EI(s) near an end.
  std::vector<LineSection> sections;
  std::vector<BendStiffener> stiffeners;
  ModelOptions options;
  double end_mass = 0.0;         // line.end_mass [kg]
  TorsionSpec torsion;           // line.torsion
  BendingAxesSpec bending_axes;  // line.EI: [EI_1, EI_2], line.bending_axis
  double gravity = 9.81;         // environment.gravity [m/s^2]
  TopMotionSpec top;
  FlexJointSpec top_flex_joint;  // top.flex_joint (3D)
  BottomBoundary bottom = BottomBoundary::kFree;
  Eigen::Vector3d bottom_point = Eigen::Vector3d::Zero();  // bottom.position [m]
  // bottom.motion of a pinned bottom (3D; the top's motion keys): its position is bottom.position. fixed by
  // default; external is held at bottom.position until fed (as the top's external in the CLI).
  TopMotionSpec bottom_motion;
  FlexJointSpec bottom_flex_joint;  // bottom.flex_joint (3D, pinned bottom)
  InitialSpec initial;
  SolverSettings solver;
  double duration = 20.0;  // run.duration [s] (CLI default)
  // Sea and flow (each optional; a section that is absent builds no term).
  WaterSpec water;                          // environment.water / current / waves
  HydroSpec hydro;                          // hydrodynamics
  SeabedSpec seabed;                        // seabed
  InternalFlowSpec internal_fluid;          // internal_fluid
  std::vector<AttachmentSpec> attachments;  // attachments: point bodies on the line (attachment.h)
};

// The scene's line as sections (one when line.sections is absent), the internal fluid's mass in each.
std::vector<LineSection> lineSections(const Scene& scene);
// Some section has a C_M or C_a,t of its own (the added-mass terms are built for it).
bool sectionsAddMass(const Scene& scene);
// The planar engine's model and holder motion: they read inPlane of the scene's vectors (a sinusoid's phase.x()).
// `options` (build_options.h): the planar engine takes the steady sea, a pinned end's point and an end load (their x
// and z); the other options are 3D only and throw std::invalid_argument, as an end load on a pinned end does.
std::shared_ptr<Model> buildModel(const Scene& scene, const BuildOptions& options = BuildOptions());
std::unique_ptr<TopMotion> buildTopMotion(const TopMotionSpec& spec);
// Static problem for the scene's initial state (top at the motion's position at t = 0).
StaticsProblem staticsProblem(const Scene& scene);

}  // namespace riser_sim
