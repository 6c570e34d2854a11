// Stage 07's calls between the judge and the stage server (autograder/runner/stage_call.h): each
// warp's samples and each density's values in bulk. The judge's stage functions are batches of one.
#include "07_sampling_calls.h"
#include "stage_call.h"

#include "raylab/stages/07_sampling.h"

#include <stdexcept>

namespace raylab {
namespace {

using grading::Warp;
using grading::protocol::Reader;
using grading::protocol::Writer;

constexpr grading::StageCall kWarpSamples{"warp_samples", "a stage-07 warp (sample_...)",
                                          grading::MessageId::lost_during_warp};
constexpr grading::StageCall kWarpPdfs{"warp_pdfs", "a stage-07 density (..._pdf)", grading::MessageId::lost_during_density};

}  // namespace

#if RAYLAB_JUDGE
namespace grading {

std::vector<glm::vec3> warp_samples(Warp warp, const std::vector<glm::vec2>& uniform_randoms) {
  Writer arguments;
  arguments.put(warp);
  arguments.put_vector(uniform_randoms);
  return remote(kWarpSamples, arguments, [&](Reader& in) {
    auto samples = in.get_vector<glm::vec3>();
    in.expect_end();
    if (samples.size() != uniform_randoms.size()) throw protocol::ProtocolError(MessageId::protocol_wrong_sample_count);
    return samples;
  });
}

std::vector<float> warp_pdfs(Warp warp, const std::vector<glm::vec3>& arguments_in) {
  Writer arguments;
  arguments.put(warp);
  arguments.put_vector(arguments_in);
  return remote(kWarpPdfs, arguments, [&](Reader& in) {
    auto values = in.get_vector<float>();
    in.expect_end();
    const std::size_t expected = warp == Warp::UniformTriangle ? arguments_in.size() / 3 : arguments_in.size();
    if (values.size() != expected) throw protocol::ProtocolError(MessageId::protocol_wrong_density_count);
    return values;
  });
}

}  // namespace grading

glm::vec3 sample_uniform_hemisphere(glm::vec2 uniform_random) {
  return grading::warp_samples(Warp::UniformHemisphere, {uniform_random})[0];
}
float uniform_hemisphere_pdf(const glm::vec3& direction) {
  return grading::warp_pdfs(Warp::UniformHemisphere, {direction})[0];
}
glm::vec3 sample_cosine_hemisphere(glm::vec2 uniform_random) {
  return grading::warp_samples(Warp::CosineHemisphere, {uniform_random})[0];
}
float cosine_hemisphere_pdf(const glm::vec3& direction) {
  return grading::warp_pdfs(Warp::CosineHemisphere, {direction})[0];
}
glm::vec3 sample_uniform_sphere(glm::vec2 uniform_random) {
  return grading::warp_samples(Warp::UniformSphere, {uniform_random})[0];
}
float uniform_sphere_pdf(const glm::vec3& direction) {
  return grading::warp_pdfs(Warp::UniformSphere, {direction})[0];
}
glm::vec2 sample_uniform_disk(glm::vec2 uniform_random) {
  return glm::vec2(grading::warp_samples(Warp::UniformDisk, {uniform_random})[0]);
}
float uniform_disk_pdf(glm::vec2 point) {
  return grading::warp_pdfs(Warp::UniformDisk, {glm::vec3(point, 0.0f)})[0];
}
Barycentrics sample_uniform_triangle(glm::vec2 uniform_random) {
  const glm::vec3 b = grading::warp_samples(Warp::UniformTriangle, {uniform_random})[0];
  return Barycentrics{b.x, b.y};
}
float uniform_triangle_pdf(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  return grading::warp_pdfs(Warp::UniformTriangle, {p0, p1, p2})[0];
}

#else
namespace grading {

std::vector<glm::vec3> warp_samples(Warp warp, const std::vector<glm::vec2>& uniform_randoms) {
  std::vector<glm::vec3> samples;
  samples.reserve(uniform_randoms.size());
  for (const glm::vec2& u : uniform_randoms) {
    switch (warp) {
      case Warp::UniformHemisphere: samples.push_back(sample_uniform_hemisphere(u)); break;
      case Warp::CosineHemisphere: samples.push_back(sample_cosine_hemisphere(u)); break;
      case Warp::UniformSphere: samples.push_back(sample_uniform_sphere(u)); break;
      case Warp::UniformDisk: samples.push_back(glm::vec3(sample_uniform_disk(u), 0.0f)); break;
      case Warp::UniformTriangle: {
        const Barycentrics b = sample_uniform_triangle(u);
        samples.push_back(glm::vec3(b.barycentric_b1, b.barycentric_b2, 0.0f));
        break;
      }
      default: throw std::invalid_argument("warp_samples: no such warp");
    }
  }
  return samples;
}

std::vector<float> warp_pdfs(Warp warp, const std::vector<glm::vec3>& arguments) {
  std::vector<float> values;
  if (warp == Warp::UniformTriangle) {
    if (arguments.size() % 3 != 0) throw std::invalid_argument("warp_pdfs: three corners per triangle");
    for (std::size_t i = 0; i < arguments.size(); i += 3)
      values.push_back(uniform_triangle_pdf(arguments[i], arguments[i + 1], arguments[i + 2]));
    return values;
  }
  values.reserve(arguments.size());
  for (const glm::vec3& argument : arguments) {
    switch (warp) {
      case Warp::UniformHemisphere: values.push_back(uniform_hemisphere_pdf(argument)); break;
      case Warp::CosineHemisphere: values.push_back(cosine_hemisphere_pdf(argument)); break;
      case Warp::UniformSphere: values.push_back(uniform_sphere_pdf(argument)); break;
      case Warp::UniformDisk: values.push_back(uniform_disk_pdf(glm::vec2(argument))); break;
      default: throw std::invalid_argument("warp_pdfs: no such warp");
    }
  }
  return values;
}

}  // namespace grading

namespace {

const bool kServed = grading::serve(kWarpSamples, grading::call_local<&grading::warp_samples>) &&
                     grading::serve(kWarpPdfs, grading::call_local<&grading::warp_pdfs>);

}  // namespace
#endif

}  // namespace raylab
