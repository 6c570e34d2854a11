// The grader's own stage 04 (the slab test of raylab/stages/04_box.h, in double precision): the
// stage servers that grade stages 05 and 05b link this instead of yours (stages.json:
// "grader_versions"), so that a mistake in your box test costs points at stage 04 only (and at
// the bonus stage 06_robustness, which grades its rounding), not in your tree's tests.
#include "raylab/stages/04_box.h"

#include <cmath>

namespace raylab {
namespace {

// The part of the ray between the two planes of one axis narrows [enter, exit]. The distances
// are computed in double, where a difference of two floats and its product with a float are
// exact to 2^-53; the exit is widened by far more than that, so a ray touching the box is kept.
// 0 * infinity (the origin on a plane, the ray parallel to it) is NaN, which no comparison
// accepts: the interval stays as it was, and a ray lying in a face is a hit.
void clip(float origin, float inverse, float low, float high, double& enter, double& exit) {
  const bool negative = std::signbit(inverse);
  const double entry = (double(negative ? high : low) - double(origin)) * double(inverse);
  const double leave = (double(negative ? low : high) - double(origin)) * double(inverse) * (1.0 + 1e-12);
  if (entry > enter) enter = entry;
  if (leave < exit) exit = leave;
}

}  // namespace

std::optional<float> intersect_ray_box(const Ray& ray, const glm::vec3& ray_direction_inverse,
                                       const Bounds3& box) {
  double enter = ray.t_min, exit = ray.t_max;
  for (int axis = 0; axis < 3; ++axis)
    clip(ray.origin[axis], ray_direction_inverse[axis], box.min[axis], box.max[axis], enter, exit);
  if (!(enter <= exit)) return std::nullopt;
  return static_cast<float>(enter);
}

}  // namespace raylab
