// Hostile: every triangle test announces a reply of 500 MiB in the grader's reply pipe (descriptor
// 4) and sends the first megabyte of it. The judge knows how long a triangle test's reply can be
// and refuses the frame from its length alone, before reading or allocating it: each call is lost
// as a malformed answer, and the judge's memory stays its own.
#include "raylab/stages/03_triangle.h"

#include <unistd.h>

#include <vector>

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2) {
  (void)ray; (void)p0; (void)p1; (void)p2;
  std::vector<unsigned char> frame(1u << 20, 'x');
  const unsigned length = 500u << 20;
  for (int i = 0; i < 4; ++i) frame[static_cast<std::size_t>(i)] = static_cast<unsigned char>(length >> (8 * i));
  frame[4] = 2;  // a "return" frame
  [[maybe_unused]] const ssize_t written = ::write(4, frame.data(), frame.size());
  for (;;) ::pause();
}

}  // namespace raylab
