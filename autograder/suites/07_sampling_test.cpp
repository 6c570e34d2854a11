// Autograder suite for stage 07_sampling (30 points: 6 per warp).
//
// The judge chooses the uniform inputs (fixed seeds: the same verdict on every run), the stage
// server returns the student's samples and densities in bulk (07_sampling_calls.h), and the judge
// decides with the kit's statistics (raylab/testkit/statistics.h): a chi-square test of the
// samples against the density they should have, and one against the student's own pdf
// (expected counts from the pdf integrated over each cell), the pdf's integral, and every
// sample's domain. Each warp is looked at in parameters where its density is smooth inside
// every cell: directions by (phi, z = cos theta), where cells of equal size have equal solid
// angle; disk points by (phi, r); triangle points by (t = b2 / (b1 + b2), s = b1 + b2).
//
// False failures: the 10 chi-square tests share kGraderFalseFailureRate (1 in 1,000 for the
// whole stage, Sidak-corrected); the other tests are exact checks with tolerances for float
// rounding, which a correct implementation never fails.
#include "grading.h"
#include "07_sampling_calls.h"
#include "support.h"

#include "raylab/error.h"
#include "raylab/image.h"
#include "raylab/math.h"
#include "raylab/stages/07_sampling.h"
#include "raylab/testkit/statistics.h"
#include "raylab/testkit/warps.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "07_sampling";
constexpr double kTwoPi = 2.0 * 3.14159265358979323846;
constexpr double kPiD = 3.14159265358979323846;
constexpr int kSampleCount = 200000;
constexpr std::uint64_t kSeed = 7;
const double kLevel = testkit::sidak_level(testkit::kGraderFalseFailureRate, 10);

// Not attempted only while every function of the stage is a stub; one written warp makes the
// others' tests "not attempted" one by one.
const bool kRegistered = register_stage(kStage, [] {
  std::optional<NotImplemented> first;
  int stubs = 0, functions = 0;
  for (const Warp warp : kWarps) {
    for (const bool density : {false, true}) {
      ++functions;
      try {
        if (!density)
          (void)warp_samples(warp, {glm::vec2(0.5f)});
        else if (warp == Warp::UniformTriangle)
          (void)warp_pdfs(warp, {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)});
        else
          (void)warp_pdfs(warp, {glm::vec3(0, 0, 1)});
      } catch (const NotImplemented& e) {
        ++stubs;
        if (!first) first = e;
      }
    }
  }
  if (stubs == functions && first) throw *first;
});

// The {section} of a hint: the warp's section of the handout, in the hint's language.
MessageArg handout_section(Warp warp) {
  int section = 0;
  switch (warp) {
    case Warp::UniformHemisphere: section = 3; break;
    case Warp::CosineHemisphere: section = 4; break;
    case Warp::UniformSphere: section = 5; break;
    case Warp::UniformDisk: section = 6; break;
    case Warp::UniformTriangle: section = 7; break;
  }
  const std::string number = std::to_string(section);
  return MessageArg::bilingual("section", "docs/07_sampling.md, section " + number,
                               "docs/zh/07_sampling.md，第 " + number + " 节");
}

const char* file_name(Warp warp) {
  switch (warp) {
    case Warp::UniformHemisphere: return "uniform_hemisphere";
    case Warp::CosineHemisphere: return "cosine_hemisphere";
    case Warp::UniformSphere: return "uniform_sphere";
    case Warp::UniformDisk: return "uniform_disk";
    case Warp::UniformTriangle: return "uniform_triangle";
  }
  return "warp";
}

// The first part of the warp's test names ("CosineHemisphere").
const char* test_prefix(Warp warp) {
  switch (warp) {
    case Warp::UniformHemisphere: return "UniformHemisphere";
    case Warp::CosineHemisphere: return "CosineHemisphere";
    case Warp::UniformSphere: return "UniformSphere";
    case Warp::UniformDisk: return "UniformDisk";
    case Warp::UniformTriangle: return "UniformTriangle";
  }
  return "";
}

// ---- The parameters each warp is judged in (raylab/testkit/warps.h) ----------------------

using testkit::intended_density;
using testkit::intended_pdf;
using testkit::is_direction_warp;
using testkit::is_hemisphere;

constexpr auto& parameters_of = testkit::warp_parameters;
constexpr auto& pdf_argument_at = testkit::warp_pdf_argument;
constexpr auto& jacobian_at = testkit::warp_jacobian;

const glm::vec3 kUnitTriangle[3] = {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)};

// Mistakes whose samples have a known density: if the samples fit one, its hint names it.
struct Mistake {
  std::function<double(double u, double v)> pdf;  // in the warp's own measure, as intended_pdf
  MessageId hint;                                  // with the placeholder {section}
};
std::vector<Mistake> sample_mistakes(Warp warp) {
  switch (warp) {
    case Warp::UniformHemisphere:
      return {{[](double, double v) { return v >= 0.0 ? v / kPiD : 0.0; },
               MessageId::sampling_hemisphere_cosine_samples}};
    case Warp::CosineHemisphere:
      return {{[](double, double v) { return v >= 0.0 ? 1.0 / kTwoPi : 0.0; },
               MessageId::sampling_cosine_uniform_samples}};
    case Warp::UniformSphere:
      return {{[](double, double v) { return v >= 0.0 ? 1.0 / kTwoPi : 0.0; },
               MessageId::sampling_sphere_upper_only}};
    case Warp::UniformDisk:
      return {{[](double, double v) { return v > 0.0 ? 1.0 / (kTwoPi * v) : 0.0; },
               MessageId::sampling_disk_no_sqrt}};
    case Warp::UniformTriangle:
      return {{[](double, double v) { return v > 0.0 ? 1.0 / v : 0.0; },
               MessageId::sampling_triangle_no_sqrt}};
  }
  return {};
}

