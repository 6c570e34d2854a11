// The remote stage library: every stage function (framework/include/raylab/stages/*.h) and the
// suites' bulk calls (stage_calls.h), defined as a request to the stage server of the current
// stage (stage_session.h). The judge links this instead of stage code, so the suites call the
// stage functions by their usual names, and every value they judge is a value the judge itself
// received, checked and compared.
#include "protocol.h"
#include "stage_calls.h"
#include "stage_session.h"
#include "support.h"

#include "raylab/stages/01_camera_rays.h"
#include "raylab/stages/02_sphere.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/stages/03b_watertight.h"
#include "raylab/stages/04_box.h"
#include "raylab/stages/05_bvh.h"
#include "raylab/stages/07_sampling.h"
#include "raylab/stages/08_direct_light.h"
#include "raylab/stages/09_path.h"

#include <cstring>

namespace raylab {
namespace {

using grading::StageSession;
using grading::protocol::Function;
using grading::protocol::Reader;
using grading::protocol::Writer;

template <class Result>
Result call_returning(Function function, const Writer& arguments) {
  const std::string reply = StageSession::instance().call(function, arguments);
  Reader in(reply);
  in.get<std::uint8_t>();
  const Result result = in.get<Result>();
  in.expect_end();
  return result;
}

template <class Result>
std::optional<Result> call_returning_optional(Function function, const Writer& arguments) {
  const std::string reply = StageSession::instance().call(function, arguments);
  Reader in(reply);
  in.get<std::uint8_t>();
  const std::optional<Result> result = in.get_optional<Result>();
  in.expect_end();
  return result;
}

Bvh call_builder(Function function, const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  Writer arguments;
  arguments.put_vector(primitive_bounds);
  arguments.put(max_leaf_size);
  const std::string reply = StageSession::instance().call(function, arguments);
  Reader in(reply);
  in.get<std::uint8_t>();
  Bvh bvh;
  bvh.nodes = in.get_vector<BvhNode, BvhNodeAllocator<BvhNode>>();
  bvh.primitive_order = in.get_vector<std::uint32_t>();
  in.expect_end();
  return bvh;
}

template <class T, class Allocator>
bool same_bytes(const std::vector<T, Allocator>& a, const std::vector<T, Allocator>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// What the current stage server holds from earlier intersect_bvh requests.
struct SentToServer {
  unsigned generation = 0;
  Bvh bvh;
  std::vector<grading::protocol::Triangle> triangles;
  bool has_bvh = false, has_triangles = false;
};

}  // namespace

Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  Writer arguments;
  arguments.put(camera);
  arguments.put(pixel_x);
  arguments.put(pixel_y);
  arguments.put(position_in_pixel);
  return call_returning<Ray>(Function::GenerateCameraRay, arguments);
}

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  Writer arguments;
  arguments.put(ray);
  arguments.put(sphere_center);
  arguments.put(sphere_radius);
  return call_returning_optional<float>(Function::IntersectRaySphere, arguments);
}

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2) {
  Writer arguments;
  arguments.put(ray);
  arguments.put(p0);
  arguments.put(p1);
  arguments.put(p2);
  return call_returning_optional<TriangleHit>(Function::IntersectRayTriangle, arguments);
}

std::optional<TriangleHit> intersect_ray_triangle_watertight(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                             const glm::vec3& p2) {
  Writer arguments;
  arguments.put(ray);
  arguments.put(p0);
  arguments.put(p1);
  arguments.put(p2);
  return call_returning_optional<TriangleHit>(Function::IntersectRayTriangleWatertight, arguments);
}

std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bounds3& box) {
  Writer arguments;
  arguments.put(ray);
  arguments.put(ray_direction_inverse);
  arguments.put(box);
  return call_returning_optional<float>(Function::IntersectRayBox, arguments);
}

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  return call_builder(Function::BuildBvh, primitive_bounds, max_leaf_size);
}

