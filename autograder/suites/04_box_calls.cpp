// Stage 04's calls between the judge and the stage server (autograder/runner/stage_call.h).
#include "04_box_calls.h"
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

std::vector<std::optional<float>> grading::intersect_ray_box_each(const std::vector<BoxTestArguments>& calls) {
  return call_remote_each<decltype(intersect_ray_box)>(kIntersectRayBox, calls);
}
#else
namespace {
const bool kServed = grading::serve(kIntersectRayBox, grading::call_local<&intersect_ray_box>);
}  // namespace

std::vector<std::optional<float>> grading::intersect_ray_box_each(const std::vector<BoxTestArguments>& calls) {
  return call_local_each<&intersect_ray_box>(calls);
}
#endif

}  // namespace raylab