// Mistaken densities a pdf may return (compared value by value with the student's).
std::vector<Mistake> pdf_mistakes(Warp warp) {
  switch (warp) {
    case Warp::UniformHemisphere:
      return {{[](double, double v) { return v >= 0.0 ? v / kPiD : 0.0; },
               MessageId::sampling_hemisphere_pdf_cosine}};
    case Warp::CosineHemisphere:
      return {{[](double, double v) { return v >= 0.0 ? 1.0 / kTwoPi : 0.0; },
               MessageId::sampling_cosine_pdf_uniform}};
    case Warp::UniformSphere: return {};
    case Warp::UniformDisk:
      return {{[](double, double v) { return v / kPiD; },
               MessageId::sampling_disk_pdf_jacobian}};
    case Warp::UniformTriangle: return {};
  }
  return {};
}

// ---- What the student's code returned, fetched once per warp -------------------------------

// Why a sample is outside its warp's domain: in short (a hint's {reason}) and with its numbers
// (the failure's).
struct DomainProblem {
  MessageId reason;  // sampling_reason_...
  Message detail;    // sampling_domain_...
};

struct WarpData {
  std::vector<glm::vec2> inputs;
  std::vector<glm::vec3> samples;
  std::size_t non_finite = 0, out_of_domain = 0;
  std::optional<std::size_t> first_non_finite, first_out_of_domain;
  std::optional<DomainProblem> out_of_domain_problem;  // of the first such sample
  std::size_t below_surface = 0;
  // The first kRepeated inputs asked again, in reverse order: the samples that differ from the
  // first answers (a warp is a function of its two numbers: no rand(), no state between calls).
  std::size_t not_repeated = 0;
  std::optional<std::size_t> first_not_repeated;
  glm::vec3 repeated_sample{0.0f};  // the second answer for that input
  testkit::Histogram2D histogram{1, 1, 0.0, 1.0, 0.0, 1.0};
  std::vector<double> expected;  // from the intended density
};

// Why a finite sample is outside its warp's domain, or nothing.
std::optional<DomainProblem> domain_problem(Warp warp, const glm::vec3& s) {
  if (is_direction_warp(warp)) {
    const float length = glm::length(s);
    if (std::fabs(length - 1.0f) > 1e-3f)
      return DomainProblem{MessageId::sampling_reason_not_unit,
                           {MessageId::sampling_domain_not_unit, {{"length", stream_text(length)}}}};
    if (is_hemisphere(warp) && s.z < -1e-5f)
      return DomainProblem{MessageId::sampling_reason_below_surface,
                           {MessageId::sampling_domain_below_surface, {{"z", stream_text(s.z)}}}};
    return std::nullopt;
  }
  if (warp == Warp::UniformDisk) {
    const float radius = std::sqrt(s.x * s.x + s.y * s.y);
    if (radius > 1.0f + 1e-5f)
      return DomainProblem{MessageId::sampling_reason_outside_disk,
                           {MessageId::sampling_domain_outside_disk, {{"radius", stream_text(radius)}}}};
    return std::nullopt;
  }
  if (s.x < -1e-6f || s.y < -1e-6f)
    return DomainProblem{MessageId::sampling_reason_outside_triangle,
                         {MessageId::sampling_domain_negative_barycentric,
                          {{"b1", stream_text(s.x)}, {"b2", stream_text(s.y)}}}};
  if (s.x + s.y > 1.0f + 1e-5f)
    return DomainProblem{MessageId::sampling_reason_outside_triangle,
                         {MessageId::sampling_domain_barycentrics_above_one, {{"sum", stream_text(s.x + s.y)}}}};
  return std::nullopt;
}

// The uniform inputs: the corners and middle of [0, 1)^2 first (where formulas meet 0, 1 and
// sqrt(0)), then random pairs from the warp's own stream.
std::vector<glm::vec2> inputs_of(Warp warp) {
  const float below_one = std::nextafter(1.0f, 0.0f);
  std::vector<glm::vec2> inputs = {{0.0f, 0.0f},      {0.0f, 0.5f},      {0.5f, 0.0f},      {0.5f, 0.5f},
                                   {below_one, 0.0f}, {0.0f, below_one}, {below_one, below_one}, {0.25f, 0.75f}};
  Pcg32 random(kSeed, testkit::stream_of(std::string(kStage) + "/" + warp_sample_function(warp)));
  while (inputs.size() < static_cast<std::size_t>(kSampleCount)) {
    const float a = random.next_float();
    const float b = random.next_float();
    inputs.push_back({a, b});
  }
  return inputs;
}

const WarpData& data_of(Warp warp) {
  static std::map<Warp, WarpData> cache;
  const auto found = cache.find(warp);
  if (found != cache.end()) return found->second;
  WarpData data;
  data.inputs = inputs_of(warp);
  data.samples = warp_samples(warp, data.inputs);  // throws NotImplemented for a stub: nothing cached
  constexpr std::size_t kRepeated = 1000;
  const std::vector<glm::vec2> again(data.inputs.rend() - kRepeated, data.inputs.rend());
  const std::vector<glm::vec3> answers = warp_samples(warp, again);
  for (std::size_t k = 0; k < kRepeated; ++k) {
    const std::size_t i = kRepeated - 1 - k;
    if (std::memcmp(&answers[k], &data.samples[i], sizeof(glm::vec3)) == 0) continue;
    ++data.not_repeated;
    if (!data.first_not_repeated || i < *data.first_not_repeated) {
      data.first_not_repeated = i;
      data.repeated_sample = answers[k];
    }
  }
  const testkit::WarpGrid g = testkit::warp_grid(warp);
  data.histogram = testkit::Histogram2D(g.columns, g.rows, g.u_min, g.u_max, g.v_min, g.v_max);
  for (std::size_t i = 0; i < data.samples.size(); ++i) {
    const glm::vec3& s = data.samples[i];
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z)) {
      ++data.non_finite;
      if (!data.first_non_finite) data.first_non_finite = i;
      data.histogram.add(NAN, NAN);
      continue;
    }
    if (std::optional<DomainProblem> problem = domain_problem(warp, s)) {
      ++data.out_of_domain;
      if (!data.first_out_of_domain) {
        data.first_out_of_domain = i;
        data.out_of_domain_problem = std::move(problem);
      }
    }
    if (is_hemisphere(warp) && s.z < -1e-5f) ++data.below_surface;
    const glm::dvec2 p = parameters_of(warp, s);
    data.histogram.add(p.x, p.y);
  }
  data.expected = data.histogram.expected_counts([warp](double u, double v) { return intended_density(warp, u, v); },
                                                 static_cast<double>(data.samples.size()), 4);
  return cache.emplace(warp, std::move(data)).first->second;
}