Bvh build_bvh_sah(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  return call_builder(Function::BuildBvhSah, primitive_bounds, max_leaf_size);
}

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats) {
  static SentToServer sent;
  StageSession& session = StageSession::instance();
  // A server that is not running yet starts fresh in the call below, holding nothing.
  if (!session.server_running() || sent.generation != session.server_generation()) sent = SentToServer{};
  // The tree and the mesh go to the server only when they differ from what it holds (a fresh
  // server starts during the call when the generation changes, and then holds nothing).
  Writer arguments;
  const bool send_bvh = !sent.has_bvh || !same_bytes(sent.bvh.nodes, bvh.nodes) ||
                        !same_bytes(sent.bvh.primitive_order, bvh.primitive_order);
  arguments.put<std::uint8_t>(send_bvh);
  if (send_bvh) {
    arguments.put_vector(bvh.nodes);
    arguments.put_vector(bvh.primitive_order);
  }
  // The grader's own triangle test runs in the server on a copy of the mesh (a round trip per
  // primitive would make a traversal that tests every triangle take minutes); any other
  // intersector is called back here, in the judge.
  const bool grader_test = intersector.test == &grading::grader_triangle_test;
  const auto* triangles = static_cast<const std::vector<grading::protocol::Triangle>*>(intersector.context);
  std::uint8_t mode = 0;
  if (grader_test) mode = sent.has_triangles && same_bytes(sent.triangles, *triangles) ? 1 : 2;
  arguments.put(mode);
  if (mode == 2) arguments.put_vector(*triangles);
  arguments.put(ray);
  arguments.put<std::uint8_t>(any_hit);

  std::uint64_t judged_tests = 0;
  const std::string reply = session.call(Function::IntersectBvh, arguments, [&](Reader& request, Writer& answer) {
    const Ray asked = request.get<Ray>();
    const auto primitive = request.get<std::uint32_t>();
    request.expect_end();
    ++judged_tests;
    answer.put_optional(intersector.test(intersector.context, asked, primitive));
  });
  sent.generation = session.server_generation();
  if (send_bvh) {
    sent.bvh = bvh;
    sent.has_bvh = true;
  }
  if (mode == 2) {
    sent.triangles = *triangles;
    sent.has_triangles = true;
  }
  Reader in(reply);
  in.get<std::uint8_t>();
  const std::optional<BvhHit> hit = in.get_optional<BvhHit>();
  const auto nodes_visited = in.get<std::uint64_t>();
  const auto primitives_tested = in.get<std::uint64_t>();
  in.expect_end();
  stats.nodes_visited += nodes_visited;
  stats.primitives_tested += grader_test ? primitives_tested : judged_tests;
  return hit;
}

// Stage 07: each function is a batch of one.
glm::vec3 sample_uniform_hemisphere(glm::vec2 uniform_random) {
  return grading::warp_samples(grading::Warp::UniformHemisphere, {uniform_random})[0];
}
float uniform_hemisphere_pdf(const glm::vec3& direction) {
  return grading::warp_pdfs(grading::Warp::UniformHemisphere, {direction})[0];
}
glm::vec3 sample_cosine_hemisphere(glm::vec2 uniform_random) {
  return grading::warp_samples(grading::Warp::CosineHemisphere, {uniform_random})[0];
}
float cosine_hemisphere_pdf(const glm::vec3& direction) {
  return grading::warp_pdfs(grading::Warp::CosineHemisphere, {direction})[0];
}
glm::vec3 sample_uniform_sphere(glm::vec2 uniform_random) {
  return grading::warp_samples(grading::Warp::UniformSphere, {uniform_random})[0];
}
float uniform_sphere_pdf(const glm::vec3& direction) {
  return grading::warp_pdfs(grading::Warp::UniformSphere, {direction})[0];
}
glm::vec2 sample_uniform_disk(glm::vec2 uniform_random) {
  return glm::vec2(grading::warp_samples(grading::Warp::UniformDisk, {uniform_random})[0]);
}
float uniform_disk_pdf(glm::vec2 point) {
  return grading::warp_pdfs(grading::Warp::UniformDisk, {glm::vec3(point, 0.0f)})[0];
}
Barycentrics sample_uniform_triangle(glm::vec2 uniform_random) {
  const glm::vec3 b = grading::warp_samples(grading::Warp::UniformTriangle, {uniform_random})[0];
  return Barycentrics{b.x, b.y};
}
float uniform_triangle_pdf(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  return grading::warp_pdfs(grading::Warp::UniformTriangle, {p0, p1, p2})[0];
}

// Stage 08: the radiometry functions one call each; the estimator only in bulk, in a test scene
// the server builds (grading::direct_light_samples), since a RenderContext cannot be sent.
glm::vec3 point_light_intensity(const glm::vec3& power) {
  Writer arguments;
  arguments.put(power);
  return call_returning<glm::vec3>(Function::PointLightIntensity, arguments);
}
glm::vec3 point_light_irradiance(const glm::vec3& intensity, const glm::vec3& light_position, const glm::vec3& point,
                                 const glm::vec3& normal) {
  Writer arguments;
  arguments.put(intensity);
  arguments.put(light_position);
  arguments.put(point);
  arguments.put(normal);
  return call_returning<glm::vec3>(Function::PointLightIrradiance, arguments);
}
glm::vec3 lambertian_f(const glm::vec3& albedo) {
  Writer arguments;
  arguments.put(albedo);
  return call_returning<glm::vec3>(Function::LambertianF, arguments);
}
float area_pdf_to_solid_angle(float pdf_area, float distance, float cos_at_light) {
  Writer arguments;
  arguments.put(pdf_area);
  arguments.put(distance);
  arguments.put(cos_at_light);
  return call_returning<float>(Function::AreaPdfToSolidAngle, arguments);
}
glm::vec3 estimate_direct_light(const RenderContext&, const SurfaceHit&, const Bsdf&, const glm::vec3&, Sampler&) {
  throw std::logic_error("the judge calls estimate_direct_light only through grading::direct_light_samples");
}
// Stage 09: only whole pictures (grading::path_render).
glm::vec3 path_radiance(const RenderContext&, const Ray&, Sampler&) {
  throw std::logic_error("the judge calls path_radiance only through grading::path_render");
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
  const std::string reply = StageSession::instance().call(Function::DirectLightSamples, arguments);
  Reader in(reply);
  in.get<std::uint8_t>();
  auto samples = in.get_vector<glm::vec3>();
  in.expect_end();
  std::size_t expected = 0;
  for (const DirectLightQuery& query : queries) expected += query.sample_count;
  if (samples.size() != expected) throw protocol::ProtocolError("an answer for the wrong number of samples");
  return samples;
}

