// Scene files: load_scene on the shipped Whitted scene, and parse_scene on malformed input.
//
// scene_loader.h promises that every mistake in a scene file is an InputError naming the file,
// the JSON path of the mistake (e.g. /objects/0/radius) and what was expected. Each malformed
// case below starts from a valid scene and makes exactly ONE mistake, so the test knows which
// path and which problem the message must name.
#include "raylab/error.h"
#include "raylab/scene_loader.h"

#include "test_helpers.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <exception>
#include <functional>
#include <string>
#include <vector>

namespace raylab {
namespace {

using nlohmann::json;
using testing::scratch_dir;
using testing::source_path;
using testing::write_text_file;

const char* const kSource = "test_scene.json";

// A small valid scene: one material, a sphere (/objects/0) and a one-triangle mesh (/objects/1).
json valid_scene() {
  return json::parse(R"({
    "camera": { "position": [0, 0, 0], "look_at": [0, 0, -1], "up": [0, 1, 0],
                "fov_y_degrees": 60, "width": 32, "height": 24 },
    "background": [0.1, 0.2, 0.3],
    "materials": { "red": { "type": "diffuse_glossy", "diffuse_color": [1, 0, 0] } },
    "objects": [
      { "type": "sphere", "center": [0, 0, -5], "radius": 1, "material": "red" },
      { "type": "mesh", "positions": [[-1, -1, -3], [1, -1, -3], [0, 1, -3]],
        "triangles": [[0, 1, 2]], "material": "red" }
    ],
    "lights": [ { "type": "point", "position": [0, 5, 0], "intensity": 1 } ]
  })");
}

// Runs parse_scene on `text` and checks that it throws an InputError whose message contains
// every one of `fragments` (and the source name, for mistakes in the JSON itself). On failure
// prints the message and the input.
enum class NamesSource { kYes, kNo };
::testing::AssertionResult fails_naming(const std::string& text,
                                        const std::vector<std::string>& fragments,
                                        const std::string& base_directory = ".",
                                        NamesSource names_source = NamesSource::kYes) {
  try {
    const Scene scene = parse_scene(text, kSource, base_directory);
    return ::testing::AssertionFailure() << "parse_scene accepted the scene (" << scene.spheres.size()
                                         << " spheres); expected an InputError.\nscene: " << text;
  } catch (const InputError& e) {
    const std::string message = e.what();
    std::vector<std::string> required = fragments;
    if (names_source == NamesSource::kYes) required.insert(required.begin(), kSource);
    for (const std::string& fragment : required)
      if (message.find(fragment) == std::string::npos)
        return ::testing::AssertionFailure() << "the message does not contain \"" << fragment
                                             << "\".\nmessage: " << message << "\nscene: " << text;
    return ::testing::AssertionSuccess();
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "threw a " << typeid(e).name()
                                         << " instead of InputError: " << e.what()
                                         << "\nscene: " << text;
  }
}

TEST(LoadScene, WhittedSceneHasEverything) {
  const std::string path = source_path("scenes/whitted.json");
  const Scene scene = load_scene(path);
  EXPECT_EQ(scene.source, path);
  EXPECT_EQ(scene.spheres.size(), 2u);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].name, "floor");
  EXPECT_EQ(scene.meshes[0].triangle_count(), 2u);
  EXPECT_EQ(scene.meshes[0].positions.size(), 4u);
  EXPECT_EQ(scene.meshes[0].texcoords.size(), 4u) << "the floor's checkerboard needs texcoords";
  EXPECT_EQ(scene.lights.size(), 2u);
  ASSERT_EQ(scene.materials.size(), 3u);
  EXPECT_EQ(scene.camera.width, 1280);
  EXPECT_EQ(scene.camera.height, 960);
  EXPECT_EQ(scene.camera.fov_y_degrees, 90.0f);
  EXPECT_EQ(scene.max_depth, 5);
  // Objects refer to materials by name; the indices must lead back to the right ones.
  ASSERT_EQ(scene.spheres.size(), 2u);
  ASSERT_LT(scene.spheres[1].material, scene.materials.size());
  const Material& glass = scene.materials[scene.spheres[1].material];
  EXPECT_EQ(glass.name, "glass");
  EXPECT_EQ(glass.kind, MaterialKind::ReflectiveRefractive);
  EXPECT_EQ(glass.index_of_refraction, 1.5f);
  ASSERT_LT(scene.meshes[0].material, scene.materials.size());
  const Material& floor = scene.materials[scene.meshes[0].material];
  EXPECT_EQ(floor.name, "checker_floor");
  EXPECT_TRUE(floor.checkerboard.has_value());
}