// The student's density at the quadrature points of every cell, and the expected counts from it.
struct PdfData {
  std::vector<glm::dvec2> points;   // (u, v) of each quadrature point
  std::vector<float> values;        // the student's pdf there
  std::vector<double> expected;     // counts per cell from the student's pdf
  double integral = 0;              // of the student's pdf over the grid's domain
  float unit_triangle_pdf = 0;      // the triangle: the pdf of the unit triangle
};

const PdfData& pdf_data_of(Warp warp) {
  static std::map<Warp, PdfData> cache;
  const auto found = cache.find(warp);
  if (found != cache.end()) return found->second;
  const WarpData& samples = data_of(warp);
  PdfData data;
  // First pass: where the quadrature asks; then one bulk call; then the same pass with the answers.
  samples.histogram.expected_counts(
      [&](double u, double v) {
        data.points.push_back({u, v});
        return 0.0;
      },
      1.0, 4);
  if (warp == Warp::UniformTriangle) {
    data.unit_triangle_pdf = warp_pdfs(warp, {kUnitTriangle[0], kUnitTriangle[1], kUnitTriangle[2]}).at(0);
    data.values.assign(data.points.size(), data.unit_triangle_pdf);
  } else {
    std::vector<glm::vec3> arguments;
    arguments.reserve(data.points.size());
    for (const glm::dvec2& p : data.points) arguments.push_back(pdf_argument_at(warp, p.x, p.y));
    data.values = warp_pdfs(warp, arguments);
  }
  std::size_t next = 0;
  const double count = static_cast<double>(samples.samples.size());
  data.expected = samples.histogram.expected_counts(
      [&](double u, double v) {
        const float value = data.values[next++];
        // A NaN or negative density is reported apart; here it counts as nothing.
        return std::isfinite(value) && value > 0.0f ? value * jacobian_at(warp, u, v) : 0.0;
      },
      count, 4);
  for (const double e : data.expected) data.integral += e / count;
  return cache.emplace(warp, std::move(data)).first->second;
}

// A number with `digits` significant digits ("0.25", "1.047e-05").
std::string digits_text(double value, int digits) {
  std::ostringstream text;
  text.precision(digits);
  text << value;
  return text.str();
}

// A warp's value in the failure texts: a direction as it is, a disk point by (x, y), a triangle
// point by its barycentrics.
std::string point_text(Warp warp, const glm::vec3& p) {
  if (warp == Warp::UniformDisk) return "(" + stream_text(p.x) + ", " + stream_text(p.y) + ")";
  if (warp == Warp::UniformTriangle) return "b1 " + stream_text(p.x) + ", b2 " + stream_text(p.y);
  return stream_text(p);
}

// The uniform numbers a warp was given, with all their digits (to replay them).
std::string input_text(const glm::vec2& u) {
  return "uniform_random = (" + digits_text(u.x, 9) + ", " + digits_text(u.y, 9) + ")";
}

// A number with 4 significant digits, as the hints give factors and the chi-square verdicts their numbers.
std::string four_digits(double value) { return digits_text(value, 4); }

// A chi-square test's verdict in words: why it failed (the {reason} of a failure) ...
Message chi_square_reason(const testkit::ChiSquareResult& result, const std::vector<double>& expected) {
  switch (result.failure) {
    case testkit::ChiSquareFailure::invalid_expected: {
      std::size_t cell = 0;
      while (cell + 1 < expected.size() && expected[cell] >= 0.0 && std::isfinite(expected[cell])) ++cell;
      return {MessageId::chi_square_invalid_expected,
              {{"cell", std::to_string(cell)}, {"value", four_digits(expected.empty() ? 0.0 : expected[cell])}}};
    }
    case testkit::ChiSquareFailure::samples_where_none_expected:
      return {MessageId::chi_square_samples_where_none_expected,
              {{"count", four_digits(result.samples_where_none_expected)}}};
    case testkit::ChiSquareFailure::too_few_samples:
      return {MessageId::chi_square_too_few_samples, {{"minimum", four_digits(result.min_expected_count)}}};
    case testkit::ChiSquareFailure::misfit:
    case testkit::ChiSquareFailure::none: break;
  }
  return {MessageId::chi_square_misfit,
          {{"p_value", four_digits(result.p_value)}, {"level", four_digits(result.significance_level)}}};
}

// ... and its figures (the {chi_square} of a failure); what they mean, only with the grading's
// first chi-square failure: a student reads it once, not once per warp.
Message chi_square_summary(const testkit::ChiSquareResult& result) {
  static bool explained = false;
  std::vector<Message> pooled, none_expected, explanation;
  if (!explained) explanation.push_back(MessageId::chi_square_explained);
  explained = true;
  if (result.pooled_cells)
    pooled.push_back({MessageId::chi_square_pooled, {{"count", std::to_string(result.pooled_cells)}}});
  if (result.samples_where_none_expected > 0)
    none_expected.push_back(
        {MessageId::chi_square_none_expected, {{"count", four_digits(result.samples_where_none_expected)}}});
  return {MessageId::chi_square_summary,
          {{"statistic", four_digits(result.statistic)},
           {"degrees_of_freedom", std::to_string(result.degrees_of_freedom)},
           {"p_value", four_digits(result.p_value)},
           {"level", four_digits(result.significance_level)},
           {"cells", std::to_string(result.cells)},
           {"pooled", pooled},
           {"observed", four_digits(result.observed_total)},
           {"expected", four_digits(result.expected_total)},
           {"none_expected", none_expected},
           {"explained", explanation}}};
}

// ---- The histogram picture -------------------------------------------------------------------