PathRenderResult path_render(const std::string& scene_path, const PathRenderRequest& request) {
  Writer arguments;
  arguments.put_string(scene_path);
  arguments.put(request);
  const std::string reply = StageSession::instance().call(Function::PathRender, arguments);
  Reader in(reply);
  in.get<std::uint8_t>();
  const int width = in.get<int>(), height = in.get<int>();
  const auto mean = in.get_vector<glm::vec3>();
  const auto variance = in.get_vector<glm::vec3>();
  in.expect_end();
  const int expected_width = request.probe_only ? 1 : request.width, expected_height = request.probe_only ? 1 : request.height;
  const std::size_t pixels = static_cast<std::size_t>(expected_width) * static_cast<std::size_t>(expected_height);
  if (width != expected_width || height != expected_height || mean.size() != pixels || variance.size() != pixels)
    throw protocol::ProtocolError("a picture of the wrong size");
  PathRenderResult result{Image(width, height), Image(width, height)};
  std::memcpy(result.mean.data(), mean.data(), pixels * sizeof(glm::vec3));
  std::memcpy(result.variance_of_mean.data(), variance.data(), pixels * sizeof(glm::vec3));
  return result;
}

std::vector<glm::vec3> warp_samples(Warp warp, const std::vector<glm::vec2>& uniform_randoms) {
  Writer arguments;
  arguments.put(warp);
  arguments.put_vector(uniform_randoms);
  const std::string reply = StageSession::instance().call(protocol::Function::WarpSamples, arguments);
  Reader in(reply);
  in.get<std::uint8_t>();
  auto samples = in.get_vector<glm::vec3>();
  in.expect_end();
  if (samples.size() != uniform_randoms.size()) throw protocol::ProtocolError("an answer for the wrong number of samples");
  return samples;
}

std::vector<float> warp_pdfs(Warp warp, const std::vector<glm::vec3>& arguments_in) {
  Writer arguments;
  arguments.put(warp);
  arguments.put_vector(arguments_in);
  const std::string reply = StageSession::instance().call(protocol::Function::WarpPdfs, arguments);
  Reader in(reply);
  in.get<std::uint8_t>();
  auto values = in.get_vector<float>();
  in.expect_end();
  const std::size_t expected = warp == Warp::UniformTriangle ? arguments_in.size() / 3 : arguments_in.size();
  if (values.size() != expected) throw protocol::ProtocolError("an answer for the wrong number of densities");
  return values;
}

std::vector<std::vector<std::uint32_t>> triangles_hit(TriangleFunction function,
                                                      const std::vector<protocol::Triangle>& triangles,
                                                      const std::vector<Ray>& rays,
                                                      const std::vector<std::vector<std::uint32_t>>& candidates) {
  const bool watertight = function == &intersect_ray_triangle_watertight;
  if (!watertight && function != &intersect_ray_triangle)
    throw std::invalid_argument("triangles_hit: only the stage functions can be called in the stage server");
  if (!candidates.empty() && candidates.size() != rays.size())
    throw std::invalid_argument("triangles_hit: one candidate list per ray");
  Writer arguments;
  arguments.put<std::uint8_t>(watertight);
  arguments.put_vector(triangles);
  arguments.put_vector(rays);
  protocol::put_lists(arguments, candidates);
  const std::string reply = StageSession::instance().call(Function::TrianglesHit, arguments);
  Reader in(reply);
  in.get<std::uint8_t>();
  auto hits = protocol::get_lists(in);
  in.expect_end();
  if (hits.size() != rays.size()) throw protocol::ProtocolError("an answer for the wrong number of rays");
  for (const auto& list : hits)
    for (std::uint32_t t : list)
      if (t >= triangles.size()) throw protocol::ProtocolError("a triangle index out of range");
  return hits;
}

Image render_stage_image(const std::string& stage_id) {
  Writer arguments;
  arguments.put_string(stage_id);
  const std::string reply = StageSession::instance().call(Function::RenderStageImage, arguments);
  Reader in(reply);
  in.get<std::uint8_t>();
  const int width = in.get<int>(), height = in.get<int>();
  const auto pixels = in.get_vector<glm::vec3>();
  in.expect_end();
  if (width != kImageWidth || height != kImageHeight ||
      pixels.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    throw protocol::ProtocolError("a picture of the wrong size");
  Image image(width, height);
  std::memcpy(image.data(), pixels.data(), pixels.size() * sizeof(glm::vec3));
  return image;
}

}  // namespace grading
}  // namespace raylab
