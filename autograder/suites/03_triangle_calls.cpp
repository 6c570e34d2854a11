// Stage 03's calls between the judge and the stage server (autograder/runner/stage_call.h).
#include "stage_call.h"

#include "raylab/stages/03_triangle.h"

namespace raylab {
namespace {
constexpr grading::StageCall kIntersectRayTriangle{"intersect_ray_triangle", "intersect_ray_triangle"};
}  // namespace

#if RAYLAB_JUDGE
std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2) {
  return grading::call_remote<decltype(intersect_ray_triangle)>(kIntersectRayTriangle, ray, p0, p1, p2);
}
#else
namespace {
const bool kServed = grading::serve(kIntersectRayTriangle, grading::call_local<&intersect_ray_triangle>);
}  // namespace
#endif

}  // namespace raylab