// black -> red -> yellow -> white as value goes 0 -> 1 (clamped).
glm::vec3 heat(double value) {
  const float x = static_cast<float>(std::clamp(value, 0.0, 1.0)) * 3.0f;
  return glm::vec3(std::min(1.0f, x), std::clamp(x - 1.0f, 0.0f, 1.0f), std::clamp(x - 2.0f, 0.0f, 1.0f));
}

// <output>/07_sampling-<warp>.png: the student's samples per pixel | the count the intended
// density expects there (and each half on its own: -yours.png, -intended.png), on one colour scale (white = twice the domain's mean). Directions are
// drawn by (phi across, z = cos theta up: an equal-area map, so a uniform warp looks flat),
// disk points as they are, triangle points by (b1 across, b2 up). Returns the path, or why it
// could not be written (a build without image I/O, a folder that cannot be written): the picture
// only illustrates; the verdict never depends on it.
struct HistogramPicture {
  std::string path;    // if written
  std::string reason;  // else: why not
};
HistogramPicture write_histogram_picture(Warp warp, const WarpData& data) {
  const bool directions = is_direction_warp(warp);
  const int width = directions ? 128 : 96, height = directions ? 64 : 96, scale = 2, gap = 6;
  std::vector<double> counts(static_cast<std::size_t>(width) * height, 0.0), expected(counts.size(), 0.0);
  // The picture's coordinates of a sample, in [0, 1)^2 (y up).
  auto picture_xy = [&](const glm::vec3& s) -> glm::dvec2 {
    if (directions) {
      const glm::dvec2 p = parameters_of(warp, s);
      return {p.x / kTwoPi, (p.y + 1.0) / 2.0};
    }
    if (warp == Warp::UniformDisk) return {(s.x + 1.0) / 2.0, (s.y + 1.0) / 2.0};
    return {s.x, s.y};
  };
  for (const glm::vec3& s : data.samples) {
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z)) continue;
    const glm::dvec2 p = picture_xy(s);
    const int x = static_cast<int>(std::floor(p.x * width)), y = static_cast<int>(std::floor(p.y * height));
    if (x >= 0 && x < width && y >= 0 && y < height) counts[static_cast<std::size_t>(y) * width + x] += 1.0;
  }
  // Expected: the intended density at 4 x 4 points of each pixel, times the pixel's measure.
  const double n = static_cast<double>(data.samples.size());
  double sum = 0, nonzero = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double mean_pdf = 0;
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
          const double px = (x + (i + 0.5) / 4.0) / width, py = (y + (j + 0.5) / 4.0) / height;
          if (directions) {
            mean_pdf += intended_pdf(warp, px * kTwoPi, 2.0 * py - 1.0);
          } else if (warp == Warp::UniformDisk) {
            const double dx = 2.0 * px - 1.0, dy = 2.0 * py - 1.0;
            mean_pdf += dx * dx + dy * dy <= 1.0 ? 1.0 / kPiD : 0.0;
          } else {
            mean_pdf += px + py <= 1.0 ? 2.0 : 0.0;
          }
        }
      mean_pdf /= 16.0;
      const double measure = directions ? (kTwoPi / width) * (2.0 / height)
                                        : warp == Warp::UniformDisk ? (2.0 / width) * (2.0 / height)
                                                                    : (1.0 / width) * (1.0 / height);
      const double e = n * mean_pdf * measure;
      expected[static_cast<std::size_t>(y) * width + x] = e;
      if (e > 0) {
        sum += e;
        ++nonzero;
      }
    }
  const double white = nonzero > 0 ? 2.0 * sum / nonzero : 1.0;
  Image picture(2 * width * scale + gap, height * scale, glm::vec3(0.35f));
  Image yours(width * scale, height * scale), intended(width * scale, height * scale);  // the halves, for the HTML report
  for (int y = 0; y < height * scale; ++y)
    for (int x = 0; x < width * scale; ++x) {
      const std::size_t cell = static_cast<std::size_t>(height - 1 - y / scale) * width + x / scale;  // y up
      picture.at(x, y) = yours.at(x, y) = heat(counts[cell] / white);
      picture.at(x + width * scale + gap, y) = intended.at(x, y) = heat(expected[cell] / white);
    }
  const std::string directory = output_directory();
  const std::string name = std::string(kStage) + "-" + file_name(warp);
  const std::string path = directory + "/" + name + ".png";
  try {
    std::filesystem::create_directories(directory);
    write_image(picture, path);
    write_image(yours, directory + "/" + name + "-yours.png");
    write_image(intended, directory + "/" + name + "-intended.png");
  } catch (const std::exception& e) {
    return {"", e.what()};
  }
  add_image({name + "-yours.png", name + "-intended.png", "", MessageId::report_your_samples, MessageId::report_intended_density});
  return {path, ""};
}

// ---- The tests -------------------------------------------------------------------------------

void hint_non_finite(Warp warp, const WarpData& data) {
  if (!data.first_non_finite) return;
  const std::size_t i = *data.first_non_finite;
  const glm::vec3& s = data.samples[i];
  const float bad = !std::isfinite(s.x) ? s.x : !std::isfinite(s.y) ? s.y : s.z;
  hint_if_not_finite(std::string(warp_sample_function(warp)) + "(" + input_text(data.inputs[i]) + ")", {bad},
                     {MessageId::sampling_not_finite_advice, {handout_section(warp)}});
}

Message below_surface_hint(Warp warp, const WarpData& data) {
  return {MessageId::sampling_below_surface,
          {{"count", std::to_string(data.below_surface)}, {"total", std::to_string(data.samples.size())}, handout_section(warp)}};
}