TEST(LoadScene, MissingFileNamesThePath) {
  const std::string path = (scratch_dir() / "no_such_scene.json").string();
  try {
    load_scene(path);
    FAIL() << "load_scene(" << path << ") returned instead of throwing InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << "message: " << e.what();
  }
}

TEST(ParseScene, TheValidBaseSceneParses) {
  // Every malformed case below is this scene with one mistake: it must itself be valid.
  const Scene scene = parse_scene(valid_scene().dump(), kSource, ".");
  ASSERT_EQ(scene.spheres.size(), 1u);
  EXPECT_FALSE(scene.spheres[0].faces_inward) << "spheres face outward unless they say otherwise";
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].triangle_count(), 1u);
  EXPECT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.camera.width, 32);
}

TEST(ParseScene, InvalidJsonNamesTheLine) {
  // The stray comma is on line 3: students need the line, not just "syntax error".
  const std::string text = "{\n  \"camera\": {\n    \"width\": 32,,\n  }\n}\n";
  EXPECT_TRUE(fails_naming(text, {"not valid JSON", "line 3"}));
}

// One mistake per case: what it is, how to make it, and what the message must contain.
struct MalformedCase {
  const char* name;
  std::function<void(json&)> make_mistake;
  std::vector<std::string> fragments;
};

void PrintTo(const MalformedCase& c, std::ostream* out) { *out << c.name; }

class MalformedScene : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(MalformedScene, ThrowsInputErrorNamingThePathAndProblem) {
  json scene = valid_scene();
  GetParam().make_mistake(scene);
  EXPECT_TRUE(fails_naming(scene.dump(2), GetParam().fragments)) << "case: " << GetParam().name;
}

