// Stage 05c's calls between the judge and the stage server (autograder/runner/stage_call.h): the
// collapse, whose tree comes back whole (the suite checks every node), the four-box test in bulk,
// and intersect_bvh4, whose primitive tests are either the grader's own triangle test run in the
// server on a copy of the mesh, or any other intersector (the work test's counting probe), called
// back in the judge per primitive (05_bvh_calls.h). The tree and the mesh go to the server only
// when they differ from what it holds.
#include "05_bvh_calls.h"
#include "05c_wide_bvh_calls.h"
#include "grader_geometry.h"
#include "stage_call.h"

#include <stdexcept>

namespace raylab {
namespace {

using grading::protocol::Reader;
using grading::protocol::Triangle;
using grading::protocol::Writer;

constexpr grading::StageCall kCollapse{"collapse_bvh4", "collapse_bvh4"};
constexpr grading::StageCall kBox4{"box4_answers", "intersect_ray_box4"};
constexpr grading::StageCall kIntersectBvh4{"intersect_bvh4", "intersect_bvh4"};

}  // namespace

#if RAYLAB_JUDGE
Bvh4 collapse_bvh4(const Bvh& binary) {
  Writer arguments;
  arguments.put_vector(binary.nodes);
  arguments.put_vector(binary.primitive_order);
  return grading::remote(kCollapse, arguments, [](Reader& in) {
    Bvh4 wide;
    wide.nodes = in.get_vector<Bvh4Node>();
    wide.primitive_order = in.get_vector<std::uint32_t>();
    in.expect_end();
    return wide;
  });
}

namespace grading {

std::vector<Box4Answer> box4_answers(const std::vector<Ray>& rays, const std::vector<Bvh4Node>& nodes) {
  Writer arguments;
  arguments.put_vector(rays);
  arguments.put_vector(nodes);
  return remote(kBox4, arguments, [&](Reader& in) {
    auto answers = in.get_vector<Box4Answer>();
    in.expect_end();
    if (answers.size() != rays.size()) throw protocol::ProtocolError(MessageId::protocol_wrong_sample_count);
    return answers;
  });
}

}  // namespace grading

unsigned intersect_ray_box4(const Ray& ray, const glm::vec3&, const Bvh4Node& node, float entry_distances[kBvh4Width]) {
  const grading::Box4Answer answer = grading::box4_answers({ray}, {node})[0];
  for (int i = 0; i < kBvh4Width; ++i) entry_distances[i] = answer.entry_distances[static_cast<std::size_t>(i)];
  return answer.mask;
}

std::optional<BvhHit> intersect_bvh4(const Bvh4& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                     bool any_hit, BvhTraversalStats& stats) {
  static grading::SentList<Bvh4Node> sent_nodes;
  static grading::SentList<std::uint32_t> sent_order;
  static grading::SentList<Triangle> sent_triangles;
  const bool grader_test = intersector.test == &grading::grader_triangle_test;
  const auto* triangles = static_cast<const std::vector<Triangle>*>(intersector.context);
  Writer arguments;
  sent_nodes.put(arguments, bvh.nodes);
  sent_order.put(arguments, bvh.primitive_order);
  arguments.put<std::uint8_t>(grader_test);
  if (grader_test) sent_triangles.put(arguments, *triangles);
  arguments.put(ray);
  arguments.put<std::uint8_t>(any_hit);
  const grading::TraversalReply reply = grading::remote(kIntersectBvh4, arguments, grading::read_traversal_reply,
                                                       grading::answer_primitive_tests(intersector));
  sent_nodes.returned(bvh.nodes);
  sent_order.returned(bvh.primitive_order);
  if (grader_test) sent_triangles.returned(*triangles);
  grading::add_traversal_work(reply, grader_test, stats);
  return reply.hit;
}

#else
namespace grading {

std::vector<Box4Answer> box4_answers(const std::vector<Ray>& rays, const std::vector<Bvh4Node>& nodes) {
  if (rays.size() != nodes.size()) throw std::invalid_argument("box4_answers: one node per ray");
  std::vector<Box4Answer> answers(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    float entries[kBvh4Width] = {};
    answers[i].mask = intersect_ray_box4(rays[i], ray_direction_inverse_of(rays[i]), nodes[i], entries);
    for (int k = 0; k < kBvh4Width; ++k) answers[i].entry_distances[static_cast<std::size_t>(k)] = entries[k];
  }
  return answers;
}

}  // namespace grading

namespace {

void serve_collapse(Reader& in, Writer& out) {
  Bvh binary;
  binary.nodes = in.get_vector<BvhNode, BvhNodeAllocator<BvhNode>>();
  binary.primitive_order = in.get_vector<std::uint32_t>();
  const Bvh4 wide = collapse_bvh4(binary);
  out.put_vector(wide.nodes);
  out.put_vector(wide.primitive_order);
}

void serve_box4(Reader& in, Writer& out) {
  const auto rays = in.get_vector<Ray>();
  const auto nodes = in.get_vector<Bvh4Node>();
  out.put_vector(grading::box4_answers(rays, nodes));
}

void serve_intersect_bvh4(Reader& in, Writer& out) {
  static Bvh4 bvh;  // what the judge sent for earlier calls
  static std::vector<Triangle> triangles;
  grading::receive(in, bvh.nodes);
  grading::receive(in, bvh.primitive_order);
  const bool grader_test = in.get<std::uint8_t>() != 0;
  if (grader_test) grading::receive(in, triangles);
  const auto ray = in.get<Ray>();
  const bool any_hit = in.get<std::uint8_t>() != 0;
  grading::serve_traversal(out, ray, any_hit, grader_test, triangles,
                           [&](const Ray& r, const PrimitiveIntersector& intersector, bool any, BvhTraversalStats& stats) {
                             return intersect_bvh4(bvh, r, intersector, any, stats);
                           });
}

const bool kServed = grading::serve(kCollapse, serve_collapse) && grading::serve(kBox4, serve_box4) &&
                     grading::serve(kIntersectBvh4, serve_intersect_bvh4);

}  // namespace
#endif

}  // namespace raylab
