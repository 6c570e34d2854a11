// What fuzzing the loaders found (docs/fuzzing.md), one test per finding: each input once
// crashed, hung, read without end or broke the loaders' contract, and must now load or be
// rejected with an InputError naming the problem and the place. The same inputs are in the
// kept corpus (tests/fuzz/corpus/*/finding-*), which ctest also replays through the fuzz
// targets with the sanitizers in a -DRAYLAB_FUZZ=ON build.
#include "raylab/error.h"
#include "raylab/scene_loader.h"

#include "test_helpers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace raylab {
namespace {

using testing::scratch_dir;
using testing::write_text_file;

// The message of the InputError that `load` throws, or a failure if it throws none.
template <typename Load>
::testing::AssertionResult input_error_naming(Load load, const std::vector<std::string>& fragments) {
  try {
    load();
    return ::testing::AssertionFailure() << "loaded without an InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const std::string& fragment : fragments)
      if (message.find(fragment) == std::string::npos)
        return ::testing::AssertionFailure() << "the message does not name '" << fragment << "': " << message;
    return ::testing::AssertionSuccess();
  }
}

const char* const kCamera = R"("camera": {"position": [0, 0, 5], "look_at": [0, 0, 0]})";

TEST(FuzzFindings, NumberBeyondADoubleNamesTheLine) {
  // nlohmann-json threw out_of_range (not parse_error) for it, which escaped the loader.
  const std::string text = std::string("{\n  ") + kCamera + ",\n  \"max_depth\": 1e999,\n  \"objects\": []\n}";
  EXPECT_TRUE(input_error_naming([&] { parse_scene(text, "overflow.json", "."); },
                                 {"overflow.json", "line 3, column 16", "1e999", "too large"}));
}

TEST(FuzzFindings, MillionDeepNestingIsRejectedAtItsPlace) {
  // Parsed, a million nested arrays overflowed the stack when the message printed them.
  const std::string text = "{\"camera\": " + std::string(1000000, '[') + std::string(1000000, ']') + "}";
  EXPECT_TRUE(input_error_naming([&] { parse_scene(text, "deep.json", "."); },
                                 {"deep.json", "line 1, column 75", "nested deeper than 64"}));
}

TEST(FuzzFindings, VertexWeightLinesAreIgnored) {
  // tinyobjloader converts vw's joint numbers to int unchecked: 1e10 was undefined behaviour
  // (UndefinedBehaviorSanitizer reports it in the fuzz build, not here); raylab skips the line.
  const TriangleMesh mesh = parse_obj_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nvw 0 1e10 0.5\nf 1 2 3\n", "vw.obj");
  EXPECT_EQ(mesh.triangle_count(), 1u);
  EXPECT_EQ(mesh.positions.size(), 3u);
}

TEST(FuzzFindings, VertexWeightLinesAfterALoneCarriageReturnAreIgnoredToo) {
  // tinyobjloader also ends a line at a lone "\r" (old Mac files).
  const TriangleMesh mesh = parse_obj_mesh("v 0 0 0\rv 1 0 0\rv 0 1 0\rvw 0 1e10 0.5\rf 1 2 3\r", "vw_cr.obj");
  EXPECT_EQ(mesh.triangle_count(), 1u);
}

TEST(FuzzFindings, ExponentWithTooManyDigitsNamesTheLine) {
  // tinyobjloader's exponent (an int) overflowed on 5e-2147483648 (found by fuzz_obj).
  EXPECT_TRUE(input_error_naming(
      [] { parse_obj_mesh("v 0 0 0\nv 1 0 0\nv 5e-2147483648 1 0\nf 1 2 3\n", "exponent.obj"); },
      {"exponent.obj", "line 3", "exponent has more than 9 digits"}));
  // Nine digits are still read (as 0 here).
  EXPECT_EQ(parse_obj_mesh("v 0 0 0\nv 1 0 0\nv 5e-999999999 1 0\nf 1 2 3\n", "nine.obj").triangle_count(), 1u);
}

TEST(FuzzFindings, TexcoordBeyondAFloatIsAnError) {
  // vt 1e39 became an infinite texture coordinate, which the loader passed on.
  EXPECT_TRUE(input_error_naming(
      [] { parse_obj_mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 1e39 0\nf 1/1 2/1 3/1\n", "vt.obj"); },
      {"vt.obj", "texture coordinate (vt)", "not a finite float"}));
}

TEST(FuzzFindings, ScaleThatLeavesTheFloatRangeNamesTheObject) {
  // Finite vertices times a finite scale made infinite positions, passed on to the renderer.
  const std::filesystem::path dir = scratch_dir();
  write_text_file(dir / "big.obj", "v 3e38 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n");
  const std::string scene = std::string("{") + kCamera +
      R"(, "materials": {"m": {"type": "diffuse"}},
         "objects": [{"type": "obj", "file": "big.obj", "scale": 10, "material": "m"}]})";
  EXPECT_TRUE(input_error_naming([&] { parse_scene(scene, "scale.json", dir.string()); },
                                 {"scale.json", "/objects/0", "beyond the float range", "big.obj"}));
}

TEST(FuzzFindings, AFolderOrADeviceIsNotReadAsAFile) {
  // A folder read as empty text; /dev/zero was read without end (memory grew until killed).
  const std::string dir = scratch_dir().string();
  EXPECT_TRUE(input_error_naming([&] { load_scene(dir); }, {dir, "not a regular file", "a folder"}));
  EXPECT_TRUE(input_error_naming([&] { load_obj_mesh(dir); }, {dir, "not a regular file", "a folder"}));
  if (std::filesystem::exists("/dev/zero")) {
    EXPECT_TRUE(input_error_naming([] { load_scene("/dev/zero"); }, {"/dev/zero", "not a regular file", "device"}));
    EXPECT_TRUE(input_error_naming([] { load_obj_mesh("/dev/zero"); }, {"/dev/zero", "not a regular file"}));
    const std::string scene = std::string("{") + kCamera +
        R"(, "materials": {"m": {"type": "diffuse"}},
           "objects": [{"type": "obj", "file": "/dev/zero", "material": "m"}]})";
    EXPECT_TRUE(input_error_naming([&] { parse_scene(scene, "zero.json", dir); },
                                   {"zero.json", "/objects/0/file", "/dev/zero", "not a regular file"}));
  }
}

TEST(FuzzFindings, MtllibOpensNoFile) {
  // tinyobjloader read the material file `mtllib` names: /dev/zero without end. raylab's
  // materials come from the scene, so no material file is opened at all.
  const std::filesystem::path dir = scratch_dir();
  write_text_file(dir / "mtllib.obj", "mtllib /dev/zero\nmtllib missing.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl x\nf 1 2 3\n");
  const TriangleMesh mesh = load_obj_mesh((dir / "mtllib.obj").string());
  EXPECT_EQ(mesh.triangle_count(), 1u);
}

}  // namespace
}  // namespace raylab