const MalformedCase kMalformedCases[] = {
    {"MissingCamera", [](json& s) { s.erase("camera"); }, {"at /:", "missing key 'camera'"}},
    {"MissingObjects", [](json& s) { s.erase("objects"); }, {"missing key 'objects'"}},
    // A typo must not be silently ignored (the sphere would get the default radius).
    {"MisspelledKey", [](json& s) { s["objects"][0]["raduis"] = 2; },
     {"/objects/0/raduis", "unknown key 'raduis'"}},
    {"NegativeRadius", [](json& s) { s["objects"][0]["radius"] = -1; },
     {"/objects/0/radius", "got -1"}},
    {"ZeroRadius", [](json& s) { s["objects"][0]["radius"] = 0; },
     {"/objects/0/radius", "got 0"}},
    {"StringWhereNumber", [](json& s) { s["objects"][0]["radius"] = "2"; },
     {"/objects/0/radius", "expected a number", "string"}},
    {"VectorOfTwo", [](json& s) { s["objects"][0]["center"] = {0, -5}; },
     {"/objects/0/center", "array of 3 numbers"}},
    {"NaNLikeNullInVector", [](json& s) { s["objects"][0]["center"] = {0, nullptr, -5}; },
     {"/objects/0/center/1", "expected a number"}},
    {"TriangleIndexOutOfRange", [](json& s) { s["objects"][1]["triangles"][0] = {0, 1, 3}; },
     {"/objects/1/triangles/0/2", "got 3"}},
    {"TriangleWithTwoIndices", [](json& s) { s["objects"][1]["triangles"][0] = {0, 1}; },
     {"/objects/1/triangles/0", "three vertex indices"}},
    {"TexcoordsCountMismatch", [](json& s) { s["objects"][1]["texcoords"] = {{0, 0}, {1, 0}}; },
     {"/objects/1/texcoords", "one [s, t] per position"}},
    {"UnknownMaterialName", [](json& s) { s["objects"][0]["material"] = "chrome"; },
     {"/objects/0/material", "no material named 'chrome'"}},
    {"UnknownMaterialType", [](json& s) { s["materials"]["red"]["type"] = "metal"; },
     {"/materials/red/type", "unknown material type 'metal'"}},
    {"UnknownObjectType", [](json& s) { s["objects"][0]["type"] = "cube"; },
     {"/objects/0/type", "unknown object type 'cube'"}},
    {"UnknownLightType", [](json& s) { s["lights"][0]["type"] = "spot"; },
     {"/lights/0/type", "unknown light type 'spot'"}},
    {"NegativeColour", [](json& s) { s["background"] = {0.1, -0.2, 0.3}; },
     {"/background", ">= 0"}},
    {"WidthZero", [](json& s) { s["camera"]["width"] = 0; }, {"/camera/width", "got 0"}},
    {"Width100000", [](json& s) { s["camera"]["width"] = 100000; },
     {"/camera/width", "got 100000"}},
    {"FractionalWidth", [](json& s) { s["camera"]["width"] = 32.5; },
     {"/camera/width", "whole number"}},
    {"UpParallelToView", [](json& s) { s["camera"]["up"] = {0, 0, -3}; },
     {"/camera", "parallel"}},
    {"LookAtEqualsPosition", [](json& s) { s["camera"]["look_at"] = {0, 0, 0}; },
     {"/camera", "look_at must differ from position"}},
    {"Fov180", [](json& s) { s["camera"]["fov_y_degrees"] = 180; },
     {"/camera/fov_y_degrees", "got 180"}},
    {"ObjectsNotAnArray", [](json& s) { s["objects"] = json::object(); },
     {"/objects", "expected an array"}},
    // Emission, point-light power and the Monte Carlo materials (lights.h, bsdf.h).
    {"NegativeEmission", [](json& s) { s["materials"]["red"]["emission"] = {1, -2, 0}; },
     {"/materials/red/emission", "emitted radiance components must be >= 0"}},
    {"NegativeGreyEmission", [](json& s) { s["materials"]["red"]["emission"] = -1; },
     {"/materials/red/emission", "emitted radiance must be >= 0"}},
    {"EmissionNotAColour", [](json& s) { s["materials"]["red"]["emission"] = "bright"; },
     {"/materials/red/emission", "expected an array of 3 numbers", "string"}},
    {"IntensityAndPower", [](json& s) { s["lights"][0]["power"] = 10; },
     {"/lights/0", "not both"}},
    {"NeitherIntensityNorPower", [](json& s) { s["lights"][0].erase("intensity"); },
     {"/lights/0", "missing key 'intensity' (W/sr) or 'power' (W)"}},
    {"NegativePower", [](json& s) { s["lights"][0].erase("intensity"); s["lights"][0]["power"] = {1, 1, -1}; },
     {"/lights/0/power", "power components must be >= 0"}},
    {"DiffuseAlbedoAboveOne", [](json& s) { s["materials"]["red"] = {{"type", "diffuse"}, {"diffuse_color", {1.5, 0, 0}}}; },
     {"/materials/red/diffuse_color", "<= 1"}},
    {"DiffuseWithPhongKey", [](json& s) { s["materials"]["red"] = {{"type", "diffuse"}, {"ks", 0.5}}; },
     {"/materials/red/ks", "unknown key 'ks'"}},
    {"SphereFacingUnknown", [](json& s) { s["objects"][0]["facing"] = "in"; },
     {"/objects/0/facing", "unknown facing 'in' (expected outward or inward)"}},
    {"MirrorReflectanceAboveOne", [](json& s) { s["materials"]["red"] = {{"type", "mirror"}, {"reflectance", 2}}; },
     {"/materials/red/reflectance", "<= 1"}},
};

INSTANTIATE_TEST_SUITE_P(OneMistakeEach, MalformedScene, ::testing::ValuesIn(kMalformedCases),
                         [](const ::testing::TestParamInfo<MalformedCase>& param_info) {
                           return std::string(param_info.param.name);
                         });

// --- OBJ meshes -------------------------------------------------------------------------

