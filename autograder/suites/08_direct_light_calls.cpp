// Stage 08's calls between the judge and the stage server (autograder/runner/stage_call.h): the
// radiometry functions one call each; the estimator only in bulk, in a test scene the server
// builds (direct_light_samples), since a RenderContext cannot be sent.
#include "08_direct_light_calls.h"
#include "grader_geometry.h"
#include "stage_call.h"

#include "raylab/stages/08_direct_light.h"

#include <stdexcept>

namespace raylab {
namespace {

using grading::DirectLightPoint;
using grading::DirectLightQuery;
using grading::DirectLightScene;
using grading::DirectLightSphere;
using grading::DirectLightTriangle;
using grading::protocol::Reader;
using grading::protocol::Writer;

constexpr grading::StageCall kPointLightIntensity{"point_light_intensity", "point_light_intensity"};
constexpr grading::StageCall kPointLightIrradiance{"point_light_irradiance", "point_light_irradiance"};
constexpr grading::StageCall kLambertianF{"lambertian_f", "lambertian_f"};
constexpr grading::StageCall kAreaPdfToSolidAngle{"area_pdf_to_solid_angle", "area_pdf_to_solid_angle"};
constexpr grading::StageCall kDirectLightSamples{"direct_light_samples", "estimate_direct_light"};

}  // namespace

#if RAYLAB_JUDGE
glm::vec3 point_light_intensity(const glm::vec3& power) {
  return grading::call_remote<decltype(point_light_intensity)>(kPointLightIntensity, power);
}
glm::vec3 point_light_irradiance(const glm::vec3& intensity, const glm::vec3& light_position, const glm::vec3& point,
                                 const glm::vec3& normal) {
  return grading::call_remote<decltype(point_light_irradiance)>(kPointLightIrradiance, intensity, light_position, point,
                                                                normal);
}
glm::vec3 lambertian_f(const glm::vec3& albedo) {
  return grading::call_remote<decltype(lambertian_f)>(kLambertianF, albedo);
}
float area_pdf_to_solid_angle(float pdf_area, float distance, float cos_at_light) {
  return grading::call_remote<decltype(area_pdf_to_solid_angle)>(kAreaPdfToSolidAngle, pdf_area, distance, cos_at_light);
}
glm::vec3 estimate_direct_light(const RenderContext&, const SurfaceHit&, const Bsdf&, const glm::vec3&, Sampler&) {
  throw std::logic_error("the judge calls estimate_direct_light only through grading::direct_light_samples");
}

namespace grading {

std::vector<glm::vec3> direct_light_samples(const DirectLightScene& scene, const std::vector<DirectLightQuery>& queries,
                                            std::uint64_t seed) {
  Writer arguments;
  arguments.put_vector(scene.triangles);
  arguments.put_vector(scene.spheres);
  arguments.put_vector(scene.point_lights);
  arguments.put_vector(queries);
  arguments.put(seed);
  std::size_t expected = 0;
  for (const DirectLightQuery& query : queries) expected += query.sample_count;
  return remote(kDirectLightSamples, arguments, [&](Reader& in) {
    auto samples = in.get_vector<glm::vec3>();
    in.expect_end();
    if (samples.size() != expected) throw protocol::ProtocolError(MessageId::protocol_wrong_sample_count);
    return samples;
  }, {}, grading::reply_limit(sizeof(std::uint64_t) + expected * sizeof(glm::vec3)));
}

}  // namespace grading

#else
namespace grading {

std::vector<glm::vec3> direct_light_samples(const DirectLightScene& test_scene, const std::vector<DirectLightQuery>& queries,
                                            std::uint64_t seed) {
  // The test scene: material 0 is the black occluders', then one material per emitter.
  Scene scene;
  scene.materials.push_back(Material{});
  scene.materials[0].kind = MaterialKind::Diffuse;
  scene.materials[0].diffuse_color = glm::vec3(0.0f);
  auto material_of = [&](const glm::vec3& emission) {
    if (emission == glm::vec3(0.0f)) return std::uint32_t{0};
    Material material = scene.materials[0];
    material.emission = emission;
    scene.materials.push_back(material);
    return static_cast<std::uint32_t>(scene.materials.size() - 1);
  };
  for (const DirectLightTriangle& triangle : test_scene.triangles) {
    TriangleMesh mesh;
    mesh.positions = {triangle.p0, triangle.p1, triangle.p2};
    mesh.indices = {0, 1, 2};
    mesh.material = material_of(triangle.emission);
    scene.meshes.push_back(mesh);
  }
  for (const DirectLightSphere& sphere : test_scene.spheres)
    scene.spheres.push_back(Sphere{sphere.center, sphere.radius, material_of(sphere.emission)});
  for (const DirectLightPoint& light : test_scene.point_lights) scene.lights.push_back(PointLight{light.position, light.intensity});
  const SceneGeometry geometry(scene, Acceleration::BruteForce, TriangleTest::MollerTrumbore, grader_tracing());
  const RenderContext context(scene, geometry, 0, Skips{});

  std::vector<glm::vec3> samples;
  Sampler sampler(1, seed);
  int index = 0;
  for (const DirectLightQuery& query : queries) {
    SurfaceHit hit;
    hit.point = query.point;
    // A bound on the point's error keeps shadow rays off the surface it may lie on: a point on a
    // triangle of the scene, computed in float from barycentrics (08_direct_light_test.cpp), is
    // within a few float roundings of its plane, about 1e-7 |p|, well inside this bound.
    hit.point_error = glm::vec3(1e-6f * (1.0f + glm::length(query.point)));
    hit.geometric_normal = query.normal;
    Bsdf bsdf;
    bsdf.kind = BsdfKind::Lambertian;
    bsdf.albedo = query.albedo;
    for (std::uint32_t i = 0; i < query.sample_count; ++i, ++index) {
      sampler.start_pixel_sample(index % 4096, index / 4096, 0);
      samples.push_back(estimate_direct_light(context, hit, bsdf, query.wo, sampler));
    }
  }
  return samples;
}

}  // namespace grading

namespace {

void serve_direct_light_samples(Reader& in, Writer& out) {
  DirectLightScene scene;
  scene.triangles = in.get_vector<DirectLightTriangle>();
  scene.spheres = in.get_vector<DirectLightSphere>();
  scene.point_lights = in.get_vector<DirectLightPoint>();
  const auto queries = in.get_vector<DirectLightQuery>();
  const auto seed = in.get<std::uint64_t>();
  out.put_vector(grading::direct_light_samples(scene, queries, seed));
}

const bool kServed = grading::serve(kPointLightIntensity, grading::call_local<&point_light_intensity>) &&
                     grading::serve(kPointLightIrradiance, grading::call_local<&point_light_irradiance>) &&
                     grading::serve(kLambertianF, grading::call_local<&lambertian_f>) &&
                     grading::serve(kAreaPdfToSolidAngle, grading::call_local<&area_pdf_to_solid_angle>) &&
                     grading::serve(kDirectLightSamples, serve_direct_light_samples);

}  // namespace
#endif

}  // namespace raylab
