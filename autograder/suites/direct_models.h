// Stage 08's one-sample estimator tests and the estimator's modelled mistakes, each a factor on the
// exact direct light, in plain arithmetic with no stage code and no test framework, so that a test
// of the models alone (tests/test_path_models.cpp: DirectModels) can prove that each estimator
// test tells every modelled mistake, and every pair made together, from a correct estimator and
// from each other.
#pragma once

#include "messages.h"

#include <vector>

namespace raylab::grading {

// How many lights the estimator chooses from in each estimator test: EstimatorUnderQuadLight (a
// quad light, which is two triangles) and EstimatorSeveralLights (a triangle, a sphere and two
// point lights).
constexpr int kDirectEstimatorLights[] = {2, 4};

struct DirectMistake {
  const char* name;  // for the tests of the models
  MessageId hint;
  double (*factor)(int lights);  // the estimate's mean over the exact direct light
  // Made in the BSDF's value: lambertian_f without 1 / pi gives the estimator the same factor, and
  // its own test names it there.
  bool in_bsdf = false;
};

// In the order the hints are tried. A pair made together multiplies the two factors.
inline const std::vector<DirectMistake>& direct_mistakes() {
  static const std::vector<DirectMistake> mistakes = {
      {"not divided by the choice probability", MessageId::direct_estimate_no_choice_probability,
       [](int lights) { return 1.0 / lights; }},
      {"1 / pi missing", MessageId::direct_estimate_times_pi, [](int) { return 3.14159265358979323846; }, true},
  };
  return mistakes;
}

}  // namespace raylab::grading
