// libFuzzer target: scene JSON through parse_scene (scene_schema.cpp, json_reader.cpp) and the
// OBJ files a scene names, resolved against tests/fuzz/ (which holds tiny.obj).
// docs/fuzzing.md says how to build and run it.
#include "loader_contract.h"

#include "raylab/scene_loader.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  raylab::fuzz::expect_result_or_input_error(
      "fuzz.json", [&] { return raylab::parse_scene(text, "fuzz.json", RAYLAB_FUZZ_DIR); },
      [](const raylab::Scene& scene) { raylab::fuzz::check_scene(scene); });
  return 0;
}
