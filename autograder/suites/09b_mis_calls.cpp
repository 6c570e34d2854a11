// Stage 09b's calls between the judge and the stage server (autograder/runner/stage_call.h):
// power_heuristic one call each; path_radiance_mis only in bulk, along chosen rays in a test scene
// the server builds (mis_scripted_paths), or in pictures (09_path_calls.cpp: path_render with
// request.mis).
#include "09b_mis_calls.h"
#include "grader_geometry.h"
#include "stage_call.h"

#include "raylab/stages/09b_mis.h"

#include <stdexcept>

namespace raylab {
namespace {

using grading::MisPointLight;
using grading::MisScene;
using grading::MisScriptedPath;
using grading::MisTriangle;
using grading::protocol::Reader;
using grading::protocol::Writer;

constexpr grading::StageCall kPowerHeuristic{"power_heuristic", "power_heuristic"};
constexpr grading::StageCall kMisScriptedPaths{"mis_scripted_paths", "path_radiance_mis"};

}  // namespace

namespace grading {

Scene scene_of(const MisScene& test_scene) {
  Scene scene;
  for (const MisTriangle& triangle : test_scene.triangles) {
    Material material;
    material.kind = MaterialKind::Diffuse;
    material.diffuse_color = triangle.albedo;
    material.emission = triangle.emission;
    scene.materials.push_back(material);
    TriangleMesh mesh;
    mesh.positions = {triangle.p0, triangle.p1, triangle.p2};
    mesh.indices = {0, 1, 2};
    mesh.material = static_cast<std::uint32_t>(scene.materials.size() - 1);
    scene.meshes.push_back(mesh);
  }
  for (const MisPointLight& light : test_scene.point_lights) scene.lights.push_back(PointLight{light.position, light.intensity});
  return scene;
}

}  // namespace grading

#if RAYLAB_JUDGE
float power_heuristic(int count_f, float pdf_f, int count_g, float pdf_g) {
  return grading::call_remote<decltype(power_heuristic)>(kPowerHeuristic, count_f, pdf_f, count_g, pdf_g);
}
glm::vec3 path_radiance_mis(const RenderContext&, const Ray&, Sampler&) {
  throw std::logic_error("the judge calls path_radiance_mis only through grading::mis_scripted_paths and path_render");
}

namespace grading {

std::vector<glm::vec3> mis_scripted_paths(const MisScene& scene, const std::vector<MisScriptedPath>& paths) {
  Writer arguments;
  arguments.put_vector(scene.triangles);
  arguments.put_vector(scene.point_lights);
  arguments.put_vector(paths);
  return remote(kMisScriptedPaths, arguments, [&](Reader& in) {
    auto radiance = in.get_vector<glm::vec3>();
    in.expect_end();
    if (radiance.size() != paths.size()) throw protocol::ProtocolError(MessageId::protocol_wrong_path_count);
    return radiance;
  });
}

}  // namespace grading

#else
namespace grading {

std::vector<glm::vec3> mis_scripted_paths(const MisScene& test_scene, const std::vector<MisScriptedPath>& paths) {
  const Scene scene = scene_of(test_scene);
  const SceneGeometry geometry(scene, Acceleration::BruteForce, TriangleTest::MollerTrumbore, grader_tracing());
  std::vector<glm::vec3> radiance;
  for (const MisScriptedPath& path : paths) {
    const RenderContext context(scene, geometry, path.max_depth, Skips{}, RussianRoulette{});
    Ray ray;
    ray.origin = path.origin;
    ray.direction = path.direction;
    Sampler sampler = Sampler::constant(path.u1, path.u2);
    radiance.push_back(path_radiance_mis(context, ray, sampler));
  }
  return radiance;
}

}  // namespace grading

namespace {

void serve_mis_scripted_paths(Reader& in, Writer& out) {
  MisScene scene;
  scene.triangles = in.get_vector<MisTriangle>();
  scene.point_lights = in.get_vector<MisPointLight>();
  const auto paths = in.get_vector<MisScriptedPath>();
  out.put_vector(grading::mis_scripted_paths(scene, paths));
}

const bool kServed = grading::serve(kPowerHeuristic, grading::call_local<&power_heuristic>) &&
                     grading::serve(kMisScriptedPaths, serve_mis_scripted_paths);

}  // namespace
#endif

}  // namespace raylab
