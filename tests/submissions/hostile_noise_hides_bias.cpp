// Hostile: a path tracer without the cosine in its bounce weight (path_missing_cosine, biased),
// which adds to every sample a zero-mean random term 200 times the light's order of magnitude, so
// that its own spread, which the stage server reports, widens the Cornell boxes' region z-tests
// until the bias fits inside them. Noise counts only up to 4 times a correct path tracer's
// (path_support.h: kNoisierThanReferenceAllowed): the Cornell tests fail, with the hint that the
// picture is noisier than a correct one can be; it gains nothing over path_missing_cosine.
#define path_radiance biased_path_radiance
#define PATH_VARIANT(v) v.cosine = false
#include "path_variant.h"
#undef path_radiance

namespace raylab {

glm::vec3 path_radiance(const RenderContext& context, const Ray& camera_ray, Sampler& sampler) {
  const float noise = 200.0f * (2.0f * sampler.get_1d() - 1.0f);  // mean 0
  return biased_path_radiance(context, camera_ray, sampler) + glm::vec3(noise);
}

}  // namespace raylab
