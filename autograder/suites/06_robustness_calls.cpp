// Stage 06's calls between the judge and the stage server (autograder/runner/stage_call.h): the
// watertight triangle test, and the leak test's rays against a closed mesh in batches
// (triangles_hit, with stage 06's or stage 03's triangle test).
#include "06_robustness_calls.h"
#include "stage_call.h"

#include "raylab/stages/03_triangle.h"
#include "raylab/stages/03b_watertight.h"

#include <stdexcept>

namespace raylab {
namespace {

using grading::protocol::Reader;
using grading::protocol::Triangle;
using grading::protocol::Writer;

constexpr grading::StageCall kIntersectRayTriangleWatertight{"intersect_ray_triangle_watertight",
                                                             "intersect_ray_triangle_watertight"};
constexpr grading::StageCall kTrianglesHit{"triangles_hit", "intersect_ray_triangle"};

}  // namespace

#if RAYLAB_JUDGE
std::optional<TriangleHit> intersect_ray_triangle_watertight(const Ray& ray, const glm::vec3& p0, const glm::vec3& p1,
                                                             const glm::vec3& p2) {
  return grading::call_remote<decltype(intersect_ray_triangle_watertight)>(kIntersectRayTriangleWatertight, ray, p0,
                                                                           p1, p2);
}

namespace grading {

std::vector<std::optional<TriangleHit>> intersect_ray_triangle_watertight_each(
    const std::vector<TriangleTestArguments>& calls) {
  return call_remote_each<decltype(intersect_ray_triangle_watertight)>(kIntersectRayTriangleWatertight, calls);
}

std::vector<std::vector<std::uint32_t>> triangles_hit(TriangleFunction function, const std::vector<Triangle>& triangles,
                                                      const std::vector<Ray>& rays,
                                                      const std::vector<std::vector<std::uint32_t>>& candidates) {
  const bool watertight = function == &intersect_ray_triangle_watertight;
  if (!watertight && function != &intersect_ray_triangle)
    throw std::invalid_argument("triangles_hit: only the stage functions can be called in the stage server");
  if (!candidates.empty() && candidates.size() != rays.size())
    throw std::invalid_argument("triangles_hit: one candidate list per ray");
  Writer arguments;
  arguments.put<std::uint8_t>(watertight);
  arguments.put_vector(triangles);
  arguments.put_vector(rays);
  protocol::put_lists(arguments, candidates);
  // At most every triangle (or every candidate) for every ray, with the lists' offsets.
  std::uint64_t most_hits = 0;
  if (candidates.empty()) most_hits = static_cast<std::uint64_t>(rays.size()) * triangles.size();
  else
    for (const auto& list : candidates) most_hits += list.size();
  const std::uint32_t limit = reply_limit(2 * sizeof(std::uint64_t) + (rays.size() + 1) * sizeof(std::uint64_t) +
                                          most_hits * sizeof(std::uint32_t));
  return remote(kTrianglesHit, arguments, [&](Reader& in) {
    auto hits = protocol::get_lists(in);
    in.expect_end();
    if (hits.size() != rays.size()) throw protocol::ProtocolError(MessageId::protocol_wrong_ray_count);
    for (const auto& list : hits)
      for (std::uint32_t t : list)
        if (t >= triangles.size()) throw protocol::ProtocolError(MessageId::protocol_triangle_out_of_range);
    return hits;
  }, {}, limit);
}

}  // namespace grading

#else
namespace grading {

std::vector<std::optional<TriangleHit>> intersect_ray_triangle_watertight_each(
    const std::vector<TriangleTestArguments>& calls) {
  return call_local_each<&intersect_ray_triangle_watertight>(calls);
}

std::vector<std::vector<std::uint32_t>> triangles_hit(TriangleFunction function, const std::vector<Triangle>& triangles,
                                                      const std::vector<Ray>& rays,
                                                      const std::vector<std::vector<std::uint32_t>>& candidates) {
  std::vector<std::vector<std::uint32_t>> hits(rays.size());
  for (std::size_t r = 0; r < rays.size(); ++r) {
    auto test = [&](std::uint32_t t) {
      if (function(rays[r], triangles.at(t)[0], triangles.at(t)[1], triangles.at(t)[2])) hits[r].push_back(t);
    };
    if (candidates.empty())
      for (std::uint32_t t = 0; t < triangles.size(); ++t) test(t);
    else
      for (std::uint32_t t : candidates.at(r)) test(t);
  }
  return hits;
}

}  // namespace grading

namespace {

void serve_triangles_hit(Reader& in, Writer& out) {
  const bool watertight = in.get<std::uint8_t>() != 0;
  const auto triangles = in.get_vector<Triangle>();
  const auto rays = in.get_vector<Ray>();
  const auto candidates = grading::protocol::get_lists(in);
  grading::protocol::put_lists(out, grading::triangles_hit(watertight ? &intersect_ray_triangle_watertight
                                                                      : &intersect_ray_triangle,
                                                           triangles, rays, candidates));
}

const bool kServed =
    grading::serve(kIntersectRayTriangleWatertight, grading::call_local<&intersect_ray_triangle_watertight>) &&
    grading::serve(kTrianglesHit, serve_triangles_hit);

}  // namespace
#endif

}  // namespace raylab