void expect_samples_in_domain(Warp warp) {
  const WarpData& data = data_of(warp);
  hint_non_finite(warp, data);
  if (data.below_surface > 0)
    add_hint(below_surface_hint(warp, data));
  else if (data.first_out_of_domain && warp == Warp::UniformTriangle)
    add_hint({MessageId::sampling_triangle_outside, {handout_section(warp)}});
  else if (data.first_out_of_domain && is_direction_warp(warp))
    add_hint({MessageId::sampling_not_unit, {handout_section(warp)}});
  else if (data.first_out_of_domain)
    add_hint({MessageId::sampling_disk_outside, {handout_section(warp)}});
  if (data.first_non_finite)
    add_failure({MessageId::sampling_failure_not_finite,
                 {{"sampler", warp_sample_function(warp)},
                  {"input", input_text(data.inputs[*data.first_non_finite])},
                  {"sample", gtest_text(data.samples[*data.first_non_finite])},
                  {"count", std::to_string(data.non_finite)},
                  {"total", std::to_string(data.samples.size())}}});
  if (data.first_out_of_domain)
    add_failure({MessageId::sampling_failure_out_of_domain,
                 {{"sampler", warp_sample_function(warp)},
                  {"input", input_text(data.inputs[*data.first_out_of_domain])},
                  {"point", point_text(warp, data.samples[*data.first_out_of_domain])},
                  {"reason", data.out_of_domain_problem->detail},
                  {"count", std::to_string(data.out_of_domain)},
                  {"total", std::to_string(data.samples.size())}}});
  if (data.first_not_repeated)
    add_failure({MessageId::sampling_failure_not_repeatable,
                 {{"sampler", warp_sample_function(warp)},
                  {"input", input_text(data.inputs[*data.first_not_repeated])},
                  {"first", point_text(warp, data.samples[*data.first_not_repeated])},
                  {"second", point_text(warp, data.repeated_sample)},
                  {"count", std::to_string(data.not_repeated)},
                  {"total", "1000"}}});
}

testkit::ChiSquareResult chi_square_against(const WarpData& data, const std::vector<double>& expected) {
  return testkit::chi_square_test(data.histogram.counts(), expected, kLevel);
}

// The fraction of finite samples whose v parameter is below `v_limit`.
double fraction_below(Warp warp, const WarpData& data, double v_limit) {
  double below = 0, finite = 0;
  for (const glm::vec3& s : data.samples) {
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z)) continue;
    ++finite;
    below += parameters_of(warp, s).y < v_limit;
  }
  return finite > 0 ? below / finite : 0.0;
}

// Names what the samples do instead of the intended density, when the intended test failed.
void diagnose_samples(Warp warp, const WarpData& data) {
  hint_non_finite(warp, data);
  if (data.below_surface > 0) {
    add_hint(below_surface_hint(warp, data));
    return;
  }
  if (data.first_out_of_domain) {
    add_hint({MessageId::sampling_outside_domain,
              {{"count", std::to_string(data.out_of_domain)}, {"total", std::to_string(data.samples.size())},
               {"reason", Message(data.out_of_domain_problem->reason)}, {"test", test_prefix(warp)}, handout_section(warp)}});
    return;
  }
  for (const Mistake& mistake : sample_mistakes(warp)) {
    const std::vector<double> expected = data.histogram.expected_counts(
        [&](double u, double v) { return mistake.pdf(u, v) * jacobian_at(warp, u, v); },
        static_cast<double>(data.samples.size()), 4);
    // Lenient: a mistake's density that the samples fit at 1e-6 names the mistake.
    if (testkit::chi_square_test(data.histogram.counts(), expected, 1e-6).passed) {
      add_hint({mistake.hint, {handout_section(warp)}});
      return;
    }
  }
  // Crowding, whatever its exact form: the disk's inner half radius and the triangle's corner
  // half towards p0 hold a quarter of the area, so a quarter of the samples.
  if (warp == Warp::UniformDisk || warp == Warp::UniformTriangle) {
    const double inner = fraction_below(warp, data, 0.5);
    if (inner > 0.27) {
      std::ostringstream percent;
      percent.precision(3);
      percent << 100.0 * inner;
      add_hint({warp == Warp::UniformDisk ? MessageId::sampling_disk_crowds_centre : MessageId::sampling_triangle_crowds_vertex,
                {{"percent", percent.str()}, handout_section(warp)}});
      return;
    }
  }
  if (is_direction_warp(warp)) {
    // Crowding the pole(s): theta uniform instead of z = cos(theta).
    double near_pole = 0, finite = 0;
    for (const glm::vec3& s : data.samples) {
      if (!std::isfinite(s.z)) continue;
      ++finite;
      near_pole += std::fabs(s.z) > 0.9f;
    }
    const double fraction = finite > 0 ? near_pole / finite : 0.0;
    const double intended = warp == Warp::CosineHemisphere ? 0.19 : 0.1;  // P(|z| > 0.9)
    if (fraction > intended + 0.04) {
      add_hint({MessageId::sampling_crowd_pole,
                {warp == Warp::UniformSphere ? MessageArg::bilingual("pole", "poles", "两极")
                                             : MessageArg::bilingual("pole", "pole", "极点"),
                 {"percent", std::to_string(static_cast<int>(100.0 * fraction + 0.5))},
                 {"expected", std::to_string(static_cast<int>(100.0 * intended + 0.5))}, handout_section(warp)}});
      return;
    }
  }
  add_hint({MessageId::sampling_wrong_density, {handout_section(warp)}});
}

void expect_intended_density(Warp warp) {
  const WarpData& data = data_of(warp);
  const HistogramPicture written = write_histogram_picture(warp, data);
  if (written.path.empty())
    add_note({MessageId::note_sampling_no_picture, {{"sampler", warp_sample_function(warp)}, {"reason", written.reason}}});
  else
    add_note({MessageId::note_sampling_picture, {{"sampler", warp_sample_function(warp)}, {"picture", written.path}}});
  const testkit::ChiSquareResult result = chi_square_against(data, data.expected);
  if (!result.passed) {
    diagnose_samples(warp, data);
    add_failure({MessageId::sampling_failure_intended_density,
                 {{"sampler", warp_sample_function(warp)},
                  {"count", std::to_string(data.samples.size())},
                  {"reason", chi_square_reason(result, data.expected)},
                  {"chi_square", chi_square_summary(result)},
                  {"level", gtest_text(kLevel)},
                  {"seed", std::to_string(kSeed)},
                  written.path.empty()
                      ? MessageArg{"picture", Message{MessageId::sampling_failure_no_picture, {{"reason", written.reason}}}}
                      : MessageArg{"picture", written.path}}});
  }
}

