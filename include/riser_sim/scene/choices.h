// The scene's choices as enums, each with its one table of names: the loader parses a name once, the
// code switches on the enum, and messages and docs list the names from the same table.
#pragma once
#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace riser_sim {

enum class IntegratorKind { kRk4, kDopri5, kRosenbrock2, kMidpoint, kGeneralizedAlpha };  // solver.integrator
enum class FormulationKind { kAbsolute, kIndependent, kRecursive };                       // solver.formulation
enum class JacobianKind { kAuto, kStructured, kDense };                                   // solver.jacobian
enum class MotionKind { kFixed, kSinusoid, kVelocityProfile, kExternal };                 // top.motion.type
enum class InitialKind { kHanging, kDisplaced, kBetweenPoints, kStraight };               // initial.type
enum class EndForceKind { kRelease, kHold };                                              // initial.end_force
enum class FlowModelKind { kPipeFlow, kPaper };                                           // internal_fluid.model
enum class SpaceKind { kPlanar, kSpatial };                                               // space
enum class WaveKind { kRegular, kJonswap };                                               // environment.waves.type

template <class E>
struct Choices;  // static constexpr std::array<std::pair<E, const char*>, N> names

template <>
struct Choices<IntegratorKind> {
  static constexpr std::array<std::pair<IntegratorKind, const char*>, 5> names{
      {{IntegratorKind::kRk4, "rk4"},
       {IntegratorKind::kDopri5, "dopri5"},
       {IntegratorKind::kRosenbrock2, "rosenbrock2"},
       {IntegratorKind::kMidpoint, "midpoint"},
       {IntegratorKind::kGeneralizedAlpha, "generalized_alpha"}}};
};
template <>
struct Choices<FormulationKind> {
  static constexpr std::array<std::pair<FormulationKind, const char*>, 3> names{
      {{FormulationKind::kAbsolute, "absolute"},
       {FormulationKind::kIndependent, "independent"},
       {FormulationKind::kRecursive, "recursive"}}};
};
template <>
struct Choices<JacobianKind> {
  static constexpr std::array<std::pair<JacobianKind, const char*>, 3> names{
      {{JacobianKind::kAuto, "auto"}, {JacobianKind::kStructured, "structured"}, {JacobianKind::kDense, "dense"}}};
};
template <>
struct Choices<MotionKind> {
  static constexpr std::array<std::pair<MotionKind, const char*>, 4> names{
      {{MotionKind::kFixed, "fixed"},
       {MotionKind::kSinusoid, "sinusoid"},
       {MotionKind::kVelocityProfile, "velocity_profile"},
       {MotionKind::kExternal, "external"}}};
};
template <>
struct Choices<InitialKind> {
  static constexpr std::array<std::pair<InitialKind, const char*>, 4> names{
      {{InitialKind::kHanging, "hanging"},
       {InitialKind::kDisplaced, "displaced"},
       {InitialKind::kBetweenPoints, "between_points"},
       {InitialKind::kStraight, "straight"}}};
};
template <>
struct Choices<EndForceKind> {
  static constexpr std::array<std::pair<EndForceKind, const char*>, 2> names{
      {{EndForceKind::kRelease, "release"}, {EndForceKind::kHold, "hold"}}};
};
template <>
struct Choices<FlowModelKind> {
  static constexpr std::array<std::pair<FlowModelKind, const char*>, 2> names{
      {{FlowModelKind::kPipeFlow, "pipe_flow"}, {FlowModelKind::kPaper, "paper"}}};
};

template <>
struct Choices<WaveKind> {
  static constexpr std::array<std::pair<WaveKind, const char*>, 2> names{
      {{WaveKind::kRegular, "regular"}, {WaveKind::kJonswap, "jonswap"}}};
};

template <>
struct Choices<SpaceKind> {
  static constexpr std::array<std::pair<SpaceKind, const char*>, 2> names{
      {{SpaceKind::kPlanar, "planar"}, {SpaceKind::kSpatial, "spatial"}}};
};

// The name of a choice ("rk4").
template <class E>
const char* name(E e) {
  for (const auto& [value, text] : Choices<E>::names)
    if (value == e) return text;
  return "?";
}
// The choice with that name, if any.
template <class E>
std::optional<E> parseChoice(std::string_view text) {
  for (const auto& [value, name] : Choices<E>::names)
    if (text == name) return value;
  return std::nullopt;
}
// Every name, comma separated ("rk4, dopri5, rosenbrock2, midpoint, generalized_alpha").
template <class E>
std::string choiceNames() {
  std::string out;
  for (const auto& entry : Choices<E>::names) out += (out.empty() ? "" : ", ") + std::string(entry.second);
  return out;
}

// The choice with that name; throws std::invalid_argument naming the accepted ones.
template <class E>
E toChoice(std::string_view text) {
  if (const auto e = parseChoice<E>(text)) return *e;
  throw std::invalid_argument("unknown value '" + std::string(text) + "' (accepted: " + choiceNames<E>() + ")");
}

}  // namespace riser_sim
