// Grader self-test submission (stage 02_sphere): a recursion that never ends, so every call
// overflows the stack (Linux: signal 11; Windows: exception 0xC00000FD, "stack overflow"). The
// stage scores 0 and the report names the crash; the other stages keep their marks.
#include "raylab/stages/02_sphere.h"

namespace raylab {
namespace {
// Each level keeps a page of the stack busy (volatile: the compiler may not fold it away).
// (The stack ends long before the depth that would stop it.)
float deeper(float radius, int depth) {
  if (depth == 1 << 30) return radius;
  volatile char frame[4096];
  frame[depth % 4096] = static_cast<char>(depth);
  return deeper(radius, depth + 1) + static_cast<float>(frame[(depth * 7) % 4096]);
}
}  // namespace

std::optional<float> intersect_ray_sphere(const Ray& ray, const glm::vec3& sphere_center, float sphere_radius) {
  (void)ray;
  (void)sphere_center;
  return deeper(sphere_radius, 0);
}

}  // namespace raylab
