// Stage 09b's batch call (09b_mis_calls.cpp): path_radiance_mis along chosen rays, in a test scene
// that the stage server builds (a RenderContext cannot be sent), with a constant sampler
// (Sampler::constant) so that the judge knows which light point and which BSDF direction each path
// takes. (Its pictures go through stage 09's path_render, with request.mis.)
#pragma once

#include "raylab/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace raylab::grading {

// A test scene of Lambertian triangles (two-sided, of diffuse colour `albedo`), each emitting
// `emission` from its front (by winding), and point lights. Plain values: sent as they are.
struct MisTriangle {
  glm::vec3 p0{0.0f}, p1{0.0f}, p2{0.0f};
  glm::vec3 emission{0.0f};
  glm::vec3 albedo{0.0f};
};
struct MisPointLight {
  glm::vec3 position{0.0f};
  glm::vec3 intensity{0.0f};
};
struct MisScene {
  std::vector<MisTriangle> triangles;
  std::vector<MisPointLight> point_lights;
};
// The Scene the stage server renders (and the judge models): material i is triangle i's.
Scene scene_of(const MisScene& test_scene);

// One path: path_radiance_mis along the ray (origin, unit direction), max_depth bounces, no
// Russian roulette, with Sampler::constant(u1, u2): every get_1d() gives u1, every get_2d() u2.
struct MisScriptedPath {
  glm::vec3 origin{0.0f}, direction{0.0f, 0.0f, 1.0f};
  float u1 = 0.5f;
  glm::vec2 u2{0.5f};
  std::int32_t max_depth = 1;
};
// Each path's radiance, in order.
std::vector<glm::vec3> mis_scripted_paths(const MisScene& scene, const std::vector<MisScriptedPath>& paths);

}  // namespace raylab::grading
