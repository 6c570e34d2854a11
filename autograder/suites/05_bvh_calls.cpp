// Stages 05 and 05b's calls between the judge and the stage server (autograder/runner/stage_call.h):
// the two builders, whose trees come back whole (the suites check every node), and
// intersect_bvh (one ray, or many with the grader's triangle test: intersect_bvh_each,
// 05_bvh_calls.h). A traversal's primitive tests are either the grader's own triangle test, run in
// the server on a copy of the mesh (a round trip per primitive would make a traversal that tests
// every triangle take minutes), or any other intersector, called back in the judge per primitive.
// The tree and the mesh go to the server only when they differ from what it holds.
#include "05_bvh_calls.h"
#include "grader_geometry.h"
#include "stage_call.h"

#include "raylab/stages/05_bvh.h"

namespace raylab {
namespace {

using grading::protocol::Reader;
using grading::protocol::Triangle;
using grading::protocol::Writer;

constexpr grading::StageCall kBuildBvh{"build_bvh", "build_bvh"};
constexpr grading::StageCall kBuildBvhSah{"build_bvh_sah", "build_bvh_sah"};
constexpr grading::StageCall kIntersectBvh{"intersect_bvh", "intersect_bvh"};
constexpr grading::StageCall kIntersectBvhEach{"intersect_bvh_each", "intersect_bvh"};

}  // namespace

#if RAYLAB_JUDGE
namespace {

Bvh remote_build(const grading::StageCall& call, const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  Writer arguments;
  arguments.put_vector(primitive_bounds);
  arguments.put(max_leaf_size);
  return grading::remote(call, arguments, [](Reader& in) {
    Bvh bvh;
    bvh.nodes = in.get_vector<BvhNode, BvhNodeAllocator<BvhNode>>();
    bvh.primitive_order = in.get_vector<std::uint32_t>();
    return bvh;
  });
}

// What the current stage server holds, for intersect_bvh and intersect_bvh_each alike.
grading::SentList<BvhNode, BvhNodeAllocator<BvhNode>> sent_nodes;
grading::SentList<std::uint32_t> sent_order;
grading::SentList<Triangle> sent_triangles;

}  // namespace

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  return remote_build(kBuildBvh, primitive_bounds, max_leaf_size);
}

Bvh build_bvh_sah(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  return remote_build(kBuildBvhSah, primitive_bounds, max_leaf_size);
}

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats) {
  Writer arguments;
  sent_nodes.put(arguments, bvh.nodes);
  sent_order.put(arguments, bvh.primitive_order);
  const bool grader_test = intersector.test == &grading::grader_triangle_test;
  const auto* triangles = static_cast<const std::vector<Triangle>*>(intersector.context);
  arguments.put<std::uint8_t>(grader_test);
  if (grader_test) sent_triangles.put(arguments, *triangles);
  arguments.put(ray);
  arguments.put<std::uint8_t>(any_hit);

  const grading::TraversalReply reply = grading::remote(kIntersectBvh, arguments, grading::read_traversal_reply,
                                                       grading::answer_primitive_tests(intersector));
  sent_nodes.returned(bvh.nodes);
  sent_order.returned(bvh.primitive_order);
  if (grader_test) sent_triangles.returned(*triangles);
  grading::add_traversal_work(reply, grader_test, stats);
  return reply.hit;
}

grading::TraversalReply grading::read_traversal_reply(Reader& in) {
  TraversalReply read;
  read.hit = in.get_optional<BvhHit>();
  read.nodes_visited = in.get<std::uint64_t>();
  read.reported_tests = in.get<std::uint64_t>();
  read.counted_tests = in.get<std::uint64_t>();
  in.expect_end();
  return read;
}

void grading::add_traversal_work(const TraversalReply& reply, bool grader_test, BvhTraversalStats& stats) {
  stats.nodes_visited += reply.nodes_visited;
  stats.primitives_tested += grader_test ? reply.counted_tests : reply.reported_tests;
}

grading::StageSession::Callback grading::answer_primitive_tests(const PrimitiveIntersector& intersector) {
  return [intersector](Reader& question, Writer& answer) {
    const Ray asked = question.get<Ray>();
    const auto primitive = question.get<std::uint32_t>();
    question.expect_end();
    answer.put_optional(intersector.test(intersector.context, asked, primitive));
  };
}

