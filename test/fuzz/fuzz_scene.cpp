// libFuzzer target: scene text (+ "--set key=value" lines) -> loader -> validation -> buildSimulator ->
// a few steps (test/fuzz/scene_exercise.h). Any rule broken is reported and aborts, so libFuzzer keeps
// the input as a crasher. Run with `make fuzz` (test/fuzz/Makefile).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scene_exercise.h"

// FUZZ_SCENE_VERBOSE=1 prints every input's outcome (triage: `fuzz_scene -runs=0 FILES`).
static const bool kVerbose = std::getenv("FUZZ_SCENE_VERBOSE") != nullptr;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 4096) return 0;  // scenes are small; longer inputs only slow the search down
  const riser_sim::fuzz::Outcome out =
      riser_sim::fuzz::exercise(std::string(reinterpret_cast<const char*>(data), size));
  if (kVerbose) std::fprintf(stderr, "outcome: %s\n", out.message.c_str());
  if (!out.defect.empty()) {
    std::fprintf(stderr, "scene fuzz defect: %s\n", out.defect.c_str());
    std::abort();
  }
  return 0;
}
