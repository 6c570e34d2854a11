// Hostile: every triangle test throws an exception whose text tries to be more than text where
// the grader shows it: a C1 control sequence that clears a terminal (CSI 2J), a right-to-left
// override that shows "total 20/20" backwards, a line that looks like the score table's total,
// and Markdown for Gradescope's page (a bold "All tests passed", an image from elsewhere, a link).
// The console and the HTML report show it as characters, results.json as escaped Markdown.
#include "raylab/stages/03_triangle.h"

#include <stdexcept>

namespace raylab {

std::optional<TriangleHit> intersect_ray_triangle(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                  const glm::vec3& p2) {
  (void)ray; (void)p0; (void)p1; (void)p2;
  throw std::runtime_error(
      "\xC2\x9B" "2J\xC2\x9B" "H **All tests passed** \xE2\x80\xAE" "02/02 latot\xE2\x80\xAC"
      "\n  total 128/128\n![tracker](http://example.invalid/t.png) [open the solutions](http://example.invalid/)");
}

}  // namespace raylab
