// Stage 02's calls between the judge and the stage server (autograder/runner/stage_call.h).
#include "stage_call.h"

#include "raylab/stages/02_sphere.h"

namespace raylab {
namespace {
constexpr grading::StageCall kIntersectRaySphere{"intersect_ray_sphere", "intersect_ray_sphere"};
}  // namespace

#if RAYLAB_JUDGE
std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  return grading::call_remote<decltype(intersect_ray_sphere)>(kIntersectRaySphere, ray, sphere_center, sphere_radius);
}
#else
namespace {
const bool kServed = grading::serve(kIntersectRaySphere, grading::call_local<&intersect_ray_sphere>);
}  // namespace
#endif

}  // namespace raylab
