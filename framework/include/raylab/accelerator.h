// The seam through which a program hands the renderer a tree of its own over every triangle of
// a scene, in place of the trees the stages build (TracingFunctions::own_tree in
// raylab/geometry.h). The renderer asks it two questions per ray, as pbrt-v4 asks its
// aggregates: the closest hit, and whether there is any hit.
//
// raylab-reference and bench/ give the reference's fastest tree this way
// (solutions/05c_wide_bvh/fast_tree.h); a student's program gives none, and traces the student's
// own stage trees (raylab render --accel).
#pragma once

#include "raylab/ray.h"
#include "raylab/stages/03_triangle.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace raylab {

class TriangleTree {
 public:
  virtual ~TriangleTree() = default;
  // What the render's first line calls it ("the reference's own (SAH, 8 wide)").
  virtual std::string name() const = 0;
  // The closest hit in (ray.t_min, ray.t_max): whether there is one; if so, the index of the
  // triangle hit (as the builder was given them) in `triangle`, and its t and barycentrics in
  // `hit`, as the program's stage 03 test (intersect_ray_triangle) gives them.
  virtual bool closest_hit(const Ray& ray, std::uint32_t& triangle, TriangleHit& hit) const = 0;
  // Whether any triangle is hit in (ray.t_min, ray.t_max): the t of the first hit found (not
  // always the closest: it stops there), or nullopt.
  virtual std::optional<float> any_hit(const Ray& ray) const = 0;
};

// Builds a tree over the triangles whose corners are corners[3 i], corners[3 i + 1] and
// corners[3 i + 2] (triangle i). Never nullptr.
using TriangleTreeBuilder = std::unique_ptr<TriangleTree> (*)(const std::vector<glm::vec3>& corners);

}  // namespace raylab
