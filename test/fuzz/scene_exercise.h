// One fuzz input through the whole scene path: text (+ "--set" lines) -> loadSceneText -> buildSimulator
// -> a few steps. Shared by the libFuzzer target (test/fuzz/fuzz_scene.cpp) and the regression gtest
// (test/core/scene/test_scene_fuzz_regressions.cpp).
#pragma once
#include <string>
#include <vector>

namespace riser_sim {
namespace fuzz {

// Input format: lines starting with "--set " are overrides (key.path=value, applied in order); every
// other line is the scene's YAML text.
struct SceneInput {
  std::string yaml;
  std::vector<std::string> overrides;
};
SceneInput splitInput(const std::string& data);

// What happened to an input. `defect` is empty unless the input broke a rule: only riser_sim errors
// that name their key (or a syntax/override error of the whole text), nothing non-finite out of a
// built simulator.
struct Outcome {
  // kRejected by the loader, kParsed (valid, more than kMaxBuiltElements or a long dopri5 step), kBuildRejected by
  // buildSimulator.
  enum class Kind { kRejected, kParsed, kBuildRejected, kBuilt } kind = Kind::kRejected;
  std::string message;  // the error, or "built, N steps" / "parsed ..."
  std::string defect;
};

// Scenes with more elements than this are parsed but not built (keeps one input to milliseconds).
constexpr int kMaxBuiltElements = 40;
// dopri5 scenes with a longer output step are parsed but not built: one step may take up to its 1e5
// substeps (0.3 s in Release, ~50 s under the fuzzer's instrumentation): slow, not a defect.
constexpr double kMaxBuiltDopri5Dt = 1.0;  // [s]
// Steps taken after a successful build.
constexpr int kSteps = 5;

Outcome exercise(const std::string& data);

}  // namespace fuzz
}  // namespace riser_sim