// Where the student's pdf and the intended one differ, in words, or "" if they agree.
struct PdfComparison {
  bool equals_intended = true;
  std::optional<double> constant_factor;  // student = factor x intended everywhere (factor != 1)
  std::optional<glm::dvec2> not_zero_outside;  // a point where intended is 0 and the student's is not
  std::optional<std::size_t> non_finite, negative;  // indices of points
  std::optional<MessageId> mistake_hint;
};

PdfComparison compare_pdf(Warp warp, const PdfData& pdf) {
  PdfComparison c;
  double low = INFINITY, high = -INFINITY, sum = 0, count = 0;
  for (std::size_t i = 0; i < pdf.points.size(); ++i) {
    const float value = pdf.values[i];
    const glm::dvec2 p = pdf.points[i];
    if (!std::isfinite(value)) {
      if (!c.non_finite) c.non_finite = i;
      c.equals_intended = false;
      continue;
    }
    if (value < 0.0f && !c.negative) c.negative = i;
    const double intended = intended_pdf(warp, p.x, p.y);
    if (intended == 0.0) {
      if (value != 0.0f) {
        if (!c.not_zero_outside) c.not_zero_outside = p;
        c.equals_intended = false;
      }
      continue;
    }
    const double ratio = value / intended;
    low = std::min(low, ratio);
    high = std::max(high, ratio);
    sum += ratio;
    ++count;
    if (std::fabs(ratio - 1.0) > 1e-3) c.equals_intended = false;
  }
  if (!c.equals_intended && count > 0 && low > 0 && high / low < 1.0 + 1e-3 && std::fabs(sum / count - 1.0) > 1e-3)
    c.constant_factor = sum / count;
  if (!c.equals_intended)
    for (const Mistake& mistake : pdf_mistakes(warp)) {
      bool same = true;
      for (std::size_t i = 0; i < pdf.points.size() && same; ++i) {
        const double expected = mistake.pdf(pdf.points[i].x, pdf.points[i].y);
        same = std::fabs(pdf.values[i] - expected) <= 1e-3 * std::max(expected, 1e-3);
      }
      if (same) {
        c.mistake_hint = mistake.hint;
        break;
      }
    }
  return c;
}

void hint_pdf(Warp warp, const PdfData& pdf, const PdfComparison& c) {
  const MessageArg section = handout_section(warp);
  const MessageArg function{"function", warp_pdf_function(warp)};
  if (c.non_finite) {
    const float value = pdf.values[*c.non_finite];
    hint_if_not_finite(std::string(warp_pdf_function(warp)) + "(" +
                           point_text(warp, pdf_argument_at(warp, pdf.points[*c.non_finite].x, pdf.points[*c.non_finite].y)) + ")",
                       {value}, {MessageId::sampling_pdf_not_finite_advice, {section}});
  }
  if (c.negative) add_hint({MessageId::sampling_pdf_negative, {function, section}});
  if (c.not_zero_outside)
    add_hint({MessageId::sampling_pdf_not_zero_outside,
              {function,
               {"point", point_text(warp, pdf_argument_at(warp, c.not_zero_outside->x, c.not_zero_outside->y))},
               is_hemisphere(warp) ? MessageArg::bilingual("below", ", below the surface", "，在表面以下")
                                   : MessageArg{"below", ""},
               section}});
  if (c.mistake_hint) {
    add_hint({*c.mistake_hint, {section}});
  } else if (c.constant_factor && warp == Warp::UniformTriangle) {
    add_hint({MessageId::sampling_unit_triangle_pdf, {{"value", four_digits(pdf.unit_triangle_pdf)}, section}});
  } else if (c.constant_factor) {
    add_hint({MessageId::sampling_pdf_constant_factor,
              {function, {"factor", four_digits(*c.constant_factor)},
               is_direction_warp(warp) ? MessageArg::bilingual("measure", "solid angle", "立体角")
                                       : MessageArg::bilingual("measure", "area", "面积"),
               section}});
  }
}

// Points outside the unit disk, where uniform_disk_pdf must be 0.
const std::vector<glm::vec3> kOutsideDisk = {{1.05f, 0, 0}, {0, -1.5f, 0}, {2.0f, 2.0f, 0}, {-0.8f, 0.8f, 0}};

// Triangles of every size and shape, on which uniform_triangle_pdf x area must be 1, and the
// student's values there (fetched once).
struct TrianglePdfCases {
  std::vector<glm::vec3> corners;  // three per triangle
  std::vector<float> areas, values;
  bool integrates_to_one(std::size_t i) const {
    const double integral = static_cast<double>(values[i]) * areas[i];
    return std::isfinite(integral) && std::fabs(integral - 1.0) <= 1e-3;
  }
};
const TrianglePdfCases& triangle_pdf_cases() {
  static const TrianglePdfCases cases = [] {  // a stub throws: nothing kept, asked again next time
    TrianglePdfCases t;
    Pcg32 random(kSeed, testkit::stream_of(std::string(kStage) + "/triangles"));
    for (int i = 0; i < 64; ++i) {
      const float size = std::pow(10.0f, random.uniform(-2.0f, 2.0f));
      const glm::vec3 p0 = testkit::random_vec3(random, -10.0f, 10.0f);
      const glm::vec3 p1 = p0 + size * testkit::random_vec3(random, -1.0f, 1.0f);
      const glm::vec3 p2 = p0 + size * testkit::random_vec3(random, -1.0f, 1.0f);
      const float area = 0.5f * glm::length(glm::cross(p1 - p0, p2 - p0));
      if (!(area > 1e-6f * size * size)) continue;
      t.corners.insert(t.corners.end(), {p0, p1, p2});
      t.areas.push_back(area);
    }
    t.values = warp_pdfs(Warp::UniformTriangle, t.corners);
    return t;
  }();
  return cases;
}

