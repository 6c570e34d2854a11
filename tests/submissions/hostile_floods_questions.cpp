// Grader self-test submission (stage 05_bvh), hostile: the reference's traversal, except where it
// is asked to test primitives through the judge (grader_intersectors.h: the check that any_hit
// stops, then the work test): there
// it writes well-formed questions into its reply pipe as fast as it can and never reads an answer.
// The judge answers until the request pipe is full, then its write waits only until the stage's
// deadline: the call times out, the stage's remaining tests are lost with the reason, and grading
// goes on to write results.json (before the judge waited for ever, both sides in write()).
#define intersect_bvh reference_intersect_bvh
#include "../../solutions/05_bvh/bvh.cpp"
#undef intersect_bvh

#include "grader_intersectors.h"

#include <unistd.h>

#include <cstdint>
#include <cstring>

namespace raylab {

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats);

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats) {
  if (!submission::is_work_probe(intersector)) return reference_intersect_bvh(bvh, ray, intersector, any_hit, stats);
  // A question frame (autograder/runner/protocol.h): its length, then kCallback, the ray, a primitive.
  constexpr std::uint32_t kPayload = 1 + sizeof(Ray) + sizeof(std::uint32_t);
  unsigned char frame[4 + kPayload] = {};
  for (int i = 0; i < 4; ++i) frame[i] = static_cast<unsigned char>((kPayload >> (8 * i)) & 0xff);
  frame[4] = 4;  // kCallback
  std::memcpy(frame + 5, &ray, sizeof(Ray));
  for (;;) {
    if (::write(4, frame, sizeof frame) < 0) ::pause();
  }
}

}  // namespace raylab
