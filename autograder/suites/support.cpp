#include "support.h"

#include "09_path_calls.h"
#include "grading.h"

#include "raylab/error.h"
#include "raylab/stage_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace raylab::grading {

namespace {
bool hint_non_finite(const MessageArg& what, std::initializer_list<float> results, const Message& advice) {
  for (float value : results) {
    if (std::isfinite(value)) continue;
    const MessageArg name = std::isnan(value) ? MessageArg("value", "NaN")
                            : value > 0.0f  ? MessageArg::bilingual("value", "infinity", "无穷大")
                                            : MessageArg::bilingual("value", "-infinity", "负无穷大");
    add_hint({std::isnan(value) ? MessageId::not_finite_nan : MessageId::not_finite_infinity,
              {what, name, {"advice", advice}}});
    return true;
  }
  return false;
}
}  // namespace

void throw_if_every_function_is_a_stub(const char* stage_id, std::initializer_list<std::function<void()>> calls) {
  std::optional<NotImplemented> first;
  std::size_t stubs = 0;
  for (const std::function<void()>& call : calls) {
    try {
      call();
    } catch (const NotImplemented& e) {
      if (e.stage_id() != stage_id) continue;
      ++stubs;
      if (!first) first = e;
    }
  }
  if (stubs == calls.size() && first) throw *first;
}

bool hint_if_not_finite(const std::string& what, std::initializer_list<float> results, const Message& advice) {
  return hint_non_finite({"what", what}, results, advice);
}
bool hint_if_not_finite(const Message& what, std::initializer_list<float> results, const Message& advice) {
  return hint_non_finite({"what", what}, results, advice);
}

Message hit_text(std::optional<float> t, bool fixed) {
  if (!t) return MessageId::value_no_hit;
  return {MessageId::value_t, {{"t", fixed ? std::to_string(*t) : stream_text(*t)}}};
}

Message ray_text(const Ray& ray) {
  return {MessageId::value_ray,
          {{"origin", gtest_text(ray.origin)}, {"direction", gtest_text(ray.direction)},
           {"t_min", gtest_text(ray.t_min)}, {"t_max", gtest_text(ray.t_max)}}};
}

Message box_text(const Bounds3& box) {
  if (box.is_empty()) return MessageId::value_box_empty;
  return {MessageId::value_box, {{"min", gtest_text(box.min)}, {"max", gtest_text(box.max)}}};
}