void expect_pdf_integrates_to_one(Warp warp) {
  const MessageArg section = handout_section(warp);
  if (warp == Warp::UniformTriangle) {
    const TrianglePdfCases& cases = triangle_pdf_cases();
    const std::vector<glm::vec3>& corners = cases.corners;
    const std::vector<float>& areas = cases.areas;
    const std::vector<float>& values = cases.values;
    int failures = 0;
    bool returns_area = true, constant = true;
    const double first_ratio = static_cast<double>(values[0]) * areas[0];
    for (std::size_t i = 0; i < values.size(); ++i) {
      const double integral = static_cast<double>(values[i]) * areas[i];
      returns_area = returns_area && std::fabs(values[i] - areas[i]) <= 1e-3f * areas[i];
      constant = constant && std::fabs(integral - first_ratio) <= 1e-3 * std::fabs(first_ratio);
      if (cases.integrates_to_one(i)) continue;
      if (++failures <= 2)
        add_failure({MessageId::sampling_failure_triangle_pdf,
                     {{"p0", gtest_text(corners[3 * i])},
                      {"p1", gtest_text(corners[3 * i + 1])},
                      {"p2", gtest_text(corners[3 * i + 2])},
                      {"value", gtest_text(values[i])},
                      {"area", gtest_text(areas[i])},
                      {"integral", gtest_text(integral)}}});
    }
    if (failures == 0) return;
    if (hint_if_not_finite("uniform_triangle_pdf", {values[0]}, {MessageId::sampling_triangle_pdf_advice, {section}})) {
    } else if (returns_area) {
      add_hint({MessageId::sampling_triangle_pdf_is_area, {section}});
    } else if (constant) {
      add_hint({MessageId::sampling_triangle_pdf_constant_factor, {{"factor", four_digits(first_ratio)}, section}});
    } else {
      add_hint({MessageId::sampling_triangle_pdf_wrong, {section}});
    }
    add_failure({MessageId::sampling_failure_triangles,
                 {{"failures", std::to_string(failures)}, {"count", std::to_string(values.size())}}});
    return;
  }
  const PdfData& pdf = pdf_data_of(warp);
  const PdfComparison c = compare_pdf(warp, pdf);
  bool failed = false;
  if (!(std::fabs(pdf.integral - 1.0) <= 1e-3) || c.non_finite || c.negative) {
    failed = true;
    add_failure({MessageId::sampling_failure_pdf_integral,
                 {{"function", warp_pdf_function(warp)},
                  {"integral", gtest_text(pdf.integral)},
                  {"domain", Message(is_direction_warp(warp) ? MessageId::sampling_over_sphere : MessageId::sampling_over_disk)}}});
  }
  if (warp == Warp::UniformDisk) {
    // Outside the disk the density is 0.
    const std::vector<glm::vec3>& outside = kOutsideDisk;
    const std::vector<float> values = warp_pdfs(warp, outside);
    for (std::size_t i = 0; i < outside.size(); ++i)
      if (values[i] != 0.0f) {
        failed = true;
        add_hint({MessageId::sampling_disk_pdf_outside, {section}});
        add_failure({MessageId::sampling_failure_disk_pdf_outside,
                     {{"point", point_text(warp, outside[i])}, {"value", gtest_text(values[i])}}});
      }
  }
  if (failed) hint_pdf(warp, pdf, c);
}

// The density must be > 0 wherever the warp goes (the renderer divides by it): the student's pdf
// at up to 2000 of the samples in the warp's domain (none for the triangle, whose pdf takes no
// point), with their indices in the samples.
struct PdfAtSamples {
  std::vector<glm::vec3> arguments;
  std::vector<std::size_t> which;
  std::vector<float> values;
  bool all_positive() const {
    for (const float v : values)
      if (!(v > 0.0f) || !std::isfinite(v)) return false;
    return true;
  }
};
PdfAtSamples pdf_at_samples(Warp warp, const WarpData& data) {
  PdfAtSamples at;
  for (std::size_t i = 0; i < data.samples.size() && at.which.size() < 2000; i += 97) {
    const glm::vec3& s = data.samples[i];
    if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.z) || domain_problem(warp, s)) continue;
    if (warp == Warp::CosineHemisphere && s.z < 1e-3f) continue;  // at the rim the density itself goes to 0
    at.which.push_back(i);
    if (warp == Warp::UniformTriangle) continue;
    at.arguments.push_back(s);
  }
  if (warp != Warp::UniformTriangle && !at.arguments.empty()) at.values = warp_pdfs(warp, at.arguments);
  return at;
}

