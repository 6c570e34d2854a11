// autograder-regenerate: rebuilds autograder/reference/ from the solutions (instructors only;
// built only when solutions/ exists). Deterministic: the same seed gives the same files, so
// CI can check that what is checked in is what the solutions produce.
//
//   autograder-regenerate [--output DIR] [--seed N]
#include "support.h"

#include "raylab/stages/01_camera_rays.h"
#include "raylab/stages/02_sphere.h"
#include "raylab/stages/03_triangle.h"
#include "raylab/stages/04_box.h"
#include "raylab/stages/05_bvh.h"

#include "bvh_support.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <optional>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace {

using namespace raylab;
using namespace raylab::grading;
using nlohmann::json;

void write_json(const std::string& path, const json& value) {
  std::ofstream out(path);
  out << value.dump(1) << "\n";
  if (!out) throw std::runtime_error("cannot write " + path);
  std::cout << "wrote " << path << "\n";
}

json camera_cases(std::uint32_t seed, int count) {
  CaseRandom random(seed);
  json cases = json::array();
  while (static_cast<int>(cases.size()) < count) {
    Camera camera;
    camera.position = random.vec3(-10, 10);
    camera.look_at = camera.position + random.vec3(-1, 1);
    camera.up = random.vec3(-1, 1);
    camera.fov_y_degrees = random.uniform(20, 120);
    camera.width = random.integer(1, 1920);
    camera.height = random.integer(1, 1080);
    try {
      validate_camera(camera);
    } catch (const std::invalid_argument&) {
      continue;
    }
    // Keep cameras whose basis is well conditioned: up far from the view direction.
    const glm::vec3 forward = glm::normalize(camera.look_at - camera.position);
    if (glm::length(glm::cross(forward, glm::normalize(camera.up))) < 0.2f) continue;
    const int x = random.integer(0, camera.width - 1), y = random.integer(0, camera.height - 1);
    cases.push_back({{"id", cases.size()}, {"position", to_json(camera.position)}, {"look_at", to_json(camera.look_at)},
                     {"up", to_json(camera.up)}, {"fov_y_degrees", camera.fov_y_degrees}, {"width", camera.width},
                     {"height", camera.height}, {"pixel_x", x}, {"pixel_y", y},
                     {"direction", to_json(generate_camera_ray(camera, x, y).direction)}});
  }
  return cases;
}

json sphere_cases(std::uint32_t seed, int count) {
  CaseRandom random(seed);
  json cases = json::array();
  while (static_cast<int>(cases.size()) < count) {
    const glm::vec3 center = random.vec3(-10, 10);
    const float radius = random.uniform(0.1f, 5.0f);
    const bool inside = random.uniform(0, 1) < 0.15f;
    const glm::vec3 origin = inside ? center + random.vec3(-0.5f, 0.5f) * radius : random.vec3(-20, 20);
    // Aim near the sphere so that about half the rays hit.
    const glm::vec3 target = center + random.vec3(-1.6f, 1.6f) * radius;
    if (glm::length(target - origin) < 1e-3f) continue;
    const glm::vec3 direction = glm::normalize(target - origin) * random.uniform(0.2f, 5.0f);
    Ray ray;
    ray.origin = origin;
    ray.direction = direction;
    ray.t_min = random.uniform(0, 1) < 0.3f ? random.uniform(0, 2) : 0.0f;
    const bool finite_t_max = random.uniform(0, 1) < 0.3f;
    ray.t_max = finite_t_max ? random.uniform(1, 30) : kInfinity;
    // Leave out cases a correct float implementation may decide either way: near-tangent
    // rays and hits within a hair of t_min or t_max (computed in double).
    const glm::dvec3 o(origin - center), d(direction);
    const double a = glm::dot(d, d), half_b = glm::dot(o, d), c = glm::dot(o, o) - double(radius) * radius;
    const double discriminant = half_b * half_b - a * c;
    if (std::fabs(discriminant) < 1e-3 * a * double(radius) * radius) continue;
    bool ambiguous = false;
    if (discriminant > 0)
      for (double root : {(-half_b - std::sqrt(discriminant)) / a, (-half_b + std::sqrt(discriminant)) / a})
        for (double limit : {double(ray.t_min), double(ray.t_max)})
          if (std::isfinite(limit) && std::fabs(root - limit) < 1e-3 * std::max(1.0, std::fabs(limit))) ambiguous = true;
    if (ambiguous) continue;
    const std::optional<float> t = intersect_ray_sphere(ray, center, radius);
    cases.push_back({{"id", cases.size()}, {"origin", to_json(origin)}, {"direction", to_json(direction)},
                     {"t_min", ray.t_min}, {"t_max", finite_t_max ? json(ray.t_max) : json(nullptr)},
                     {"center", to_json(center)}, {"radius", radius}, {"t_hit", t ? json(*t) : json(nullptr)}});
  }
  return cases;
}

