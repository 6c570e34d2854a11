// A ray: the points origin + t * direction for t in the open interval (t_min, t_max).
#pragma once

#include "raylab/math.h"

#include <ostream>

namespace raylab {

struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  // not necessarily unit length
  float t_min = 0.0f;                       // hits must have t_min < t < t_max
  float t_max = kInfinity;

  glm::vec3 at(float t) const { return origin + t * direction; }
};

// A ray from its parts: make_ray(origin, direction) is the whole line ahead, t in (0, inf).
inline Ray make_ray(const glm::vec3& origin, const glm::vec3& direction, float t_min = 0.0f,
                    float t_max = kInfinity) {
  Ray ray;
  ray.origin = origin;
  ray.direction = direction;
  ray.t_min = t_min;
  ray.t_max = t_max;
  return ray;
}

std::ostream& operator<<(std::ostream& out, const Ray& ray);

}  // namespace raylab
