// Hostile: every triangle test writes the start of a reply frame into the grader's reply pipe
// (descriptor 4: a frame's 4-byte length, here 100 bytes, then 3 of them) and waits for ever. The
// judge reads every reply within the call's deadline, byte by byte: the call times out, the stage
// loses its remaining tests once, the grader writes results.json and leaves no process.
#include "raylab/stages/03_triangle.h"

#include <unistd.h>

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2) {
  (void)ray; (void)p0; (void)p1; (void)p2;
  const unsigned char start_of_a_frame[] = {100, 0, 0, 0, 2, 0, 0};
  [[maybe_unused]] const ssize_t written = ::write(4, start_of_a_frame, sizeof start_of_a_frame);
  for (;;) ::pause();
}

}  // namespace raylab
