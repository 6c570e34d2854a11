// Grader self-test submission (stage 08_direct_light): the intensity as power / pi, as if the
// power left through pi steradians instead of the whole sphere's 4 pi.
#define point_light_intensity reference_point_light_intensity
#include "../../solutions/08_direct_light/direct_light.cpp"
#undef point_light_intensity

namespace raylab {
glm::vec3 point_light_intensity(const glm::vec3& power) { return power / kPi; }
}  // namespace raylab
