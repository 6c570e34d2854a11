// Stage 05d's calls between the judge and the stage server (autograder/runner/stage_call.h): the
// build, whose tree comes back whole (the suite checks every node and every leaf's list), and
// intersect_kdtree, one ray at a time with any intersector (the work test's counting probe, called
// back in the judge per primitive), or many rays at once with the grader's triangle test run in the
// server on a copy of the mesh (intersect_kdtree_each). The tree and the mesh go to the server only
// when they differ from what it holds.
#include "05_bvh_calls.h"
#include "05d_kdtree_calls.h"
#include "grader_geometry.h"
#include "stage_call.h"

namespace raylab {
namespace {

using grading::protocol::Reader;
using grading::protocol::Triangle;
using grading::protocol::Writer;

constexpr grading::StageCall kBuildKdTree{"build_kdtree", "build_kdtree"};
constexpr grading::StageCall kIntersectKdTree{"intersect_kdtree", "intersect_kdtree"};
constexpr grading::StageCall kIntersectKdTreeEach{"intersect_kdtree_each", "intersect_kdtree"};

}  // namespace

#if RAYLAB_JUDGE
namespace {

// What the current stage server holds, for intersect_kdtree and intersect_kdtree_each alike.
grading::SentList<Bounds3> sent_bounds;
grading::SentList<KdNode> sent_nodes;
grading::SentList<std::uint32_t> sent_indices;
grading::SentList<Triangle> sent_triangles;

void put_tree(Writer& arguments, const KdTree& tree) {
  sent_bounds.put(arguments, std::vector<Bounds3>{tree.bounds});
  sent_nodes.put(arguments, tree.nodes);
  sent_indices.put(arguments, tree.primitive_indices);
}
void tree_returned(const KdTree& tree) {
  sent_bounds.returned(std::vector<Bounds3>{tree.bounds});
  sent_nodes.returned(tree.nodes);
  sent_indices.returned(tree.primitive_indices);
}

}  // namespace

KdTree build_kdtree(const std::vector<Bounds3>& primitive_bounds) {
  Writer arguments;
  arguments.put_vector(primitive_bounds);
  return grading::remote(kBuildKdTree, arguments, [](Reader& in) {
    KdTree tree;
    tree.bounds = in.get<Bounds3>();
    tree.nodes = in.get_vector<KdNode>();
    tree.primitive_indices = in.get_vector<std::uint32_t>();
    in.expect_end();
    return tree;
  });
}

std::optional<BvhHit> intersect_kdtree(const KdTree& tree, const Ray& ray, const PrimitiveIntersector& intersector,
                                       bool any_hit, BvhTraversalStats& stats) {
  const bool grader_test = intersector.test == &grading::grader_triangle_test;
  const auto* triangles = static_cast<const std::vector<Triangle>*>(intersector.context);
  Writer arguments;
  put_tree(arguments, tree);
  arguments.put<std::uint8_t>(grader_test);
  if (grader_test) sent_triangles.put(arguments, *triangles);
  arguments.put(ray);
  arguments.put<std::uint8_t>(any_hit);
  const grading::TraversalReply reply = grading::remote(kIntersectKdTree, arguments, grading::read_traversal_reply,
                                                       grading::answer_primitive_tests(intersector));
  tree_returned(tree);
  if (grader_test) sent_triangles.returned(*triangles);
  grading::add_traversal_work(reply, grader_test, stats);
  return reply.hit;
}

std::vector<std::optional<BvhHit>> grading::intersect_kdtree_each(const KdTree& tree,
                                                                  const std::vector<Triangle>& triangles,
                                                                  const std::vector<Ray>& rays, bool any_hit) {
  Writer arguments;
  put_tree(arguments, tree);
  sent_triangles.put(arguments, triangles);
  arguments.put_vector(rays);
  arguments.put<std::uint8_t>(any_hit);
  std::vector<std::optional<BvhHit>> hits = remote(
      kIntersectKdTreeEach, arguments,
      [&](Reader& in) {
        std::vector<std::optional<BvhHit>> read;
        read.reserve(rays.size());
        for (std::size_t r = 0; r < rays.size(); ++r) read.push_back(in.get_optional<BvhHit>());
        in.expect_end();
        return read;
      },
      {}, reply_limit(rays.size() * (1 + sizeof(BvhHit))));
  tree_returned(tree);
  sent_triangles.returned(triangles);
  return hits;
}

#else
namespace {

void serve_build(Reader& in, Writer& out) {
  const auto boxes = in.get_vector<Bounds3>();
  const KdTree tree = build_kdtree(boxes);
  out.put(tree.bounds);
  out.put_vector(tree.nodes);
  out.put_vector(tree.primitive_indices);
}

// What the judge sent for earlier calls.
KdTree tree;
std::vector<Bounds3> tree_bounds;
std::vector<Triangle> triangles;

void receive_tree(Reader& in) {
  grading::receive(in, tree_bounds);
  if (tree_bounds.size() != 1) throw grading::protocol::ProtocolError(grading::MessageId::protocol_wrong_item_count);
  tree.bounds = tree_bounds[0];
  grading::receive(in, tree.nodes);
  grading::receive(in, tree.primitive_indices);
}

std::optional<BvhHit> traverse_kdtree(const Ray& ray, const PrimitiveIntersector& intersector, bool any_hit,
                                      BvhTraversalStats& stats) {
  return intersect_kdtree(tree, ray, intersector, any_hit, stats);
}

void serve_intersect(Reader& in, Writer& out) {
  receive_tree(in);
  const bool grader_test = in.get<std::uint8_t>() != 0;
  if (grader_test) grading::receive(in, triangles);
  const auto ray = in.get<Ray>();
  const bool any_hit = in.get<std::uint8_t>() != 0;
  grading::serve_traversal(out, ray, any_hit, grader_test, triangles, traverse_kdtree);
}

void serve_intersect_each(Reader& in, Writer& out) {
  receive_tree(in);
  grading::receive(in, triangles);
  const auto rays = in.get_vector<Ray>();
  const bool any_hit = in.get<std::uint8_t>() != 0;
  for (const std::optional<BvhHit>& hit : grading::intersect_kdtree_each(tree, triangles, rays, any_hit))
    out.put_optional(hit);
}

const bool kServed = grading::serve(kBuildKdTree, serve_build) && grading::serve(kIntersectKdTree, serve_intersect) &&
                     grading::serve(kIntersectKdTreeEach, serve_intersect_each);

}  // namespace

std::vector<std::optional<BvhHit>> grading::intersect_kdtree_each(const KdTree& kd, const std::vector<Triangle>& mesh,
                                                                  const std::vector<Ray>& rays, bool any_hit) {
  return traverse_each(mesh, rays, any_hit, [&](const Ray& ray, const PrimitiveIntersector& intersector, bool any,
                                                BvhTraversalStats& stats) {
    return intersect_kdtree(kd, ray, intersector, any, stats);
  });
}
#endif

}  // namespace raylab
