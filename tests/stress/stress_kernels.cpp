// The stress suite's tools: see stress_kernels.h.
#include "stress_kernels.h"

#include "raylab/mesh_generator.h"
#include "raylab/stages/03b_watertight.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <sstream>
#include <tuple>
#include <utility>

namespace raylab::stress {

// ---- Error statistics -------------------------------------------------------------------

void ErrorStats::add(double t, long double t_reference) {
  if (!std::isfinite(t)) {
    ++non_finite;
    return;
  }
  const long double scale = std::fabs(t_reference);
  relative_errors.push_back(scale > 0 ? static_cast<double>(std::fabs((long double)t - t_reference) / scale)
                                      : std::fabs(t));
}

double ErrorStats::max() const {
  double m = 0.0;
  for (double e : relative_errors) m = std::max(m, e);
  return m;
}

double ErrorStats::percentile(double p) const {
  if (relative_errors.empty()) return 0.0;
  std::vector<double> sorted = relative_errors;
  std::sort(sorted.begin(), sorted.end());
  const double position = p / 100.0 * static_cast<double>(sorted.size() - 1);
  return sorted[static_cast<std::size_t>(std::ceil(position))];
}

std::string describe(const ErrorStats& stats) {
  char text[200];
  std::snprintf(text, sizeof text, "max %.2e  p99.9 %.2e  median %.2e  wrong %llu/%llu  non-finite %llu",
                stats.max(), stats.percentile(99.9), stats.median(),
                static_cast<unsigned long long>(stats.wrong_decisions),
                static_cast<unsigned long long>(stats.inputs), static_cast<unsigned long long>(stats.non_finite));
  return text;
}

// ---- Ray-sphere -------------------------------------------------------------------------

std::optional<float> sphere_textbook(const Ray& ray, const glm::vec3& center, float radius) {
  const glm::vec3 oc = ray.origin - center;
  const float a = glm::dot(ray.direction, ray.direction);
  const float b = 2.0f * glm::dot(oc, ray.direction);
  const float c = glm::dot(oc, oc) - radius * radius;
  const float discriminant = b * b - 4.0f * a * c;
  if (!(discriminant >= 0.0f) || !(a > 0.0f)) return std::nullopt;
  const float root = std::sqrt(discriminant);
  const float t_near = (-b - root) / (2.0f * a);
  const float t_far = (-b + root) / (2.0f * a);
  if (t_near > ray.t_min && t_near < ray.t_max) return t_near;
  if (t_far > ray.t_min && t_far < ray.t_max) return t_far;
  return std::nullopt;
}

const std::vector<std::string>& sphere_case_sets() {
  static const std::vector<std::string> sets = {"ordinary", "far_tiny", "huge_near", "grazing", "on_surface"};
  return sets;
}

std::vector<SphereCase> sphere_cases(const std::string& set, int count, std::uint64_t seed) {
  Pcg32 random(seed, testkit::stream_of("sphere " + set));
  std::vector<SphereCase> cases;
  cases.reserve(static_cast<std::size_t>(count));
  while (static_cast<int>(cases.size()) < count) {
    SphereCase c;
    c.ray.t_min = 0.0f;
    c.ray.t_max = kInfinity;
    if (set == "ordinary") {
      c.center = random.uniform(-10, 10) * random_unit_vector(random);
      c.radius = random.uniform(0.1f, 5.0f);
      c.ray.origin = glm::vec3(random.uniform(-20, 20), random.uniform(-20, 20), random.uniform(-20, 20));
      const glm::vec3 target = c.center + random.uniform(0, 1.2f) * c.radius * random_unit_vector(random);
      c.ray.direction = (target - c.ray.origin) * random.uniform(0.2f, 5.0f);
    } else if (set == "far_tiny") {
      const float distance = random_log_uniform(random, 1e2f, 1e5f);
      c.center = distance * random_unit_vector(random);
      c.radius = distance * random_log_uniform(random, 1e-4f, 1e-2f);
      c.ray.origin = glm::vec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
      const glm::vec3 target = c.center + random.uniform(0, 1.1f) * c.radius * random_unit_vector(random);
      c.ray.direction = glm::normalize(target - c.ray.origin) * random.uniform(0.5f, 2.0f);
    } else if (set == "huge_near") {
      c.radius = random_log_uniform(random, 1e3f, 1e6f);
      c.center = random.uniform(0, 10) * random_unit_vector(random);
      const glm::vec3 up = random_unit_vector(random);
      const float height = c.radius * random_log_uniform(random, 1e-4f, 1e-1f);
      c.ray.origin = c.center + (c.radius + height) * up;
      c.ray.direction = glm::normalize(-up + random.uniform(0, 0.3f) * random_unit_vector(random));
    } else if (set == "grazing") {
      c.center = random.uniform(-10, 10) * random_unit_vector(random);
      c.radius = random.uniform(0.1f, 5.0f);
      const glm::vec3 away = random_unit_vector(random);
      c.ray.origin = c.center + random.uniform(2, 20) * c.radius * away;
      glm::vec3 side = glm::cross(away, random_unit_vector(random));
      if (glm::length(side) < 1e-3f) continue;
      side = glm::normalize(side);
      const float impact = c.radius * (1.0f - random_log_uniform(random, 1e-6f, 1e-1f));
      c.ray.direction = glm::normalize(c.center + impact * side - c.ray.origin);
    } else if (set == "on_surface") {
      c.center = random.uniform(-10, 10) * random_unit_vector(random);
      c.radius = random.uniform(0.1f, 5.0f);
      const glm::vec3 normal = random_unit_vector(random);
      c.ray.origin = c.center + c.radius * normal;  // rounded: a hair in or out
      glm::vec3 direction = random_unit_vector(random);
      if ((cases.size() % 2 == 0) != (glm::dot(direction, normal) < 0.0f)) direction = -direction;
      c.ray.direction = direction;
      c.ray.t_min = 1e-4f * c.radius;  // the usual epsilon: leaving rays must miss, entering ones find the far side
    } else {
      std::fprintf(stderr, "unknown sphere case set %s\n", set.c_str());
      std::abort();
    }
    if (!is_finite(c.ray.direction) || glm::length(c.ray.direction) == 0.0f) continue;
    cases.push_back(c);
  }
  return cases;
}

// ---- Ray-triangle -----------------------------------------------------------------------

namespace {

// det [a b c] (columns), by Sarrus' rule.
inline float determinant3(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  return a.x * b.y * c.z + b.x * c.y * a.z + c.x * a.y * b.z - c.x * b.y * a.z - a.x * c.y * b.z -
         b.x * a.y * c.z;
}

}  // namespace

std::optional<TriangleHit> triangle_cramer(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                           const glm::vec3& p2) {
  // -t d + b1 e1 + b2 e2 = s: the columns are (-d, e1, e2), the right-hand side s.
  const glm::vec3 minus_d = -ray.direction, e1 = p1 - p0, e2 = p2 - p0, s = ray.origin - p0;
  const float det = determinant3(minus_d, e1, e2);
  if (!(det != 0.0f) || !std::isfinite(det)) return std::nullopt;
  const float t = determinant3(s, e1, e2) / det;
  const float b1 = determinant3(minus_d, s, e2) / det;
  const float b2 = determinant3(minus_d, e1, s) / det;
  if (!(b1 >= 0.0f && b2 >= 0.0f && b1 + b2 <= 1.0f)) return std::nullopt;
  if (!(t > ray.t_min && t < ray.t_max)) return std::nullopt;
  return TriangleHit{t, b1, b2};
}

TriangleReference triangle_reference(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                     const glm::vec3& p2, long double margin) {
  using L = long double;
  auto lv = [](const glm::vec3& v, L out[3]) { out[0] = v.x; out[1] = v.y; out[2] = v.z; };
  L a[3], b[3], c[3], o[3], d[3];
  lv(p0, a), lv(p1, b), lv(p2, c), lv(ray.origin, o), lv(ray.direction, d);
  L e1[3], e2[3], s[3];
  for (int i = 0; i < 3; ++i) e1[i] = b[i] - a[i], e2[i] = c[i] - a[i], s[i] = o[i] - a[i];
  auto cross = [](const L u[3], const L v[3], L out[3]) {
    out[0] = u[1] * v[2] - u[2] * v[1];
    out[1] = u[2] * v[0] - u[0] * v[2];
    out[2] = u[0] * v[1] - u[1] * v[0];
  };
  auto dot = [](const L u[3], const L v[3]) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  L s1[3], s2[3];
  cross(d, e2, s1);
  cross(s, e1, s2);
  const L det = dot(s1, e1);
  TriangleReference result;
  if (det == 0) return result;
  result.parallel = false;
  result.t = dot(s2, e2) / det;
  result.b1 = dot(s1, s) / det;
  result.b2 = dot(s2, d) / det;
  const L b0 = 1 - result.b1 - result.b2;
  const L smallest = std::min({b0, result.b1, result.b2});
  result.inside_clearly = smallest > margin;
  result.outside_clearly = smallest < -margin;
  return result;
}

const std::vector<NamedTriangleKernel>& triangle_kernels() {
  static const std::vector<NamedTriangleKernel> kernels = {
      {"moller_trumbore", &intersect_ray_triangle},
      {"cramer", &triangle_cramer},
      {"watertight", &intersect_ray_triangle_watertight},
  };
  return kernels;
}

const std::vector<std::string>& triangle_case_sets() {
  static const std::vector<std::string> sets = {"ordinary", "near_parallel", "slivers", "large_coords", "degenerate"};
  return sets;
}

std::vector<TriangleCase> triangle_cases(const std::string& set, int count, std::uint64_t seed) {
  Pcg32 random(seed, testkit::stream_of("triangle " + set));
  std::vector<TriangleCase> cases;
  cases.reserve(static_cast<std::size_t>(count));
  auto random_point = [&](float half) {
    return glm::vec3(random.uniform(-half, half), random.uniform(-half, half), random.uniform(-half, half));
  };
  while (static_cast<int>(cases.size()) < count) {
    TriangleCase c;
    c.ray.t_min = 0.0f;
    c.ray.t_max = kInfinity;
    c.p0 = random_point(1), c.p1 = random_point(1), c.p2 = random_point(1);
    float b1 = random.uniform(-0.2f, 1.2f), b2 = random.uniform(-0.2f, 1.2f);
    if (set == "slivers") {
      const glm::vec3 length = random.uniform(1, 3) * random_unit_vector(random);
      glm::vec3 side = glm::cross(length, random_unit_vector(random));
      if (glm::length(side) < 1e-3f) continue;
      side = glm::normalize(side) * glm::length(length) * random_log_uniform(random, 1e-6f, 1e-3f);
      c.p1 = c.p0 + length;
      c.p2 = c.p0 + 0.5f * length + side;
    }
    if (set == "degenerate") {
      if (random_integer(random, 0, 1) == 0) c.p2 = c.p0;                                   // a repeated corner
      else c.p2 = c.p0 + random.uniform(-2, 2) * (c.p1 - c.p0);                     // three on a line
      b1 = random.uniform(0, 1), b2 = random.uniform(0, 1 - b1);
    }
    const glm::vec3 normal = glm::cross(c.p1 - c.p0, c.p2 - c.p0);
    if (set != "degenerate" && glm::length(normal) < 1e-12f) continue;
    const glm::vec3 target = (1.0f - b1 - b2) * c.p0 + b1 * c.p1 + b2 * c.p2;
    if (set == "near_parallel") {
      const glm::vec3 n = glm::normalize(normal);
      glm::vec3 in_plane = glm::cross(n, random_unit_vector(random));
      if (glm::length(in_plane) < 1e-3f) continue;
      in_plane = glm::normalize(in_plane);
      const double angle = random_log_uniform(random, 1e-6f, 1e-2f);
      c.ray.direction = glm::vec3(glm::dvec3(in_plane) * std::cos(angle) + glm::dvec3(n) * std::sin(angle));
      c.ray.origin = target - random.uniform(0.5f, 4.0f) * c.ray.direction;
    } else {
      c.ray.origin = target + random_point(10);
      c.ray.direction = (target - c.ray.origin) * random.uniform(0.2f, 3.0f);
    }
    if (set == "large_coords") {
      const glm::vec3 shift = random_log_uniform(random, 1e4f, 1e6f) * random_unit_vector(random);
      c.p0 += shift, c.p1 += shift, c.p2 += shift, c.ray.origin += shift;
    }
    if (!is_finite(c.ray.direction) || glm::length(c.ray.direction) == 0.0f) continue;
    cases.push_back(c);
  }
  return cases;
}

// ---- Closed meshes ----------------------------------------------------------------------

ClosedMesh make_icosphere(int levels, float radius, const glm::vec3& center) {
  return testkit::closed_icosphere(levels, radius, center);
}

ClosedMesh make_grid_cube(int n, float half_size, const glm::vec3& center) {
  ClosedMesh mesh = testkit::closed_grid_cube(n, half_size, center);
  if (glm::length(center) > 1e3f) mesh.name += "_far";
  return mesh;
}

ClosedMesh make_sliver_bipyramid(int segments, float radius, float height, const glm::vec3& center) {
  ClosedMesh mesh;
  for (int i = 0; i < segments; ++i) {
    const double angle = 2.0 * 3.14159265358979323846 * i / segments;
    mesh.positions.push_back(center + glm::vec3(glm::dvec3(radius * std::cos(angle), radius * std::sin(angle), 0.0)));
  }
  mesh.positions.push_back(center + glm::vec3(0, 0, height));
  mesh.positions.push_back(center - glm::vec3(0, 0, height));
  const auto top = static_cast<std::uint32_t>(segments), bottom = top + 1;
  for (std::uint32_t i = 0; i < top; ++i) {
    const std::uint32_t next = (i + 1) % top;
    mesh.indices.insert(mesh.indices.end(), {i, next, top, next, i, bottom});
  }
  mesh.name = "sliver_bipyramid_" + std::to_string(mesh.indices.size() / 3);
  mesh.inside = center;
  mesh.inside_radius = 0.5f * radius * height / std::sqrt(radius * radius + height * height);
  return mesh;
}

std::vector<ClosedMesh> leak_test_meshes() {
  return {make_icosphere(4, 1.0f, glm::vec3(0.1f, -0.2f, 0.3f)),
          make_grid_cube(12, 1.0f, glm::vec3(0.0f)),
          make_grid_cube(12, 10.0f, glm::vec3(17000.0f, -23000.0f, 31000.0f)),
          make_sliver_bipyramid(2048, 1.0f, 2.0f, glm::vec3(-0.3f, 0.2f, 0.1f))};
}

LeakCount count_leaks(const ClosedMesh& mesh, TriangleKernel kernel, std::uint64_t rays, std::uint64_t seed) {
  Pcg32 random(seed);
  return testkit::count_leaks(mesh, rays, random, testkit::hits_any_triangle_by(mesh, kernel));
}

// ---- Ray-box ----------------------------------------------------------------------------

std::optional<float> box_plain_slab(const Ray& ray, const glm::vec3& inverse, const Bounds3& box) {
  float t_enter = ray.t_min, t_exit = ray.t_max;
  for (int axis = 0; axis < 3; ++axis) {
    const bool negative = inverse[axis] < 0.0f;
    const float entry = ((negative ? box.max[axis] : box.min[axis]) - ray.origin[axis]) * inverse[axis];
    const float exit = ((negative ? box.min[axis] : box.max[axis]) - ray.origin[axis]) * inverse[axis];
    if (entry > t_enter) t_enter = entry;
    if (exit < t_exit) t_exit = exit;
  }
  if (t_enter <= t_exit) return t_enter;
  return std::nullopt;
}

bool full_sweep() {
  const char* value = std::getenv("RAYLAB_STRESS_FULL");
  return value && std::strcmp(value, "0") != 0 && value[0] != '\0';
}

}  // namespace raylab::stress