json triangle_cases(std::uint32_t seed, int count) {
  CaseRandom random(seed);
  json cases = json::array();
  while (static_cast<int>(cases.size()) < count) {
    const glm::vec3 p0 = random.vec3(-5, 5), p1 = random.vec3(-5, 5), p2 = random.vec3(-5, 5);
    const glm::vec3 normal = glm::cross(p1 - p0, p2 - p0);
    if (glm::length(normal) < 0.5f) continue;  // keep triangles with a clear area
    // Aim at a point with barycentrics in [-0.3, 1.3]: about half inside.
    const float b1 = random.uniform(-0.3f, 1.3f), b2 = random.uniform(-0.3f, 1.3f);
    const float b0 = 1.0f - b1 - b2;
    const float margin = 1e-3f;
    if (std::fabs(b1) < margin || std::fabs(b2) < margin || std::fabs(b0) < margin) continue;  // on an edge: either answer
    const glm::vec3 target = b0 * p0 + b1 * p1 + b2 * p2;
    const glm::vec3 origin = target + random.vec3(-8, 8);
    const glm::vec3 direction = (target - origin) * random.uniform(0.2f, 3.0f);
    if (std::fabs(glm::dot(glm::normalize(direction), glm::normalize(normal))) < 0.05f) continue;  // near-parallel
    Ray ray;
    ray.origin = origin;
    ray.direction = direction;
    ray.t_min = 0.0f;
    const bool finite_t_max = random.uniform(0, 1) < 0.3f;
    // t of the target is 1 / scale; keep t_max away from it.
    const float t_target = glm::length(target - origin) / glm::length(direction);
    ray.t_max = finite_t_max ? t_target * (random.uniform(0, 1) < 0.5f ? 0.7f : 1.3f) : kInfinity;
    const std::optional<TriangleHit> hit = intersect_ray_triangle(ray, p0, p1, p2);
    cases.push_back({{"id", cases.size()}, {"origin", to_json(origin)}, {"direction", to_json(direction)},
                     {"t_min", ray.t_min}, {"t_max", finite_t_max ? json(ray.t_max) : json(nullptr)},
                     {"p0", to_json(p0)}, {"p1", to_json(p1)}, {"p2", to_json(p2)},
                     {"hit", hit ? json::array({hit->t_hit, hit->barycentric_b1, hit->barycentric_b2}) : json(nullptr)}});
  }
  return cases;
}

