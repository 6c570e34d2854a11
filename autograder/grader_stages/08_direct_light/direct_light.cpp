// The grader's own stage 08 (raylab/stages/08_direct_light.h; the products in double precision):
// the stage servers that grade stages 09 and 09b link these instead of yours (stages.json:
// "grader_versions"), so that a mistake in your stage 08 costs points at stage 08 only. The
// estimator takes its random numbers in the reference's order (one to choose the light, two for
// the point on it), so the grades of 09 and 09b see the same paths as with the reference.
#include "raylab/stages/08_direct_light.h"

#include "raylab/lights.h"
#include "raylab/shading.h"

#include <cmath>

namespace raylab {
namespace {

constexpr double kPiInDouble = 3.14159265358979323846;

}  // namespace

glm::vec3 point_light_intensity(const glm::vec3& power) { return glm::vec3(glm::dvec3(power) / (4.0 * kPiInDouble)); }

glm::vec3 point_light_irradiance(const glm::vec3& intensity, const glm::vec3& light_position, const glm::vec3& point,
                                 const glm::vec3& normal) {
  const glm::dvec3 to_light = glm::dvec3(light_position) - glm::dvec3(point);
  const double squared = glm::dot(to_light, to_light);
  const double cosine = squared > 0.0 ? glm::dot(glm::dvec3(normal), to_light) / std::sqrt(squared) : 0.0;
  if (!(cosine > 0.0)) return glm::vec3(0.0f);  // the light on the point, or behind the surface
  return glm::vec3(glm::dvec3(intensity) * (cosine / squared));
}

glm::vec3 lambertian_f(const glm::vec3& albedo) { return glm::vec3(glm::dvec3(albedo) / kPiInDouble); }

float area_pdf_to_solid_angle(float pdf_area, float distance, float cos_at_light) {
  return float(double(pdf_area) * double(distance) * double(distance) / double(cos_at_light));
}

glm::vec3 estimate_direct_light(const RenderContext& context, const SurfaceHit& hit, const Bsdf& bsdf,
                                const glm::vec3& wo, Sampler& sampler) {
  if (context.lights.empty()) return glm::vec3(0.0f);
  float chosen_with = 0.0f;
  const Light& light = context.lights[context.lights.choose(sampler.get_1d(), &chosen_with)];
  const auto sample = sample_li(light, hit.point, sampler.get_2d());
  if (!sample) return glm::vec3(0.0f);
  const glm::vec3 f = bsdf_f(bsdf, hit.geometric_normal, wo, sample->direction);
  if (f == glm::vec3(0.0f)) return glm::vec3(0.0f);
  Ray shadow;  // from just off the surface to just short of the light's point
  shadow.origin = offset_ray_origin(hit, sample->direction);
  shadow.direction = sample->point - shadow.origin;
  shadow.t_max = 1.0f - 1e-4f;
  if (context.geometry.occluded(shadow)) return glm::vec3(0.0f);
  const double cosine = std::fabs(glm::dot(glm::dvec3(hit.geometric_normal), glm::dvec3(sample->direction)));
  return glm::vec3(glm::dvec3(f) * glm::dvec3(sample->radiance) * (cosine / (double(sample->pdf) * double(chosen_with))));
}

}  // namespace raylab
