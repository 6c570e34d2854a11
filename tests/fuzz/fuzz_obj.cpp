// libFuzzer target: OBJ text through parse_obj_mesh (obj_loader.cpp, tinyobjloader).
// docs/fuzzing.md says how to build and run it.
#include "loader_contract.h"

#include "raylab/scene_loader.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  raylab::fuzz::expect_result_or_input_error(
      "fuzz.obj", [&] { return raylab::parse_obj_mesh(text, "fuzz.obj"); },
      [](const raylab::TriangleMesh& mesh) { raylab::fuzz::check_mesh(mesh, 0); });
  return 0;
}