json box_cases(std::uint32_t seed, int count) {
  CaseRandom random(seed);
  json cases = json::array();
  while (static_cast<int>(cases.size()) < count) {
    const glm::vec3 corner = random.vec3(-10, 10);
    glm::vec3 size = random.vec3(0, 5);
    if (random.uniform(0, 1) < 0.15f) size[random.integer(0, 2)] = 0.0f;  // flat boxes
    const Bounds3 box{corner, corner + size};
    const bool inside = random.uniform(0, 1) < 0.15f;
    Ray ray;
    ray.origin = inside ? box.min + glm::vec3(random.uniform(0, 1), random.uniform(0, 1), random.uniform(0, 1)) * size
                        : random.vec3(-20, 20);
    const glm::vec3 target = box.min + random.vec3(-0.5f, 1.5f) * size + random.vec3(-1, 1);
    if (glm::length(target - ray.origin) < 1e-3f) continue;
    ray.direction = glm::normalize(target - ray.origin) * random.uniform(0.2f, 5.0f);
    if (random.uniform(0, 1) < 0.2f) ray.direction[random.integer(0, 2)] = random.integer(0, 1) ? 0.0f : -0.0f;
    if (glm::length(ray.direction) == 0.0f) continue;
    ray.t_min = random.uniform(0, 1) < 0.3f ? random.uniform(0, 3) : 0.0f;
    const bool finite_t_max = random.uniform(0, 1) < 0.3f;
    ray.t_max = finite_t_max ? random.uniform(1, 30) : kInfinity;
    // Leave out cases a correct float implementation may decide either way (in double): a
    // slab interval that almost closes, or an entry or exit within a hair of t_min or t_max.
    double enter = ray.t_min, exit = ray.t_max;
    bool degenerate = false;
    for (int axis = 0; axis < 3; ++axis) {
      const double o = ray.origin[axis], d = ray.direction[axis], lo = box.min[axis], hi = box.max[axis];
      if (d == 0.0) {
        if (std::fabs(o - lo) < 1e-4 || std::fabs(o - hi) < 1e-4) degenerate = true;
        if (o < lo || o > hi) exit = -1.0;  // misses the slab
        continue;
      }
      double t0 = (lo - o) / d, t1 = (hi - o) / d;
      if (t0 > t1) std::swap(t0, t1);
      enter = std::max(enter, t0);
      exit = std::min(exit, t1);
    }
    const double gap = exit - enter;
    if (degenerate || (std::isfinite(gap) && std::fabs(gap) < 1e-3 * std::max(1.0, std::fabs(enter)))) continue;
    if (std::fabs(enter - ray.t_min) < 1e-4 && enter != ray.t_min) continue;
    const std::optional<float> t = intersect_ray_box(ray, ray_direction_inverse_of(ray), box);
    cases.push_back({{"id", cases.size()}, {"origin", to_json(ray.origin)}, {"direction", to_json(ray.direction)},
                     {"t_min", ray.t_min}, {"t_max", finite_t_max ? json(ray.t_max) : json(nullptr)},
                     {"min", to_json(box.min)}, {"max", to_json(box.max)}, {"t_enter", t ? json(*t) : json(nullptr)}});
  }
  return cases;
}

// Stage 06_robustness: spheres that the textbook quadratic gets wrong, with the EXACT answer
// for the float inputs (long double), not the reference's float one. Two kinds:
//   far_tiny   spheres 100 to 100,000 away, radius 1e-4 to 1e-2 of that (b^2 - 4ac cancels)
//   huge_near  integer spheres of radius 500 to 4000 seen from within a few units of their
//              surface, where c = |oc|^2 - R^2 is exact in float but -b - sqrt(disc) cancels
std::optional<long double> exact_sphere_hit(const Ray& ray, const glm::vec3& center, float radius, long double* margin) {
  using L = long double;
  L o[3], d[3];
  for (int i = 0; i < 3; ++i) o[i] = L(ray.origin[i]) - L(center[i]), d[i] = ray.direction[i];
  const L a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const L half_b = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
  const L r2 = L(radius) * L(radius);
  const L c = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - r2;
  L perp2 = 0;
  for (int i = 0; i < 3; ++i) perp2 += (o[i] - half_b / a * d[i]) * (o[i] - half_b / a * d[i]);
  *margin = std::fabs(r2 - perp2) / r2;
  if (r2 - perp2 < 0) return std::nullopt;
  const L root = std::sqrt(a * (r2 - perp2));
  const L q = half_b < 0 ? -(half_b - root) : -(half_b + root);
  L t0 = q / a, t1 = c / q;
  if (t0 > t1) std::swap(t0, t1);
  if (t0 > ray.t_min && t0 < ray.t_max) return t0;
  if (t1 > ray.t_min && t1 < ray.t_max) return t1;
  return std::nullopt;
}

