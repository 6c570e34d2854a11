// raylab trace, Whitted's rays after the camera ray (raylab/trace.h): the reflection and
// refraction rays the framework's Whitted shading (whitted.cpp) spawns at each surface your
// geometry hit, and its shadow rays towards the point lights, each answered by your geometry
// (stages 02-05) beside the contract's exact tests. The directions and the shading are the
// framework's; what can differ is what your stages find along them. Where an answer differs, the
// sphere and triangle tests along that ray that differ are listed before it, so that the first
// disagreement names the function.
#include "raylab/trace.h"

#include "trace_text.h"

#include "raylab/shading.h"
#include "raylab/stages/02_sphere.h"
#include "raylab/stages/03_triangle.h"

#include <exception>
#include <string>
#include <vector>

namespace raylab {

using namespace trace_text;

namespace {

// At most this many rays after the camera ray are traced (a glass sphere doubles them at each
// bounce): the first ones, in the order the renderer traces them; and along each ray whose answer
// differs, at most this many of the primitive tests that differ.
constexpr int kMostWhittedRays = 24;
constexpr int kMostDifferingTestsPerRay = 8;

struct WhittedTracer {
  const Scene& scene;
  const TraceSettings& settings;
  const TracingFunctions& contract;
  const SceneGeometry& your_geometry;
  const SceneGeometry& contract_geometry;
  PixelTrace& trace;
  Words words{settings.chinese};
  int rays = 0, surfaces = 0;
  bool cut = false;

  // The sphere and triangle tests along `ray` whose answers differ from the contract's (a stub
  // once, at most kMostDifferingTestsPerRay), as steps of stages 02 and 03.
  void differing_primitive_tests(const Ray& ray, const std::string& at) {
    const auto sphere_test = settings.yours.sphere ? settings.yours.sphere : intersect_ray_sphere;
    const auto triangle_test = settings.yours.triangle ? settings.yours.triangle : intersect_ray_triangle;
    const std::string not_written = words("not written yet", "尚未编写"), colon = words(": ", "：");
    int listed = 0;
    bool stub_listed = false;
    for (std::size_t i = 0; i < scene.spheres.size() && listed < kMostDifferingTestsPerRay && !stub_listed; ++i) {
      const Sphere& sphere = scene.spheres[i];
      bool stub = false;
      const std::optional<std::optional<float>> got = yours([&] { return sphere_test(ray, sphere.center, sphere.radius); }, stub);
      const std::optional<float> expected = contract.sphere(ray, sphere.center, sphere.radius);
      if (!stub && near(*got, expected)) continue;
      ++listed;
      stub_listed = stub;
      trace.steps.emplace_back("02_sphere", "intersect_ray_sphere", at + colon + sphere_call_text(words, sphere, i),
                               stub ? not_written : t_text(words, *got), t_text(words, expected), "", false);
    }
    stub_listed = false;
    for_each_triangle(scene, [&](std::size_t m, std::size_t k, const glm::vec3& p0, const glm::vec3& p1,
                                 const glm::vec3& p2) {
      if (listed >= kMostDifferingTestsPerRay || stub_listed) return;
      bool stub = false;
      const std::optional<std::optional<TriangleHit>> got = yours([&] { return triangle_test(ray, p0, p1, p2); }, stub);
      const std::optional<TriangleHit> expected = contract.triangle(ray, p0, p1, p2);
      if (!stub && near(*got, expected)) return;
      ++listed;
      stub_listed = stub;
      trace.steps.emplace_back("03_triangle", "intersect_ray_triangle",
                               at + colon + triangle_call_text(words, p0, p1, p2, k, mesh_text(scene, m)),
                               stub ? not_written : triangle_hit_text(words, *got), triangle_hit_text(words, expected),
                               "", false);
    });
  }

  // One bounce ray: its closest hit by your geometry and by the contract's; then, along your hit,
  // the surface it reaches.
  void bounce(const Ray& ray, int depth, const std::string& kind_text) {
    if (rays >= kMostWhittedRays) {
      cut = true;
      return;
    }
    ++rays;
    const std::optional<SurfaceHit> hit = your_geometry.intersect(ray);
    const std::optional<SurfaceHit> expected = contract_geometry.intersect(ray);
    const bool agrees = same_closest_hit(hit, expected);
    const std::string at = kind_text + " (" + ray_text(words, ray) + ")";
    if (!agrees) differing_primitive_tests(ray, kind_text);
    // The surface your hit reaches is numbered as the steps after it name it.
    const int reached = surfaces;
    const std::string surface_text = hit ? words(" (surface ", "（表面 ") + std::to_string(reached) + words(")", "）") : "";
    TraceStep step{"", "", at + words(": the closest hit", "：最近交点"), hit_text(words, scene, hit) + surface_text,
                   hit_text(words, scene, expected)};
    step.agrees = agrees;
    if (!agrees) step.note = another_hit_note(words);
    trace.steps.push_back(step);
    trace.segments.push_back({ray.origin, ray.origin + ray.direction * (hit ? hit->t_hit : miss_length(scene)),
                              TraceSegment::Kind::Bounce});
    if (hit) surface(ray, *hit, depth);
  }

