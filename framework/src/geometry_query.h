// What the files of SceneGeometry share (framework/src/geometry*.cpp), private to them.
#pragma once

#include "raylab/geometry.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace raylab {

// What the primitive tests of one query share (the `void* context` of PrimitiveIntersector).
struct SceneGeometry::Query {
  const SceneGeometry* geometry;
  HitRecord* record;
  bool any_hit;
  const Triangle* mesh_triangles = nullptr;  // the mesh being traversed: its first triangle
  std::uint32_t mesh_first_triangle = 0;     // ... and that triangle's index in triangles_
  // walk_to's query only: its primitive (an index into triangles_ or spheres_; the other kNone),
  // whether its test was called and how many tests were. Never in a render's query.
  struct Watch {
    static constexpr std::uint32_t kNone = 0xffffffffu;
    std::uint32_t triangle = kNone, sphere = kNone;
    bool tested = false;
    std::uint64_t tests = 0;
    // Every test in the order the traversals called them (the first kMostTests): a sphere (an
    // index into spheres_) or a triangle (into triangles_), the t_max of the ray it was given,
    // and the t it hit at.
    struct Test {
      bool is_sphere = false;
      std::uint32_t index = 0;
      float t_max = 0.0f;
      std::optional<float> t;
    };
    static constexpr std::size_t kMostTests = 1u << 16;
    std::vector<Test> order;
    bool dropped = false;  // tests after the first kMostTests were not kept
    void add(bool is_sphere, std::uint32_t index, float t_max, std::optional<float> t) {
      if (order.size() < kMostTests)
        order.push_back({is_sphere, index, t_max, t});
      else
        dropped = true;
    }
  };
  Watch* watch = nullptr;
};

// The trees' work on this thread (SceneGeometry::take_thread_work), added to after each traversal
// and each set of primitives tested one by one.
inline thread_local SceneGeometry::Work thread_tree_work;

// Through the top-level BVH (geometry_bvh_adapters.cpp), or without one, every object in turn
// (geometry_brute_force.cpp). Inline, so that the public queries call either directly.
inline std::optional<float> SceneGeometry::intersect_objects(const Ray& ray, Query& query) const {
  if (!objects_bvh_.nodes.empty()) return intersect_objects_through_bvh(ray, query);
  return intersect_every_object(ray, query);
}

}  // namespace raylab
