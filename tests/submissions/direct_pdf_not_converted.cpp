// Grader self-test submission (stage 08_direct_light): the area pdf returned as it is, not turned
// into a density per steradian. Stage 08 names it; stage 09 names the stage-08 function.
#define area_pdf_to_solid_angle reference_area_pdf_to_solid_angle
#include "../../solutions/08_direct_light/direct_light.cpp"
#undef area_pdf_to_solid_angle

namespace raylab {
float area_pdf_to_solid_angle(float pdf_area, float distance, float cos_at_light) {
  (void)distance;
  (void)cos_at_light;
  return pdf_area;
}
}  // namespace raylab
