// Stage 10's batch calls (10_microfacet_calls.cpp): the two samplers in bulk (a chi-square test
// needs 10^5 samples); every other function of the stage is one call each.
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace raylab::grading {

// sample_ggx_half_vector(u, alpha) for each u.
std::vector<glm::vec3> ggx_half_vector_samples(float alpha, const std::vector<glm::vec2>& uniform_randoms);
// sample_microfacet_wi(wo, u, alpha) for each u.
std::vector<glm::vec3> microfacet_wi_samples(const glm::vec3& wo, float alpha, const std::vector<glm::vec2>& uniform_randoms);

}  // namespace raylab::grading
