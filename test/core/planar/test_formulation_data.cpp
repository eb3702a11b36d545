// The formulation / data split (formulation.h, formulation_data.h): a formulation keeps no evaluation state,
// so one formulation serves several data objects; every result is read from the data it was computed
// into; the structured solve linearises at the inputs it is given; misuse is refused. The results are
// compared for exact equality: the same inputs through the same code give the same bits, so any state
// leaking between data objects or between calls shows up as a difference.
#include <gtest/gtest.h>

#include <memory>
#include <random>

#include "riser_sim/planar/absolute_formulation.h"
#include "riser_sim/planar/independent_formulation.h"
#include "riser_sim/planar/recursive_formulation.h"
#include "riser_sim/planar/run_builder.h"
#include "riser_sim/scene/scene.h"
#include "riser_sim/scene/scene_yaml.h"

namespace riser_sim {
namespace {

// The 170 m J-lay with every hydro term (buoyancy, drag, added mass, contents) and the seabed, n = 12.
Scene jlay(bool axial) {
  Scene s = loadSceneFile(std::string(RISER_SIM_SOURCE_DIR) + "/config/scenes/paper_jlay_170m.yaml");
  s.elements = 12;
  s.options.axial_flexibility = axial;
  return s;
}

std::unique_ptr<Formulation> make(const std::string& name, const Model& model) {
  if (name == "absolute") return std::make_unique<AbsoluteFormulation>(model, 50.0);
  if (name == "independent") return std::make_unique<IndependentFormulation>(model, 50.0);
  return std::make_unique<RecursiveFormulation>(model, 50.0);
}

// Two states of one line: the static state (at rest) and one moved off it, with rates.
struct States {
  std::unique_ptr<Simulator> sim;
  VecX a, b;
  PointMotion top_a, top_b;
  double t_a = 0.0, t_b = 0.7;
};

States states(const Scene& scene, const Formulation& f) {
  States s;
  s.sim = buildSimulator(scene);
  Kinematics kin(s.sim->model().bodies());
  s.sim->kinematics(kin);
  const int p = f.positionSize();
  s.a = VecX::Zero(2 * p);
  f.packState(kin, s.a);
  s.b = s.a;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 2 * p; ++i) s.b[i] += 1e-3 * u(rng);
  s.top_a = PointMotion{kin[0].A, Vec2::Zero(), Vec2::Zero()};
  s.top_b = PointMotion{kin[0].A + Vec2(0.3, -0.1), Vec2(0.2, 0.1), Vec2(-0.5, 0.3)};
  return s;
}

void expectSameEvaluation(const FormulationData& x, const FormulationData& y, const char* what) {
  for (size_t i = 0; i < x.kin.size(); ++i) {
    EXPECT_EQ(x.kin[i].A, y.kin[i].A) << what << " rfe " << i;
    EXPECT_EQ(x.kin[i].A_dot, y.kin[i].A_dot) << what << " rfe " << i;
    EXPECT_EQ(x.kin[i].phi_dot, y.kin[i].phi_dot) << what << " rfe " << i;
  }
  for (size_t k = 0; k < x.reactions.joint.size(); ++k)
    EXPECT_EQ(x.reactions.joint[k], y.reactions.joint[k]) << what << " joint " << k;
  EXPECT_EQ(x.reactions.top, y.reactions.top) << what;
  EXPECT_EQ(x.reactions.bottom, y.reactions.bottom) << what;
  EXPECT_EQ(x.term_power, y.term_power) << what;
  EXPECT_EQ(x.constraint_error, y.constraint_error) << what;
}

TEST(FormulationData, OneFormulationServesSeveralDataObjects) {
  for (const char* name : {"absolute", "independent", "recursive"}) {
    for (bool axial : {true, false}) {
      const Scene scene = jlay(axial);
      auto model = buildModel(scene);
      auto f = make(name, *model), g = make(name, *model);
      const States s = states(scene, *f);
      const int n = static_cast<int>(s.a.size());
      auto d1 = f->makeData(), d2 = f->makeData(), ref = g->makeData();
      VecX dy1(n), dy2(n), dyr(n);
      // Interleaved: a into d1, b into d2, then a again into d2 of the same formulation.
      f->derivative(s.t_a, s.a, s.top_a, dy1, *d1);
      f->derivative(s.t_b, s.b, s.top_b, dy2, *d2);
      g->derivative(s.t_a, s.a, s.top_a, dyr, *ref);
      EXPECT_EQ(dy1, dyr) << name;
      expectSameEvaluation(*d1, *ref, name);
      EXPECT_TRUE(f->evaluatedAt(s.t_a, s.a, s.top_a, *d1)) << name;
      EXPECT_FALSE(f->evaluatedAt(s.t_b, s.b, s.top_b, *d1)) << name;
      EXPECT_FALSE(f->evaluatedAt(s.t_a, s.a, s.top_b, *d1)) << name << ": another top motion";
      EXPECT_TRUE(f->evaluatedAt(s.t_b, s.b, s.top_b, *d2)) << name;
      EXPECT_FALSE(f->evaluatedAt(s.t_a, s.a, s.top_a, *ref)) << name << ": data of another formulation";
      // The kinetic energy has its own workspace: d1 keeps its evaluation.
      const double T = f->kineticEnergy(s.t_b, s.b, s.top_b, *d1);
      EXPECT_EQ(T, g->kineticEnergy(s.t_b, s.b, s.top_b, *ref)) << name;
      EXPECT_GT(T, 0.0) << name;
      EXPECT_TRUE(f->evaluatedAt(s.t_a, s.a, s.top_a, *d1)) << name;
      g->derivative(s.t_a, s.a, s.top_a, dyr, *ref);
      expectSameEvaluation(*d1, *ref, name);
    }
  }
}

// linearize(t, y, top, data) linearises at its inputs whatever data held before, and keeps the
// linearisation while data evaluates elsewhere (the Newton iterations of the implicit schemes).
TEST(FormulationData, LinearizeAtItsInputsWhateverDataHeld) {
  for (const char* name : {"independent", "recursive"}) {
    for (bool axial : {true, false}) {
      const Scene scene = jlay(axial);
      auto model = buildModel(scene);
      auto f = make(name, *model);
      const States s = states(scene, *f);
      const int n = static_cast<int>(s.a.size()), m = n;
      auto fresh = f->makeData(), stale = f->makeData();
      VecX dy(n), b(n), x1 = VecX::Zero(n), x2 = VecX::Zero(n), x3 = VecX::Zero(n);
      std::mt19937 rng(3);
      std::uniform_real_distribution<double> u(-1.0, 1.0);
      for (int i = 0; i < m; ++i) b[i] = u(rng);
      const double c = 0.01;
      f->derivative(s.t_b, s.b, s.top_b, dy, *fresh);
      f->linearize(s.t_b, s.b, s.top_b, *fresh);  // data evaluated at the inputs: used as it is
      f->factorShifted(c, *fresh);
      f->solveShifted(b, x1, *fresh);
      f->derivative(s.t_a, s.a, s.top_a, dy, *stale);
      f->linearize(s.t_b, s.b, s.top_b, *stale);  // data evaluated elsewhere: evaluates at the inputs first
      EXPECT_TRUE(f->evaluatedAt(s.t_b, s.b, s.top_b, *stale)) << name;
      f->factorShifted(c, *stale);
      f->solveShifted(b, x2, *stale);
      EXPECT_EQ(x1, x2) << name << " axial " << axial;
      f->derivative(s.t_a, s.a, s.top_a, dy, *stale);  // a Newton evaluation elsewhere
      f->solveShifted(b, x3, *stale);
      EXPECT_EQ(x1, x3) << name << " axial " << axial;
      EXPECT_GT(x1.head(m).cwiseAbs().maxCoeff(), 0.0);
    }
  }
}

TEST(FormulationData, MisuseIsRefused) {
  const Scene scene = jlay(true);
  auto model = buildModel(scene);
  auto rec = make("recursive", *model), rec2 = make("recursive", *model), abs = make("absolute", *model);
  const States s = states(scene, *rec);
  VecX dy = VecX::Zero(s.a.size()), x(s.a.size());
  auto d = rec->makeData(), d2 = rec2->makeData(), da = abs->makeData();
  EXPECT_THROW(rec->derivative(s.t_a, s.a, s.top_a, dy, *d2), std::invalid_argument);  // same type, other owner
  EXPECT_THROW(rec->derivative(s.t_a, s.a, s.top_a, dy, *da), std::invalid_argument);  // other type
  EXPECT_THROW(rec->kineticEnergy(s.t_a, s.a, s.top_a, *da), std::invalid_argument);
  EXPECT_THROW(rec->factorShifted(0.01, *d), std::logic_error);  // before linearize
  rec->linearize(s.t_a, s.a, s.top_a, *d);
  EXPECT_THROW(rec->solveShifted(dy, x, *d), std::logic_error);  // before factorShifted
  rec->factorShifted(0.01, *d);
  EXPECT_NO_THROW(rec->solveShifted(dy, x, *d));
  rec->linearize(s.t_b, s.b, s.top_b, *d);
  EXPECT_THROW(rec->solveShifted(dy, x, *d), std::logic_error);  // factorisation of the old linearisation
  EXPECT_FALSE(abs->hasShiftedSolve());
  EXPECT_THROW(abs->linearize(s.t_a, s.a, s.top_a, *da), std::logic_error);
}

// The Simulator keeps no evaluation cache: reading outputs, energies and the constraint error between
// steps (each evaluates into the run's data) leaves the run bit for bit as it was, on every integrator,
// the structured solves included, with the seabed's history on.
TEST(FormulationData, ReadingOutputsBetweenStepsDoesNotChangeTheRun) {
  struct Run {
    const char* integrator;
    const char* formulation;
    const char* jacobian;
  };
  const Run runs[] = {{"rk4", "recursive", "auto"},
                      {"rk4", "absolute", "auto"},
                      {"dopri5", "independent", "auto"},
                      {"midpoint", "recursive", "structured"},
                      {"rosenbrock2", "independent", "structured"},
                      {"rosenbrock2", "absolute", "dense"}};
  for (const Run& r : runs) {
    Scene scene = jlay(true);
    scene.solver.integrator = toChoice<IntegratorKind>(r.integrator);
    scene.solver.formulation = toChoice<FormulationKind>(r.formulation);
    scene.solver.jacobian = toChoice<JacobianKind>(r.jacobian);
    scene.solver.dt = 0.01;
    if (std::string(r.integrator) == "rk4") scene.solver.dt = 0.5 * buildSimulator(scene)->stableStepEstimate();
    auto quiet = buildSimulator(scene), read = buildSimulator(scene);
    for (int k = 0; k < 20; ++k) {
      ASSERT_TRUE(quiet->step()) << quiet->divergenceReason();
      ASSERT_TRUE(read->step()) << read->divergenceReason();
      read->outputs();
      read->totalEnergy();
      read->constraintError();
    }
    EXPECT_EQ(quiet->state(), read->state()) << r.integrator << " / " << r.formulation;
    EXPECT_GT((quiet->state() - buildSimulator(scene)->state()).cwiseAbs().maxCoeff(), 0.0) << "the line moved";
  }
}

}  // namespace
}  // namespace riser_sim
