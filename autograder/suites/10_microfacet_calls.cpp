// Stage 10's calls between the judge and the stage server (autograder/runner/stage_call.h): the
// functions one call each, the two samplers also in bulk.
#include "10_microfacet_calls.h"
#include "stage_call.h"

#include "raylab/stages/10_microfacet.h"

namespace raylab {
namespace {

using grading::protocol::Reader;
using grading::protocol::Writer;

constexpr grading::StageCall kGgxDistribution{"ggx_distribution", "ggx_distribution"};
constexpr grading::StageCall kGgxSmithG1{"ggx_smith_g1", "ggx_smith_g1"};
constexpr grading::StageCall kMicrofacetF{"microfacet_f", "microfacet_f"};
constexpr grading::StageCall kGgxHalfVectorPdf{"ggx_half_vector_pdf", "ggx_half_vector_pdf"};
constexpr grading::StageCall kMicrofacetPdf{"microfacet_pdf", "microfacet_pdf"};
constexpr grading::StageCall kHalfVectorSamples{"ggx_half_vector_samples", "sample_ggx_half_vector"};
constexpr grading::StageCall kWiSamples{"microfacet_wi_samples", "sample_microfacet_wi"};

}  // namespace

#if RAYLAB_JUDGE
float ggx_distribution(const glm::vec3& half_vector, float alpha) {
  return grading::call_remote<decltype(ggx_distribution)>(kGgxDistribution, half_vector, alpha);
}
float ggx_smith_g1(const glm::vec3& direction, float alpha) {
  return grading::call_remote<decltype(ggx_smith_g1)>(kGgxSmithG1, direction, alpha);
}
glm::vec3 microfacet_f(const glm::vec3& wo, const glm::vec3& wi, float alpha, const glm::vec3& specular_color) {
  return grading::call_remote<decltype(microfacet_f)>(kMicrofacetF, wo, wi, alpha, specular_color);
}
float ggx_half_vector_pdf(const glm::vec3& half_vector, float alpha) {
  return grading::call_remote<decltype(ggx_half_vector_pdf)>(kGgxHalfVectorPdf, half_vector, alpha);
}
float microfacet_pdf(const glm::vec3& wo, const glm::vec3& wi, float alpha) {
  return grading::call_remote<decltype(microfacet_pdf)>(kMicrofacetPdf, wo, wi, alpha);
}
glm::vec3 sample_ggx_half_vector(glm::vec2 uniform_random, float alpha) {
  return grading::ggx_half_vector_samples(alpha, {uniform_random})[0];
}
glm::vec3 sample_microfacet_wi(const glm::vec3& wo, glm::vec2 uniform_random, float alpha) {
  return grading::microfacet_wi_samples(wo, alpha, {uniform_random})[0];
}

namespace grading {
namespace {

std::vector<glm::vec3> read_samples(Reader& in, std::size_t expected) {
  auto samples = in.get_vector<glm::vec3>();
  in.expect_end();
  if (samples.size() != expected) throw protocol::ProtocolError(MessageId::protocol_wrong_sample_count);
  return samples;
}

}  // namespace

std::vector<glm::vec3> ggx_half_vector_samples(float alpha, const std::vector<glm::vec2>& uniform_randoms) {
  Writer arguments;
  arguments.put(alpha);
  arguments.put_vector(uniform_randoms);
  return remote(kHalfVectorSamples, arguments, [&](Reader& in) { return read_samples(in, uniform_randoms.size()); });
}

std::vector<glm::vec3> microfacet_wi_samples(const glm::vec3& wo, float alpha, const std::vector<glm::vec2>& uniform_randoms) {
  Writer arguments;
  arguments.put(wo);
  arguments.put(alpha);
  arguments.put_vector(uniform_randoms);
  return remote(kWiSamples, arguments, [&](Reader& in) { return read_samples(in, uniform_randoms.size()); });
}

}  // namespace grading

#else
namespace grading {

std::vector<glm::vec3> ggx_half_vector_samples(float alpha, const std::vector<glm::vec2>& uniform_randoms) {
  std::vector<glm::vec3> samples;
  samples.reserve(uniform_randoms.size());
  for (const glm::vec2& u : uniform_randoms) samples.push_back(sample_ggx_half_vector(u, alpha));
  return samples;
}

std::vector<glm::vec3> microfacet_wi_samples(const glm::vec3& wo, float alpha, const std::vector<glm::vec2>& uniform_randoms) {
  std::vector<glm::vec3> samples;
  samples.reserve(uniform_randoms.size());
  for (const glm::vec2& u : uniform_randoms) samples.push_back(sample_microfacet_wi(wo, u, alpha));
  return samples;
}

}  // namespace grading

namespace {

void serve_half_vector_samples(Reader& in, Writer& out) {
  const auto alpha = in.get<float>();
  const auto uniform_randoms = in.get_vector<glm::vec2>();
  out.put_vector(grading::ggx_half_vector_samples(alpha, uniform_randoms));
}

void serve_wi_samples(Reader& in, Writer& out) {
  const auto wo = in.get<glm::vec3>();
  const auto alpha = in.get<float>();
  const auto uniform_randoms = in.get_vector<glm::vec2>();
  out.put_vector(grading::microfacet_wi_samples(wo, alpha, uniform_randoms));
}

const bool kServed = grading::serve(kGgxDistribution, grading::call_local<&ggx_distribution>) &&
                     grading::serve(kGgxSmithG1, grading::call_local<&ggx_smith_g1>) &&
                     grading::serve(kMicrofacetF, grading::call_local<&microfacet_f>) &&
                     grading::serve(kGgxHalfVectorPdf, grading::call_local<&ggx_half_vector_pdf>) &&
                     grading::serve(kMicrofacetPdf, grading::call_local<&microfacet_pdf>) &&
                     grading::serve(kHalfVectorSamples, serve_half_vector_samples) &&
                     grading::serve(kWiSamples, serve_wi_samples);

}  // namespace
#endif

}  // namespace raylab
