// Test meshes and a brute-force oracle for the BVH suites (05_bvh, 05b_bvh_sah).
#pragma once

#include "support.h"

#include "raylab/stages/05_bvh.h"

#include <array>
#include <string>
#include <vector>

namespace raylab::grading {

struct TestMesh {
  std::string name;
  std::vector<std::array<glm::vec3, 3>> triangles;
  std::vector<Bounds3> bounds;  // one per triangle, for the builders
};

// The meshes every BVH test runs on: the bunny (scenes/bunny.obj), a seeded triangle soup,
// a flat grid in the plane y = 0 (boxes of zero thickness), and 64 copies of one triangle
// (every centroid equal: the median split must still terminate).
const std::vector<TestMesh>& bvh_test_meshes();

// The grader's own triangle test (double precision), so that BVH grades do not depend on
// your stage 3. A PrimitiveIntersector over a TestMesh.
PrimitiveIntersector intersector_for(const TestMesh& mesh);

// Every triangle, t_max shrinking: the oracle.
std::optional<BvhHit> brute_force_closest(const TestMesh& mesh, const Ray& ray);

// Seeded rays at the mesh: origins on a sphere around it, aimed at points inside its box;
// with axis_aligned, directions along +-x, +-y or +-z (two zero components each).
std::vector<Ray> rays_at(const TestMesh& mesh, int count, std::uint32_t seed, bool axis_aligned = false);

// Primitives below each node (counted through the tree).
std::vector<std::uint32_t> subtree_primitive_counts(const Bvh& bvh);

// Compares intersect_bvh with the oracle on `rays`; reports up to 3 differences with hints.
// Returns the number of rays that differ.
int compare_with_brute_force(const Bvh& bvh, const TestMesh& mesh, const std::vector<Ray>& rays, bool any_hit,
                             const char* what);

}  // namespace raylab::grading
