// Stage 09b's scripted paths and the models the judge fits to them (09b_mis_test.cpp): the test
// scenes, what each path is made of (its light sample and its BSDF sample, computed by the judge),
// how a correct MIS path tracer weighs the two and how the common mistakes change that, alone or
// two together. tests/test_mis_models.cpp proves with them that every pair fails each scripted
// test either of its mistakes fails, and that the fit there names both; or, where the pair's
// values are those of one of them alone (no MIS, or the emission counted with weight 1, leaves the
// other no weight to get wrong; or the test cannot show the other), that one.
#pragma once

#include "09b_mis_calls.h"
#include "messages.h"

#include <glm/glm.hpp>

#include <vector>

namespace raylab::grading::mis {

// The power heuristic (exponent 2) in double, with the contract's edge cases.
double exact_power(double count_f, double pdf_f, double count_g, double pdf_g);

// The test scenes: a floor (y = 0, facing up) under a quad light (two triangles facing down,
// black: a path that reaches it ends there), or under a point light. Nothing else: a BSDF sample
// that misses the light leaves the scene.
MisScene quad_light_scene();
MisScene point_light_scene();
// Paths from a camera in front of the floor to points on it, for every pair of numbers of a grid.
std::vector<MisScriptedPath> scripted_paths(int max_depth);

// The stage's scripted tests: the test's name, its scene's name in both languages, the scene and
// the paths' max_depth.
struct ScriptedTest {
  const char* test;
  const char* english;
  const char* chinese;
  MisScene scene;
  int max_depth;
};
const std::vector<ScriptedTest>& scripted_tests();  // in the order of the suite's tests

// What a path of the test scenes is made of, computed by the judge: the light sample at the floor
// point and the light the BSDF sample finds, each before its weight, with the densities the
// weights compare. Computed with the framework's light and BSDF sampling, which call the grader's
// own stages 07 and 08 (as the student's path does here): this stage is judged on its weights only.
struct PathParts {
  glm::vec3 light{0.0f};  // f L |cos| / pdf of the light sample (0: none, or blocked)
  bool light_is_delta = false;
  double light_pdf = 0, light_pdf_area = 0, bsdf_pdf_of_light = 0;
  bool bsdf_follows = false;
  glm::vec3 bsdf{0.0f};  // f |cos| / pdf times the emission the BSDF sample finds (0: none)
  double bsdf_pdf = 0, light_pdf_of_bsdf = 0, light_pdf_area_of_bsdf = 0;
};
// Every path's parts, in the scene the stage server builds for `test_scene`.
std::vector<PathParts> parts_of(const MisScene& test_scene, const std::vector<MisScriptedPath>& paths);

// How a path tracer weighs the two samples: the correct one, changed by the common mistakes, each
// a flag, so that two mistakes made together are both flags.
struct MisModel {
  bool no_mis = false;                // the light sample alone, weight 1
  bool balance = false;               // the balance heuristic f / (f + g)
  bool area_pdf = false;              // the light's density per unit area in the BSDF sample's weight (or in both)
  bool emission_twice = false;        // the BSDF sample's emission with weight 1
  bool delta_weighted = false;        // a point light's sample weighted like an area light's
  bool last_vertex_weighted = false;  // the light sample at the last vertex weighted, no BSDF sample following
};
MisModel both(const MisModel& a, const MisModel& b);

// The values `model` may give for the path (a mistake can be made in more than one way): every
// weight of the light sample it may use, with every weight of the BSDF sample. The first is the
// model's plain reading; for the correct model it is the only one.
std::vector<glm::dvec3> model_values(const PathParts& p, const MisModel& model);

// Whether a value returned matches a model's value (float tolerance).
bool same_value(const glm::vec3& got, const glm::dvec3& expected);
// Whether every value returned matches one of the model's values for its path.
bool fits(const std::vector<glm::vec3>& got, const std::vector<PathParts>& parts, const MisModel& model);

// The common mistakes, each as the flag of MisModel it sets, with its hint.
struct MisMistake {
  MisModel model;
  MessageId hint;
  const char* name;
};
const std::vector<MisMistake>& mis_mistakes();

// What the fit names for values that are not all right: every single mistake whose model explains
// every value; when none does, the one pair that does (`together`); otherwise nothing (no pair,
// or more than one, fits).
struct MisFit {
  std::vector<const MisMistake*> named;
  bool together = false;
};
MisFit fit_mistakes(const std::vector<glm::vec3>& got, const std::vector<PathParts>& parts);

}  // namespace raylab::grading::mis
