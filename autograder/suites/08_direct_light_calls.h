// Stage 08's batch call (08_direct_light_calls.cpp): estimate_direct_light in a test scene that
// the stage server builds, since a RenderContext cannot be sent.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace raylab::grading {

// A test scene for estimate_direct_light. Every triangle and sphere emits its radiance from its
// front (a triangle's by winding); a triangle of zero emission is an occluder (black). Plain
// values only: the judge sends them as they are.
struct DirectLightTriangle {
  glm::vec3 p0{0.0f}, p1{0.0f}, p2{0.0f};
  glm::vec3 emission{0.0f};
};
struct DirectLightSphere {
  glm::vec3 center{0.0f};
  float radius = 1.0f;
  glm::vec3 emission{0.0f};
};
struct DirectLightPoint {
  glm::vec3 position{0.0f};
  glm::vec3 intensity{0.0f};
};
struct DirectLightScene {
  std::vector<DirectLightTriangle> triangles;
  std::vector<DirectLightSphere> spheres;
  std::vector<DirectLightPoint> point_lights;
};
// A diffuse surface point (on no surface of the scene, or on one of its triangles, as a hit point
// rounded to float is): where, its unit normal, the unit direction towards the viewer, its albedo,
// and how many independent samples to take there.
struct DirectLightQuery {
  glm::vec3 point{0.0f}, normal{0.0f, 0.0f, 1.0f}, wo{0.0f, 0.0f, 1.0f}, albedo{0.5f};
  std::uint32_t sample_count = 1;
};
// estimate_direct_light's samples, query after query (sample_count of each), each drawn with a
// fresh 1-spp sampler of `seed` (independent numbers).
std::vector<glm::vec3> direct_light_samples(const DirectLightScene& scene, const std::vector<DirectLightQuery>& queries,
                                            std::uint64_t seed);

}  // namespace raylab::grading