std::vector<std::optional<BvhHit>> grading::intersect_bvh_each(const Bvh& bvh, const std::vector<Triangle>& triangles,
                                                               const std::vector<Ray>& rays, bool any_hit) {
  Writer arguments;
  sent_nodes.put(arguments, bvh.nodes);
  sent_order.put(arguments, bvh.primitive_order);
  sent_triangles.put(arguments, triangles);
  arguments.put_vector(rays);
  arguments.put<std::uint8_t>(any_hit);
  std::vector<std::optional<BvhHit>> hits = remote(
      kIntersectBvhEach, arguments,
      [&](Reader& in) {
        std::vector<std::optional<BvhHit>> read;
        read.reserve(rays.size());
        for (std::size_t r = 0; r < rays.size(); ++r) read.push_back(in.get_optional<BvhHit>());
        return read;
      },
      {}, reply_limit(rays.size() * (1 + sizeof(BvhHit))));
  sent_nodes.returned(bvh.nodes);
  sent_order.returned(bvh.primitive_order);
  sent_triangles.returned(triangles);
  return hits;
}

#else
std::optional<float> grading::primitive_test_through_judge(void*, const Ray& ray, std::uint32_t primitive) {
  Writer question;
  question.put(ray);
  question.put(primitive);
  const std::string answer = grading::ask_judge(question);
  Reader in(answer);
  return in.get_optional<float>();
}

namespace {

template <Bvh (*builder)(const std::vector<Bounds3>&, int)>
void serve_build(Reader& in, Writer& out) {
  const auto boxes = in.get_vector<Bounds3>();
  const auto max_leaf_size = in.get<int>();
  const Bvh bvh = builder(boxes, max_leaf_size);
  out.put_vector(bvh.nodes);
  out.put_vector(bvh.primitive_order);
}

// What the judge sent for earlier calls of intersect_bvh and intersect_bvh_each.
Bvh bvh;
std::vector<Triangle> triangles;

std::optional<BvhHit> traverse_bvh(const Ray& ray, const PrimitiveIntersector& intersector, bool any_hit,
                                   BvhTraversalStats& stats) {
  return intersect_bvh(bvh, ray, intersector, any_hit, stats);
}

void serve_intersect_bvh(Reader& in, Writer& out) {
  grading::receive(in, bvh.nodes);
  grading::receive(in, bvh.primitive_order);
  const bool grader_test = in.get<std::uint8_t>() != 0;
  if (grader_test) grading::receive(in, triangles);
  const auto ray = in.get<Ray>();
  const bool any_hit = in.get<std::uint8_t>() != 0;
  grading::serve_traversal(out, ray, any_hit, grader_test, triangles, traverse_bvh);
}

void serve_intersect_bvh_each(Reader& in, Writer& out) {
  grading::receive(in, bvh.nodes);
  grading::receive(in, bvh.primitive_order);
  grading::receive(in, triangles);
  const auto rays = in.get_vector<Ray>();
  const bool any_hit = in.get<std::uint8_t>() != 0;
  for (const std::optional<BvhHit>& hit : grading::intersect_bvh_each(bvh, triangles, rays, any_hit)) out.put_optional(hit);
}

const bool kServed = grading::serve(kBuildBvh, serve_build<&build_bvh>) &&
                     grading::serve(kBuildBvhSah, serve_build<&build_bvh_sah>) &&
                     grading::serve(kIntersectBvh, serve_intersect_bvh) &&
                     grading::serve(kIntersectBvhEach, serve_intersect_bvh_each);

}  // namespace

std::vector<std::optional<BvhHit>> grading::intersect_bvh_each(const Bvh& tree, const std::vector<Triangle>& mesh,
                                                               const std::vector<Ray>& rays, bool any_hit) {
  return traverse_each(mesh, rays, any_hit, [&](const Ray& ray, const PrimitiveIntersector& intersector, bool any,
                                                BvhTraversalStats& stats) {
    return intersect_bvh(tree, ray, intersector, any, stats);
  });
}

void grading::serve_traversal(Writer& out, const Ray& ray, bool any_hit, bool grader_test, std::vector<Triangle>& mesh,
                              const Traversal& traverse) {
  CountedTests counting{grader_test ? PrimitiveIntersector{grader_triangle_test, &mesh}
                                    : PrimitiveIntersector{primitive_test_through_judge, nullptr}};
  BvhTraversalStats stats;
  const std::optional<BvhHit> hit = traverse(ray, PrimitiveIntersector{counting_test, &counting}, any_hit, stats);
  out.put_optional(hit);
  out.put<std::uint64_t>(stats.nodes_visited);
  out.put<std::uint64_t>(stats.primitives_tested);
  out.put<std::uint64_t>(counting.tests);
}

std::vector<std::optional<BvhHit>> grading::traverse_each(const std::vector<Triangle>& mesh, const std::vector<Ray>& rays,
                                                          bool any_hit, const Traversal& traverse) {
  const PrimitiveIntersector grader_test{grader_triangle_test, const_cast<std::vector<Triangle>*>(&mesh)};
  std::vector<std::optional<BvhHit>> hits;
  hits.reserve(rays.size());
  for (const Ray& ray : rays) {
    BvhTraversalStats stats;
    hits.push_back(traverse(ray, grader_test, any_hit, stats));
  }
  return hits;
}
#endif

}  // namespace raylab