  // What the framework's Whitted shading traces at a surface your geometry hit `depth` bounces
  // from the camera (whitted.cpp, without its skips: every ray that may matter).
  void surface(const Ray& ray, const SurfaceHit& hit, int depth) {
    const std::string at = words("surface ", "表面 ") + std::to_string(surfaces++);  // (surface 0: the camera ray's)
    const Material& material = scene.materials[hit.material];
    const glm::vec3 direction = glm::normalize(ray.direction);
    const glm::vec3& normal = hit.geometric_normal;
    const bool may_bounce = depth < settings.max_depth;
    switch (material.kind) {
      case MaterialKind::ReflectiveRefractive: {
        if (!may_bounce) return;
        const float reflectance = fresnel_reflectance(direction, normal, material.index_of_refraction);
        bounce(spawn_ray(hit, glm::normalize(reflect(direction, normal))), depth + 1,
               at + words(": the reflection ray", "：反射光线"));
        if (reflectance < 1.0f)
          bounce(spawn_ray(hit, glm::normalize(refract(direction, normal, material.index_of_refraction))), depth + 1,
                 at + words(": the refraction ray", "：折射光线"));
        return;
      }
      case MaterialKind::Reflective:
      case MaterialKind::Mirror:
      case MaterialKind::Microfacet:
        if (may_bounce)
          bounce(spawn_ray(hit, reflect(direction, normal)), depth + 1, at + words(": the reflection ray", "：反射光线"));
        return;
      case MaterialKind::DiffuseGlossy:
      case MaterialKind::Diffuse:
      default:
        break;
    }
    const glm::vec3 facing_normal = glm::dot(direction, normal) < 0.0f ? normal : -normal;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
      const PointLight& light = scene.lights[i];
      const glm::vec3 light_direction = glm::normalize(light.position - hit.point);
      if (!(glm::dot(light_direction, facing_normal) > 0.0f)) continue;  // no shadow ray needed
      if (rays >= kMostWhittedRays) {
        cut = true;
        return;
      }
      ++rays;
      Ray shadow;
      shadow.origin = offset_ray_origin(hit, light_direction);
      shadow.direction = light.position - shadow.origin;
      shadow.t_max = 1.0f - 1e-4f;
      const bool blocked = your_geometry.occluded(shadow), expected = contract_geometry.occluded(shadow);
      const std::string kind_text = at + words(": the shadow ray towards light ", "：射向光源 ") + std::to_string(i) +
                                    words("", " 的阴影光线");
      if (blocked != expected) differing_primitive_tests(shadow, kind_text);
      TraceStep step{"", "", kind_text + " (" + ray_text(words, shadow) + ", t_max " + text(shadow.t_max) + ")",
                     blocked_text(words, blocked), blocked_text(words, expected)};
      step.agrees = blocked == expected;
      if (!step.agrees) step.note = shadow_answer_note(words);
      trace.steps.push_back(step);
      trace.segments.push_back({shadow.origin, light.position, TraceSegment::Kind::Shadow});
    }
  }
};

}  // namespace

void trace_whitted(const Scene& scene, const Ray& camera_ray, const TracingFunctions& contract, PixelTrace& trace) {
  const TraceSettings& settings = trace.settings;
  const SceneGeometry your_geometry(scene, Acceleration::Bvh, TriangleTest::MollerTrumbore, settings.yours);
  const SceneGeometry contract_geometry(scene, Acceleration::BruteForce, TriangleTest::MollerTrumbore, contract);
  // From the surface your geometry found along the camera ray: the renderer shades that one.
  const std::optional<SurfaceHit> hit = your_geometry.intersect(camera_ray);
  if (!hit) return;
  WhittedTracer tracer{scene, settings, contract, your_geometry, contract_geometry, trace};
  try {
    tracer.surface(camera_ray, *hit, 0);
  } catch (const NotImplemented&) {
    throw;  // a stub: marked at its first call along the camera ray
  } catch (const std::exception& e) {
    // Your geometry threw along a ray after the camera ray: the rays after it are not traced.
    trace.steps.emplace_back("", "",
                             tracer.words("the next ray after the camera ray", "相机光线之后的下一条光线"),
                             tracer.words("threw: ", "抛出了异常：") + e.what(),
                             tracer.words("an answer", "一个回答"),
                             tracer.words("your geometry (stages 02-05) threw; the rays after it are not traced",
                                          "你的几何（阶段 02-05）抛出了异常；之后的光线没有跟踪"),
                             false);
    return;
  }
  if (tracer.cut)
    trace.steps.emplace_back("", "",
                             tracer.words("(the rays after these are not traced: at most " +
                                              std::to_string(kMostWhittedRays) + " after the camera ray)",
                                          "（之后的光线没有跟踪：相机光线之后最多跟踪 " +
                                              std::to_string(kMostWhittedRays) + " 条）"),
                             "", "", "", true);
}

}  // namespace raylab
