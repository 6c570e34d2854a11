// Later stages run the functions of earlier ones: stage 08's estimator samples lights with stage
// 07's warps, stage 09's path tracer samples BSDFs and lights with both (through the framework's
// sample_li and bsdf_sample_f). When a later test fails while an earlier function it runs fails
// its own stage's tests, the later stage cannot tell its own mistakes from that one: it says so
// (the hint earlier_function_fails) and names none of its own.
#pragma once

#include <string>
#include <vector>

namespace raylab::grading {

// Stage 07's verdict on one of its functions ("sample_uniform_triangle", "uniform_triangle_pdf",
// ...), as its own tests give it, without their failures and hints (07_sampling_test.cpp): false
// for a stub.
bool sampling_function_passes(const std::string& function);
// Stage 08's verdict on lambertian_f or area_pdf_to_solid_angle: the values its own tests check
// (08_direct_light_test.cpp); false for a stub.
bool direct_light_function_passes(const std::string& function);

// Inside a failing test of stage `current`: for each of `functions` (of stage 07 or 08) that fails
// its own stage's tests, the hint "stage 07_sampling's sample_uniform_triangle fails its tests: fix
// it first ..."; true when any does, so that the caller adds no hint about its own stage's code.
bool hint_failing_earlier_functions(const char* current, const std::vector<std::string>& functions);

}  // namespace raylab::grading
