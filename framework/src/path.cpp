// The path integrators: stage 09's path_radiance and stage 09b's path_radiance_mis (the student's
// in `raylab`, the reference's in `raylab-reference`), with the camera ray counted for the
// progress line.
#include "raylab/integrator.h"

#include "raylab/stages/09_path.h"
#include "raylab/stages/09b_mis.h"

namespace raylab {

glm::vec3 path_li(const RenderContext& context, const Ray& ray, Sampler& sampler, ShadingStats& stats) {
  ++stats.camera_rays;
  return path_radiance(context, ray, sampler);
}

glm::vec3 path_mis_li(const RenderContext& context, const Ray& ray, Sampler& sampler, ShadingStats& stats) {
  ++stats.camera_rays;
  return path_radiance_mis(context, ray, sampler);
}

}  // namespace raylab
