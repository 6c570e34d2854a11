// Hostile: the reference triangle test, which first writes a whole, well-formed frame of its own
// into the grader's reply pipe (descriptor 4): a "return" with one byte of payload, too short for
// a triangle test's result. The judge takes that frame as the reply, finds it malformed and loses
// the call: the server is stopped, so the honest reply it writes next is never read as the answer
// to a later call (before, the server stayed, and every later reply answered the call before it).
#include <unistd.h>

#define intersect_ray_triangle honest_intersect_ray_triangle
#include "../../solutions/03_triangle/triangle.cpp"
#undef intersect_ray_triangle

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2);

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2) {
  const unsigned char short_reply[] = {2, 0, 0, 0, 2, 1};  // length 2: kReturn, then one byte
  [[maybe_unused]] const ssize_t written = ::write(4, short_reply, sizeof short_reply);
  return honest_intersect_ray_triangle(ray, p0, p1, p2);
}

}  // namespace raylab