json robustness_cases(std::uint32_t seed, int count) {
  CaseRandom random(seed);
  json cases = json::array();
  while (static_cast<int>(cases.size()) < count) {
    const bool far_tiny = cases.size() % 2 == 0;
    Ray ray;
    glm::vec3 center;
    float radius;
    if (far_tiny) {
      const float distance = std::exp(random.uniform(std::log(1e2f), std::log(1e5f)));
      const glm::vec3 axis = glm::normalize(random.vec3(-1, 1));
      center = distance * axis;
      radius = distance * std::exp(random.uniform(std::log(1e-4f), std::log(1e-2f)));
      ray.origin = random.vec3(-1, 1);
      const glm::vec3 target = center + random.uniform(0, 1.1f) * radius * glm::normalize(random.vec3(-1, 1));
      ray.direction = glm::normalize(target - ray.origin) * random.uniform(0.5f, 2.0f);
    } else {
      // Looking along an axis at an integer sphere whose centre is `offset` to the side:
      // the near surface is about offset^2 / (2 radius) away.
      radius = static_cast<float>(random.integer(500, 4000));
      const int axis = random.integer(0, 2), side = (axis + 1 + random.integer(0, 1)) % 3;
      const float sign = random.integer(0, 1) ? 1.0f : -1.0f;
      center = glm::vec3(static_cast<float>(random.integer(-50, 50)), static_cast<float>(random.integer(-50, 50)),
                         static_cast<float>(random.integer(-50, 50)));
      ray.origin = center;
      ray.origin[axis] -= sign * radius;
      ray.origin[side] += static_cast<float>(random.integer(1, 30));
      ray.direction = glm::vec3(0.0f);
      ray.direction[axis] = sign * static_cast<float>(1 << random.integer(0, 3));
    }
    if (!is_finite(ray.direction) || glm::length(ray.direction) == 0.0f) continue;
    long double margin = 0;
    const std::optional<long double> t = exact_sphere_hit(ray, center, radius, &margin);
    if (margin < 1e-3L) continue;  // near-tangent: a correct float kernel may go either way
    cases.push_back({{"id", cases.size()}, {"kind", far_tiny ? "far_tiny" : "huge_near"}, {"origin", to_json(ray.origin)},
                     {"direction", to_json(ray.direction)}, {"center", to_json(center)}, {"radius", radius},
                     {"t_exact", t ? json(static_cast<double>(*t)) : json(nullptr)}});
  }
  return cases;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Regenerate the autograder's reference data from solutions/"};
  std::string output = RAYLAB_REFERENCE_DIR;
  std::uint32_t seed = 2026;
  app.add_option("--output", output, "Folder to write into")->capture_default_str();
  app.add_option("--seed", seed, "Seed of the random cases (a course may grade with its own)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    std::filesystem::create_directories(output);
    // Seeded random cases with the reference's answers, for the stages that take them.
    const struct {
      const char* id;
      json (*generate)(std::uint32_t, int);
      int count;
    } case_stages[] = {{"01_camera_rays", camera_cases, 200}, {"02_sphere", sphere_cases, 400},
                       {"03_triangle", triangle_cases, 400}, {"04_box", box_cases, 400},
                       {"06_robustness", robustness_cases, 400}};
    for (std::size_t i = 0; i < std::size(case_stages); ++i) {
      const std::uint32_t stage_seed = seed + static_cast<std::uint32_t>(i);
      write_json(output + "/" + case_stages[i].id + "_cases.json",
                 {{"stage", case_stages[i].id}, {"seed", stage_seed},
                  {"cases", case_stages[i].generate(stage_seed, case_stages[i].count)}});
    }
    // The BVH stages are compared with brute force live; the SAH bonus needs the reference's costs.
    const TestMesh& bunny = bvh_test_meshes().front();
    write_json(output + "/05_bvh_cases.json",
               {{"stage", "05_bvh"}, {"seed", nullptr},
                {"bunny_median_cost", bvh_sah_cost(build_bvh(bunny.bounds, 4))},
                {"bunny_sah_cost", bvh_sah_cost(build_bvh_sah(bunny.bounds, 4))}});
    // The stage pictures.
    const struct {
      int number;
      const char* id;
    } image_stages[] = {{1, "01_camera_rays"}, {2, "02_sphere"}, {3, "03_triangle"}, {5, "05_bvh"}};
    for (const auto& stage : image_stages) {
      const std::string image_path = output + "/" + reference_image_name(stage.id);
      write_image(render_stage_image(stage.number), image_path);
      std::cout << "wrote " << image_path << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "autograder-regenerate: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
