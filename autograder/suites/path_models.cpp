#include "path_models.h"

namespace raylab::grading {
namespace {

constexpr double kPiD = 3.14159265358979323846;

// The bounce weight times `factor(f)`.
std::function<void(PathModel&)> bounce_weight_times(std::function<double(const Furnace&)> factor) {
  return [factor](PathModel& m) {
    m.bounce_weight = [inner = m.bounce_weight, factor](const Furnace& f) { return inner(f) * factor(f); };
  };
}

}  // namespace

PathModel correct_path_model() { return PathModel{[](const Furnace& f) { return f.albedo; }}; }

double furnace_exact(const Furnace& furnace) { return furnace_value(correct_path_model(), furnace); }

double furnace_value(const PathModel& model, const Furnace& furnace) {
  const double r = model.bounce_weight(furnace), d = model.direct_factor * furnace.albedo;
  double sum = model.first_emission, reach = 1.0;
  for (int k = 0; k <= furnace.max_depth + model.depth_offset; ++k) {
    sum += reach * d + (k > 0 ? reach * model.later_emission : 0.0);
    reach *= r;
  }
  return sum;
}

const std::vector<PathMistake>& path_mistakes() {
  static const std::vector<PathMistake> models = {
      // The throughput never multiplied: every vertex is reached with weight 1 (roulette divides by
      // the p it survived). First: the other changes of the bounce weight apply to this one.
      {"throughput not multiplied", MessageId::path_throughput_not_multiplied, [](PathModel& m) { m.bounce_weight = [](const Furnace&) { return 1.0; }; }},
      {"roulette not divided", MessageId::path_roulette_not_divided, bounce_weight_times([](const Furnace& f) { return f.roulette; })},
      {"emission counted twice", MessageId::path_emission_twice, [](PathModel& m) { m.later_emission = 1.0; }},
      {"light black when seen directly", MessageId::path_light_black, [](PathModel& m) { m.first_emission = 0.0; }},
      {"one surface short", MessageId::path_one_surface_short, [](PathModel& m) { m.depth_offset = -1; }},
      // No direct light at any vertex (a shadow ray that hits the light itself is always blocked):
      // every pixel is the emission the camera sees, exactly 1.
      {"no direct light", MessageId::path_no_direct_light, [](PathModel& m) { m.direct_factor = 0.0; }},
      {"cosine missing", MessageId::path_missing_cosine, bounce_weight_times([](const Furnace&) { return 2.0; }), true},
      // The bounce weighed with f = albedo rather than the BSDF's albedo / pi (the direct light,
      // stage 08's estimator, stays right).
      {"1 / pi missing", MessageId::path_missing_inverse_pi, bounce_weight_times([](const Furnace&) { return kPiD; }), true},
  };
  return models;
}

PathModel path_model_with(const std::vector<const PathMistake*>& made) {
  PathModel model = correct_path_model();
  for (const PathMistake* mistake : made) mistake->change(model);
  return model;
}

}  // namespace raylab::grading
