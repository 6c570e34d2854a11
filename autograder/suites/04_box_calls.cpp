// Stage 04's calls between the judge and the stage server (autograder/runner/stage_call.h).
#include "stage_call.h"

#include "raylab/stages/04_box.h"

namespace raylab {
namespace {
constexpr grading::StageCall kIntersectRayBox{"intersect_ray_box", "intersect_ray_box"};
}  // namespace

#if RAYLAB_JUDGE
std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse, const Bounds3& box) {
  return grading::call_remote<decltype(intersect_ray_box)>(kIntersectRayBox, ray, ray_direction_inverse, box);
}
#else
namespace {
const bool kServed = grading::serve(kIntersectRayBox, grading::call_local<&intersect_ray_box>);
}  // namespace
#endif

}  // namespace raylab
