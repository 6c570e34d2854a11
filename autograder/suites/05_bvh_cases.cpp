// The reference data of stage 05_bvh (and its bonus 05b_bvh_sah): the BVH stages are compared
// with brute force live, and the SAH bonus with the SAH cost of the reference's trees on the
// bunny. autograder-regenerate writes autograder/reference/05_bvh_cases.json.
#include "bvh_support.h"
#include "support.h"

#include "raylab/bvh_tools.h"
#include "raylab/stages/05_bvh.h"

namespace raylab::grading {
namespace {

using nlohmann::json;

json bvh_costs(std::uint32_t /*seed: none, the trees are the reference's*/) {
  const TestMesh& bunny = bvh_test_meshes().front();
  return {{"bunny_median_cost", bvh_sah_cost(build_bvh(bunny.bounds, 4))},
          {"bunny_sah_cost", bvh_sah_cost(build_bvh_sah(bunny.bounds, 4))}};
}

const bool kRegistered = register_reference_data("05_bvh", {bvh_costs, /*seeded=*/false});

}  // namespace
}  // namespace raylab::grading
