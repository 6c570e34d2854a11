// The path integrator: stage 09's path_radiance (the student's in `raylab`, the reference's in
// `raylab-reference`), with the camera ray counted for the progress line.
#include "raylab/integrator.h"

#include "raylab/stages/09_path.h"

namespace raylab {

glm::vec3 path_li(const RenderContext& context, const Ray& ray, Sampler& sampler, ShadingStats& stats) {
  ++stats.camera_rays;
  return path_radiance(context, ray, sampler);
}

}  // namespace raylab