nlohmann::json to_json(const glm::vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

glm::vec3 vec3_from_json(const nlohmann::json& value) {
  return {value.at(0).get<float>(), value.at(1).get<float>(), value.at(2).get<float>()};
}

nlohmann::json load_reference_cases(const std::string& stage_id) {
  const std::string path = reference_path(stage_id + "_cases.json");
  std::ifstream in(path);
  if (!in) throw std::runtime_error("missing reference data " + path + " (run the regenerate tool)");
  return nlohmann::json::parse(in);
}

namespace {
std::map<std::string, ReferenceData>& reference_data_registry() {
  static std::map<std::string, ReferenceData> registry;
  return registry;
}
}  // namespace

bool register_reference_data(const char* stage_id, ReferenceData data) {
  reference_data_registry()[stage_id] = std::move(data);
  return true;
}

const ReferenceData* reference_data_of(const std::string& stage_id) {
  const auto found = reference_data_registry().find(stage_id);
  return found == reference_data_registry().end() ? nullptr : &found->second;
}

namespace {
std::uint64_t test_seed_round = 0;
}

std::size_t bitwise_differences(const std::vector<glm::vec3>& first, const std::vector<glm::vec3>& second) {
  std::size_t differing = 0;
  for (std::size_t i = 0; i < first.size() && i < second.size(); ++i)
    differing += std::memcmp(&first[i], &second[i], sizeof(glm::vec3)) != 0;
  return differing;
}

std::uint64_t test_seed(std::uint64_t graded_seed) {
  if (test_seed_round == 0) return graded_seed;
  // A seed no grading uses: the round and the graded seed hashed together (Pcg32's output).
  Pcg32 mix(graded_seed, test_seed_round);
  return (static_cast<std::uint64_t>(mix.next_uint32()) << 32) | mix.next_uint32();
}

void set_test_seed_round(std::uint64_t round) { test_seed_round = round; }

std::string seed_shown(const nlohmann::json& case_file) {
  const nlohmann::json& seed = case_file.at("seed");
  return seed.is_string() ? seed.get<std::string>() : seed.dump();
}

std::string reference_image_name(const std::string& stage_id) { return stage_id + ".png"; }

namespace {

// A failing picture's pixel that differs most, traced through the stage code, on the pictures and
// as a note; nothing when the trace cannot be had (its stage server lost: the picture's failure
// stands alone).
void add_worst_pixel_trace(ImageComparison& images, const std::string& stage_id, const ImageDifference& difference) {
  const int x = difference.max_x, y = difference.max_y;
  const bool chinese = language() == Language::Chinese;
  PixelTrace trace;
  try {
    trace = trace_stage_image_pixel(stage_id, x, y, chinese);
  } catch (const std::exception&) {
    return;
  }
  attach_pixel_trace(images, std::move(trace), stage_image_trace_command(stage_id, x, y, chinese));
}

}  // namespace

void attach_pixel_trace(ImageComparison& images, PixelTrace trace, const std::string& command) {
  images.worst_pixel = std::move(trace);
  images.trace_command = command;
  const PixelTrace& traced = *images.worst_pixel;
  const int x = traced.x, y = traced.y;
  std::vector<MessageArg> args{{"x", std::to_string(x)}, {"y", std::to_string(y)}, {"command", images.trace_command}};
  // A Monte Carlo picture's trace is one sample of the pixel (stage 09's path_trace_pixel).
  const bool sampled = traced.settings.integrator != IntegratorKind::Whitted;
  if (sampled) args.insert(args.end(), {{"sample", std::to_string(traced.settings.sample)},
                                        {"samples", std::to_string(std::min(traced.settings.samples_per_pixel,
                                                                            kMostTracedPathSamples))}});
  const int first = traced.first_disagreement();
  if (first < 0) {
    // (A trace whose later steps were left out is not said to agree: the table shows what came.)
    if (!traced.steps_cut) add_note({sampled ? MessageId::note_path_trace_agrees : MessageId::note_trace_agrees, args});
    return;
  }
  const TraceStep& step = traced.steps[static_cast<std::size_t>(first)];
  args.insert(args.end(), {{"step", std::to_string(first + 1)}, {"yours", step.yours}, {"expected", step.expected}});
  if (step.function.empty()) {
    args.emplace_back("call", step.call);
    add_note({sampled ? MessageId::note_path_trace_disagrees_at_step : MessageId::note_trace_disagrees_at_step, args});
    return;
  }
  const std::string file = step.file();
  args.emplace_back("function", step.function);
  args.emplace_back("file", file.empty() ? step.stage : file);
  add_note({sampled ? MessageId::note_path_trace_disagrees : MessageId::note_trace_disagrees, args});
}

void expect_image_matches_reference(const std::string& stage_id, float channel_threshold, double max_fraction) {
  const std::string directory = output_directory();
  std::filesystem::create_directories(directory);
  const std::string yours_path = directory + "/" + stage_id + "-yours.png";
  const std::string comparison_path = directory + "/" + stage_id + ".png";

  const Image rendered = render_stage_image(stage_id);
  write_image(rendered, yours_path);
  const Image yours = read_image(yours_path);
  const Image expected = read_image(reference_path(reference_image_name(stage_id)));
  const ImageDifference difference = compare_images(yours, expected, channel_threshold);
  const Image comparison = side_by_side_difference(yours, expected, 0.25f);
  write_image(comparison, comparison_path);
  // Each picture on its own as well, for the HTML report (its slider lays yours over the reference).
  const std::string reference_name = stage_id + "-reference.png", difference_name = stage_id + "-difference.png";
  write_image(expected, directory + "/" + reference_name);
  Image heat_map(yours.width(), yours.height());
  for (int y = 0; y < heat_map.height(); ++y)
    for (int x = 0; x < heat_map.width(); ++x) heat_map.at(x, y) = comparison.at(2 * yours.width() + x, y);
  write_image(heat_map, directory + "/" + difference_name);
  ImageComparison images{stage_id + "-yours.png", reference_name, difference_name};
  if (difference.fraction_over_threshold > max_fraction) add_worst_pixel_trace(images, stage_id, difference);
  add_image(images);

  add_note({MessageId::note_image,
            {{"width", std::to_string(kImageWidth)}, {"height", std::to_string(kImageHeight)},
             {"pixels", stream_text(difference.pixels_over_threshold)},
             {"percent", stream_text(100.0 * difference.fraction_over_threshold)},
             {"threshold", stream_text(channel_threshold)}, {"allowed", stream_text(100.0 * max_fraction)},
             {"rms", stream_text(difference.rms_error)}, {"path", comparison_path}}});
  EXPECT_LE(difference.fraction_over_threshold, max_fraction)
      << failure_text({MessageId::image_failure,
                 {{"error", gtest_text(difference.max_error)}, {"x", gtest_text(difference.max_x)},
                  {"y", gtest_text(difference.max_y)}, {"path", comparison_path}}});
}

}  // namespace raylab::grading
