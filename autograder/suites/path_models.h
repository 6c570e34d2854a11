// The furnaces of stages 09 and 09b, and what a path tracer computes in them with each common
// mistake (stage 09's fitted models): plain arithmetic, with no stage code and no test framework,
// so that a test of the models alone (tests/test_path_models.cpp) can prove that the furnaces
// tell every modelled mistake, and every pair of them, from a correct path tracer.
#pragma once

#include "messages.h"

#include <functional>
#include <vector>

namespace raylab::grading {

// The furnaces (scenes/furnace.json, a sphere seen from inside, emitting 1, with every albedo set
// to `albedo`), each rendered 32x32 at 4 spp (path_support.h: furnace_request). Chosen so that
// every modelled mistake moves a furnace by 13% or more, and no two mistakes made together cancel
// in a furnace that either of them moves (tests/test_path_models.cpp).
struct Furnace {
  double albedo, roulette;
  int max_depth;
};
constexpr Furnace kFurnaces[] = {{0.4, 1.0, 5}, {0.45, 0.6, 20}, {0.3, 0.8, 20}};
constexpr int kFurnaceCount = 3;
// A furnace's exact pixel value (emission 1): sum of a^k for k = 0 .. max_depth + 1.
double furnace_exact(const Furnace& furnace);

// What a path tracer computes in a furnace of emission 1: the camera's hit counts
// `first_emission`, every vertex k = 0..max_depth + depth_offset (reached with weight r^k) adds
// its direct light d, and vertices after the first add `later_emission` each.
struct PathModel {
  std::function<double(const Furnace&)> bounce_weight;  // r
  double direct_factor = 1.0;                            // d = direct_factor * a
  double first_emission = 1.0, later_emission = 0.0;
  int depth_offset = 0;  // -1: the vertex at depth == max_depth left out
};
// The correct path tracer: r = a.
PathModel correct_path_model();
double furnace_value(const PathModel& model, const Furnace& furnace);

// A common mistake, as what it changes in the correct model (so that two mistakes made together
// are the two changes, in the order of the list).
struct PathMistake {
  const char* name;  // for the tests of the models: "roulette not divided"
  MessageId hint;
  std::function<void(PathModel&)> change;
  // Mistakes whose weights explode: the cosine missing weighs a bounce by a / cos(theta), of
  // infinite variance; 1 / pi missing by pi a > 1. Their furnaces with roulette (weights divided
  // by p again and again) are left out of the fit, and a mean within 10% of the model (or 4
  // standard errors) fits.
  bool wild_weights = false;
};
// Stage 09's modelled mistakes, in the order the hints are tried.
const std::vector<PathMistake>& path_mistakes();
// The correct model changed by `made` (one mistake, or two together).
PathModel path_model_with(const std::vector<const PathMistake*>& made);

}  // namespace raylab::grading