// A unit quad (two triangles after triangulation) and one more triangle, with texture
// coordinates equal to each vertex's (x, y) so that the pairing can be checked.
const char* const kTinyObj = R"(# a quad and a triangle
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 2 0 1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vt 2 0
f 1/1 2/2 3/3 4/4
f 2/2 5/5 3/3
)";

TEST(LoadObjMesh, TinyValidObjWithTexcoords) {
  const std::filesystem::path path = scratch_dir() / "tiny.obj";
  write_text_file(path, kTinyObj);
  const TriangleMesh mesh = load_obj_mesh(path.string());
  EXPECT_EQ(mesh.triangle_count(), 3u) << path << ": a quad (2 triangles) and a triangle";
  EXPECT_EQ(mesh.positions.size(), 5u) << path << ": vertices shared by the faces are shared";
  ASSERT_EQ(mesh.texcoords.size(), mesh.positions.size()) << "one texcoord per position";
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
    const std::uint32_t v = mesh.indices[i];
    ASSERT_LT(v, mesh.positions.size()) << "index " << i;
    EXPECT_EQ(mesh.texcoords[v], glm::vec2(mesh.positions[v])) << "vertex " << v << " at "
                                                               << mesh.positions[v];
  }
}

TEST(LoadObjMesh, FaceUsingAMissingVertexNamesTheFile) {
  // A face refers to vertex 99 of a file with 3: reading it would be out of bounds.
  const std::filesystem::path path = scratch_dir() / "bad_face.obj";
  write_text_file(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n");
  try {
    const TriangleMesh mesh = load_obj_mesh(path.string());
    FAIL() << "load_obj_mesh(" << path << ") returned " << mesh.triangle_count()
           << " triangles instead of throwing InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path.string()), std::string::npos) << "message: " << message;
    EXPECT_NE(message.find("malformed OBJ"), std::string::npos) << "message: " << message;
  }
}

TEST(ParseScene, ObjObjectWithMissingFile) {
  // The OBJ's own path (resolved against the scene's folder) is what the student must fix.
  const std::filesystem::path dir = scratch_dir();
  json scene = valid_scene();
  scene["objects"].push_back({{"type", "obj"}, {"file", "missing.obj"}, {"material", "red"}});
  EXPECT_TRUE(fails_naming(scene.dump(2), {"cannot open OBJ", (dir / "missing.obj").string()},
                           dir.string(), NamesSource::kNo));
}

TEST(ParseScene, ObjObjectWithMalformedFileNamesTheObjFile) {
  const std::filesystem::path dir = scratch_dir();
  write_text_file(dir / "bad_face.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n");
  json scene = valid_scene();
  scene["objects"].push_back({{"type", "obj"}, {"file", "bad_face.obj"}, {"material", "red"}});
  try {
    parse_scene(scene.dump(2), kSource, dir.string());
    FAIL() << "parse_scene accepted an OBJ face using vertex 99 of 3";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad_face.obj"), std::string::npos)
        << "message: " << e.what();
  }
}

TEST(ParseScene, ObjObjectIsScaledThenTranslatedRelativeToTheSceneFolder) {
  const std::filesystem::path dir = scratch_dir();
  write_text_file(dir / "tiny.obj", kTinyObj);
  json scene = valid_scene();
  scene["objects"].push_back({{"type", "obj"}, {"file", "tiny.obj"}, {"scale", 2},
                              {"translate", {10, 20, 30}}, {"material", "red"}});
  const Scene parsed = parse_scene(scene.dump(2), kSource, dir.string());
  ASSERT_EQ(parsed.meshes.size(), 2u);
  const TriangleMesh& mesh = parsed.meshes[1];
  EXPECT_EQ(mesh.triangle_count(), 3u);
  ASSERT_FALSE(mesh.positions.empty());
  // Each vertex (x, y, z) of the file, with texcoord (x, y), lands at 2 (x, y, z) + (10, 20, 30).
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec2 st = mesh.texcoords.at(v);
    EXPECT_EQ(mesh.positions[v].x, 2.0f * st.x + 10.0f) << "vertex " << v;
    EXPECT_EQ(mesh.positions[v].y, 2.0f * st.y + 20.0f) << "vertex " << v;
  }
}

}  // namespace
}  // namespace raylab