void expect_pdf_matches_samples(Warp warp) {
  const WarpData& data = data_of(warp);
  const PdfData& pdf = pdf_data_of(warp);
  const PdfComparison c = compare_pdf(warp, pdf);
  const PdfAtSamples at = pdf_at_samples(warp, data);
  const std::vector<glm::vec3>& arguments = at.arguments;
  const std::vector<std::size_t>& which = at.which;
  if (!at.values.empty()) {
    const std::vector<float>& values = at.values;
    for (std::size_t k = 0; k < values.size(); ++k)
      if (!(values[k] > 0.0f) || !std::isfinite(values[k])) {
        add_hint({MessageId::sampling_pdf_zero_at_sample,
                  {{"function", warp_pdf_function(warp)},
                   std::isnan(values[k])   ? MessageArg{"value", "NaN"}
                   : std::isinf(values[k]) ? MessageArg::bilingual("value", "infinity", "无穷大")
                                           : MessageArg{"value", "0"},
                   is_direction_warp(warp) ? MessageArg::bilingual("kind", "direction", "方向")
                                           : MessageArg::bilingual("kind", "point", "点"),
                   {"sampler", warp_sample_function(warp)}, handout_section(warp)}});
        add_failure({MessageId::sampling_failure_pdf_at_sample,
                     {{"function", warp_pdf_function(warp)},
                      {"point", point_text(warp, arguments[k])},
                      {"value", gtest_text(values[k])},
                      {"input", input_text(data.inputs[which[k]])}}});
        break;
      }
  }
  const testkit::ChiSquareResult result = chi_square_against(data, pdf.expected);
  if (result.passed) return;
  const bool samples_right = chi_square_against(data, data.expected).passed;
  if (c.equals_intended && !samples_right) {
    add_hint({MessageId::sampling_pdf_right_samples_wrong, {{"function", warp_pdf_function(warp)}, {"test", test_prefix(warp)}}});
  } else {
    hint_pdf(warp, pdf, c);
    if (!c.mistake_hint && !c.constant_factor && !c.not_zero_outside && !c.non_finite && !c.negative) {
      // Where the pdf and the histogram disagree most.
      const auto& counts = data.histogram.counts();
      std::size_t worst = 0;
      double worst_score = -1;
      for (std::size_t cell = 0; cell < counts.size(); ++cell) {
        const double e = std::max(pdf.expected[cell], 1.0);
        const double score = std::fabs(counts[cell] - pdf.expected[cell]) / std::sqrt(e);
        if (score > worst_score) worst_score = score, worst = cell;
      }
      const int column = static_cast<int>(worst % data.histogram.columns()), row = static_cast<int>(worst / data.histogram.columns());
      const double u = data.histogram.u_min() + (column + 0.5) * data.histogram.cell_width();
      const double v = data.histogram.v_min() + (row + 0.5) * data.histogram.cell_height();
      const double measure = data.histogram.cell_area() * jacobian_at(warp, u, v);
      std::ostringstream pdf_value, density;
      pdf_value.precision(3);
      density.precision(3);
      pdf_value << pdf.values[worst * 16];
      density << counts[worst] / (static_cast<double>(data.samples.size()) * measure);
      add_hint({MessageId::sampling_pdf_disagrees,
                {{"function", warp_pdf_function(warp)},
                 {"point", point_text(warp, warp == Warp::UniformTriangle
                                                ? glm::vec3(static_cast<float>(v * (1 - u)), static_cast<float>(v * u), 0.0f)
                                                : pdf_argument_at(warp, u, v))},
                 {"pdf", pdf_value.str()}, {"density", density.str()},
                 warp == Warp::UniformTriangle ? MessageArg::bilingual("unit_triangle", " (on the unit triangle)", "（在单位三角形上）")
                                               : MessageArg{"unit_triangle", ""},
                 handout_section(warp)}});
    }
  }
  add_failure({MessageId::sampling_failure_pdf_matches,
               {{"sampler", warp_sample_function(warp)},
                {"function", warp_pdf_function(warp)},
                {"reason", chi_square_reason(result, pdf.expected)},
                {"chi_square", chi_square_summary(result)},
                {"level", gtest_text(kLevel)},
                {"seed", std::to_string(kSeed)}}});
}

// Each warp: its samples in their domain (1 point), following the intended density (2), its pdf
// integrating to 1 (1) and describing its samples (2).
GRADED_TEST(kStage, Stage07Sampling, UniformHemisphereSamplesInDomain, 1) { expect_samples_in_domain(Warp::UniformHemisphere); }
GRADED_TEST(kStage, Stage07Sampling, UniformHemisphereFollowsIntendedDensity, 2) { expect_intended_density(Warp::UniformHemisphere); }
GRADED_TEST(kStage, Stage07Sampling, UniformHemispherePdfIntegratesToOne, 1) { expect_pdf_integrates_to_one(Warp::UniformHemisphere); }
GRADED_TEST(kStage, Stage07Sampling, UniformHemispherePdfMatchesSamples, 2) { expect_pdf_matches_samples(Warp::UniformHemisphere); }

GRADED_TEST(kStage, Stage07Sampling, CosineHemisphereSamplesInDomain, 1) { expect_samples_in_domain(Warp::CosineHemisphere); }
GRADED_TEST(kStage, Stage07Sampling, CosineHemisphereFollowsIntendedDensity, 2) { expect_intended_density(Warp::CosineHemisphere); }
GRADED_TEST(kStage, Stage07Sampling, CosineHemispherePdfIntegratesToOne, 1) { expect_pdf_integrates_to_one(Warp::CosineHemisphere); }
GRADED_TEST(kStage, Stage07Sampling, CosineHemispherePdfMatchesSamples, 2) { expect_pdf_matches_samples(Warp::CosineHemisphere); }

GRADED_TEST(kStage, Stage07Sampling, UniformSphereSamplesInDomain, 1) { expect_samples_in_domain(Warp::UniformSphere); }
GRADED_TEST(kStage, Stage07Sampling, UniformSphereFollowsIntendedDensity, 2) { expect_intended_density(Warp::UniformSphere); }
GRADED_TEST(kStage, Stage07Sampling, UniformSpherePdfIntegratesToOne, 1) { expect_pdf_integrates_to_one(Warp::UniformSphere); }
GRADED_TEST(kStage, Stage07Sampling, UniformSpherePdfMatchesSamples, 2) { expect_pdf_matches_samples(Warp::UniformSphere); }

GRADED_TEST(kStage, Stage07Sampling, UniformDiskSamplesInDomain, 1) { expect_samples_in_domain(Warp::UniformDisk); }
GRADED_TEST(kStage, Stage07Sampling, UniformDiskFollowsIntendedDensity, 2) { expect_intended_density(Warp::UniformDisk); }
GRADED_TEST(kStage, Stage07Sampling, UniformDiskPdfIntegratesToOne, 1) { expect_pdf_integrates_to_one(Warp::UniformDisk); }
GRADED_TEST(kStage, Stage07Sampling, UniformDiskPdfMatchesSamples, 2) { expect_pdf_matches_samples(Warp::UniformDisk); }

GRADED_TEST(kStage, Stage07Sampling, UniformTriangleSamplesInDomain, 1) { expect_samples_in_domain(Warp::UniformTriangle); }
GRADED_TEST(kStage, Stage07Sampling, UniformTriangleFollowsIntendedDensity, 2) { expect_intended_density(Warp::UniformTriangle); }
GRADED_TEST(kStage, Stage07Sampling, UniformTrianglePdfIntegratesToOne, 1) { expect_pdf_integrates_to_one(Warp::UniformTriangle); }
GRADED_TEST(kStage, Stage07Sampling, UniformTrianglePdfMatchesSamples, 2) { expect_pdf_matches_samples(Warp::UniformTriangle); }

}  // namespace

}  // namespace raylab::grading
