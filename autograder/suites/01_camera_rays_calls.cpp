// Stage 01's calls between the judge and the stage server (autograder/runner/stage_call.h).
#include "stage_call.h"

#include "raylab/stages/01_camera_rays.h"

namespace raylab {
namespace {
constexpr grading::StageCall kGenerateCameraRay{"generate_camera_ray", "generate_camera_ray"};
}  // namespace

#if RAYLAB_JUDGE
Ray generate_camera_ray(const Camera& camera, int pixel_x, int pixel_y, glm::vec2 position_in_pixel) {
  return grading::call_remote<decltype(generate_camera_ray)>(kGenerateCameraRay, camera, pixel_x, pixel_y,
                                                             position_in_pixel);
}
#else
namespace {
const bool kServed = grading::serve(kGenerateCameraRay, grading::call_local<&generate_camera_ray>);
}  // namespace
#endif

}  // namespace raylab
