// The reference data of stage 09_path: the two Cornell boxes rendered small (kCornellSize
// pixels square) and converged (kReferenceSamples samples per pixel) by the reference path
// tracer, each pixel's mean and variance of the mean. autograder-regenerate writes them to
// autograder/reference/09_path_cases.json; the suite (09_path_test.cpp) compares the student's
// low-sample renders with them region by region.
#include "path_support.h"
#include "support.h"

namespace raylab::grading {
namespace {

using nlohmann::json;

json cornell_references(std::uint32_t) {
  json result;
  for (const char* scene : kCornellScenes) {
    const PathRenderResult render = path_render(scene, cornell_request(kReferenceSamples, kReferenceSeed));
    json mean = json::array(), variance = json::array();
    for (const glm::vec3& v : render.mean.pixels()) mean.push_back(to_json(v));
    for (const glm::vec3& v : render.variance_of_mean.pixels()) variance.push_back(to_json(v));
    result[scene] = {{"samples_per_pixel", kReferenceSamples}, {"mean", mean}, {"variance_of_mean", variance}};
  }
  return result;
}

const bool kRegistered = register_reference_data("09_path", {cornell_references, false});

}  // namespace
}  // namespace raylab::grading
