// Autograder suite for stage 01_camera_rays (20 points).
#include "grading.h"
#include "support.h"

#include "raylab/stages/01_camera_rays.h"
#include "raylab/testkit/cameras.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "01_camera_rays";
const bool kRegistered = register_stage(kStage, [] { (void)generate_camera_ray(Camera{}, 0, 0); });

constexpr float kDirectionTolerance = 1e-4f;

using testkit::make_camera;

bool same_direction(const glm::vec3& a, const glm::vec3& b, float tolerance) {
  const float la = glm::length(a), lb = glm::length(b);
  if (!(la > 0.0f && lb > 0.0f)) return false;
  return glm::all(glm::lessThanEqual(glm::abs(a / la - b / lb), glm::vec3(tolerance)));
}

// ---- Diagnosis from a fitted model of the student's screen mapping -----------------------
//
// A handful of the student's rays, each turned back into the point where it crosses the image
// plane one unit in front of the eye (screen_x = d.right / d.forward, screen_y likewise with
// true_up), tell what the code computes on each axis. The handout's mapping is linear in the
// pixel index:
//   screen_x = extent_x * (2 (pixel_x + centre_x) / width  - 1)   extent_x = aspect * scale
//   screen_y = extent_y * (2 (pixel_y + centre_y) / height - 1)   extent_y = -scale (y flipped)
// with centre = 0.5. A least-squares fit of screen = slope * pixel + intercept (plus the other
// axis's pixel index, which must not matter) recovers the student's extent and centre on each
// axis; comparing them with the expected ones names every mistake at once: a factor 2, a
// missing pixel centre, the aspect ratio, the field of view, a flipped axis. A fit that does not
// match a flat plane means the basis (forward, right, true_up) is wrong.

// Rays on a 5 x 5 grid of pixels, corners and centre included.
constexpr int kFitSamples = 5;
// The probe camera has the failing camera's position and orientation, and a size and field of
// view chosen so that no two combinations of the mistakes below give the same extents (the
// closest two differ by 1.7%): aspect 1.6, scale = tan(25 degrees).
constexpr int kProbeWidth = 48, kProbeHeight = 30;
constexpr float kProbeFovDegrees = 50.0f;
constexpr double kExtentTolerance = 2e-3;  // relative; a float computation is good to 1e-5
constexpr double kCentreTolerance = 0.02;  // pixels

struct AxisFit {
  double extent = 0.0;       // signed half-size of the screen on this axis
  double centre = 0.0;       // where in the pixel the ray goes: 0.5 is the centre
  double other_axis = 0.0;   // change per pixel along the other axis (0 for a right basis)
};

struct ScreenFit {
  bool finite = true, in_front = true, flat = true;
  glm::ivec2 non_finite_pixel{0, 0};
  AxisFit x, y;
};

// Least squares of value = c0 + c1 * a + c2 * b over the samples (normal equations, 3 x 3).
glm::dvec3 fit_plane(const std::vector<glm::dvec3>& samples /* a, b, value */) {
  glm::dmat3 normal(0.0);
  glm::dvec3 rhs(0.0);
  for (const glm::dvec3& s : samples) {
    const glm::dvec3 basis(1.0, s.x, s.y);
    normal += glm::outerProduct(basis, basis);
    rhs += basis * s.z;
  }
  return glm::inverse(normal) * rhs;
}

ScreenFit fit_screen_mapping(const Camera& camera) {
  const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.look_at - camera.position));
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
  const glm::dvec3 true_up = glm::cross(right, forward);
  ScreenFit fit;
  std::vector<glm::dvec3> x_samples, y_samples;
  for (int row = 0; row < kFitSamples; ++row)
    for (int column = 0; column < kFitSamples; ++column) {
      const int pixel_x = column * (camera.width - 1) / (kFitSamples - 1);
      const int pixel_y = row * (camera.height - 1) / (kFitSamples - 1);
      const glm::vec3 direction = generate_camera_ray(camera, pixel_x, pixel_y).direction;
      if (!is_finite(direction)) {
        fit.finite = false;
        fit.non_finite_pixel = {pixel_x, pixel_y};
        return fit;
      }
      const glm::dvec3 d(direction);
      const double along = glm::dot(d, forward);
      if (!(along > 1e-6 * glm::length(d))) {
        fit.in_front = false;
        return fit;
      }
      x_samples.emplace_back(pixel_x, pixel_y, glm::dot(d, right) / along);
      y_samples.emplace_back(pixel_y, pixel_x, glm::dot(d, true_up) / along);
    }
  auto axis = [](const std::vector<glm::dvec3>& samples, int size, bool& flat) {
    const glm::dvec3 c = fit_plane(samples);
    AxisFit a;
    a.extent = c[1] * size / 2.0;
    a.centre = c[1] != 0.0 ? c[0] / c[1] + size / 2.0 : 0.0;
    a.other_axis = c[2];
    double worst = 0.0;
    for (const glm::dvec3& s : samples) worst = std::max(worst, std::fabs(c[0] + c[1] * s.x + c[2] * s.y - s.z));
    if (!(worst <= 1e-3 * (std::fabs(c[0]) + std::fabs(a.extent) + 1e-3))) flat = false;
    return a;
  };
  fit.x = axis(x_samples, camera.width, fit.flat);
  fit.y = axis(y_samples, camera.height, fit.flat);
  return fit;
}

bool close_ratio(double got, double expected) { return std::fabs(got - expected) <= kExtentTolerance * std::fabs(expected); }

// The hints for the extents: every combination of the screen-size, field-of-view and aspect
// mistakes and the flips is tried; the one that explains both axes with the fewest mistakes wins.
std::vector<Message> name_extent_mistakes(const Camera& camera, const ScreenFit& fit) {
  const double aspect = static_cast<double>(camera.width) / camera.height;
  const double half_angle = glm::radians(static_cast<double>(camera.fov_y_degrees)) / 2.0;
  const double scale = std::tan(half_angle);
  const double degrees = camera.fov_y_degrees;
  const double ratio_x = fit.x.extent / (aspect * scale), ratio_y = fit.y.extent / -scale;
  struct Mistake {
    double x, y;         // what it multiplies each axis's extent by
    std::optional<MessageId> hint;  // none: no mistake
  };
  const Mistake sizes[] = {
      {1.0, 1.0, std::nullopt},
      {0.5, 0.5, MessageId::camera_half_size_screen},
  };
  const Mistake fovs[] = {
      {1.0, 1.0, std::nullopt},
      {std::tan(2.0 * half_angle) / scale, std::tan(2.0 * half_angle) / scale, MessageId::camera_fov_not_halved},
      {std::tan(degrees / 2.0) / scale, std::tan(degrees / 2.0) / scale, MessageId::camera_fov_in_degrees},
      {std::tan(degrees) / scale, std::tan(degrees) / scale, MessageId::camera_fov_in_degrees_not_halved},
      {1.0 / scale, 1.0 / scale, MessageId::camera_fov_ignored},
  };
  const Mistake aspects[] = {
      {1.0, 1.0, std::nullopt},
      {1.0 / aspect, 1.0, MessageId::camera_aspect_missing},
      {1.0 / (aspect * aspect), 1.0, MessageId::camera_aspect_inverted},
      {1.0 / aspect, aspect, MessageId::camera_aspect_on_y},
      {1.0, aspect, MessageId::camera_aspect_on_both},
      {1.0 / aspect, 1.0 / aspect, MessageId::camera_aspect_on_y_inverted},
  };
  const Mistake flips_x[] = {
      {1.0, 1.0, std::nullopt},
      {-1.0, 1.0, MessageId::camera_mirrored},
  };
  const Mistake flips_y[] = {
      {1.0, 1.0, std::nullopt},
      {1.0, -1.0, MessageId::camera_upside_down},
  };
  std::vector<Message> best;
  bool found = false;
  for (const Mistake& size : sizes)
    for (const Mistake& fov : fovs)
      for (const Mistake& aspect_mistake : aspects)
        for (const Mistake& flip_x : flips_x)
          for (const Mistake& flip_y : flips_y) {
            const Mistake* parts[] = {&size, &fov, &aspect_mistake, &flip_x, &flip_y};
            double x = 1.0, y = 1.0;
            std::vector<Message> hints;
            for (const Mistake* part : parts) {
              x *= part->x;
              y *= part->y;
              if (part->hint) hints.emplace_back(*part->hint);
            }
            if (!close_ratio(ratio_x, x) || !close_ratio(ratio_y, y)) continue;
            if (!found || hints.size() < best.size()) best = hints;
            found = true;
          }
  if (found) return best;
  // camera.up used as the up axis: perpendicular to the view but not unit length, it scales y.
  const double up_length = glm::length(glm::dvec3(camera.up));
  if (std::fabs(up_length - 1.0) > 1e-3 && close_ratio(ratio_x, 1.0) && close_ratio(std::fabs(ratio_y), up_length))
    return {{MessageId::camera_up_not_unit, {{"factor", std::to_string(up_length)}}}};
  std::vector<Message> also;
  if (fit.x.extent < 0.0) also.emplace_back(MessageId::camera_also_mirrored);
  if (fit.y.extent > 0.0) also.emplace_back(MessageId::camera_also_upside_down);
  return {{MessageId::camera_screen_size_wrong,
           {{"extent_x", stream_text(std::fabs(fit.x.extent))}, {"extent_y", stream_text(std::fabs(fit.y.extent))},
            {"width", std::to_string(camera.width)}, {"height", std::to_string(camera.height)},
            {"fov_y", stream_text(camera.fov_y_degrees)}, {"expected_x", stream_text(aspect * scale)},
            {"expected_y", stream_text(scale)}, {"also", also}}}};
}

// The hints for where in the pixel the rays go, per axis.
void name_centre_mistakes(const char* axis, const AxisFit& fit, int size, std::vector<Message>& hints) {
  const double centre = fit.centre;
  if (std::fabs(centre - 0.5) <= kCentreTolerance) return;
  if (std::fabs(centre) <= kCentreTolerance) {
    hints.emplace_back(MessageId::camera_pixel_centre_missing);
    return;
  }
  if (std::fabs(centre - (0.5 + size / 2.0)) <= kCentreTolerance || std::fabs(centre - size / 2.0) <= kCentreTolerance) {
    hints.push_back({MessageId::camera_screen_not_centred, {{"axis", axis}}});
    if (std::fabs(centre - size / 2.0) <= kCentreTolerance) hints.emplace_back(MessageId::camera_pixel_centre_missing);
    return;
  }
  hints.push_back({MessageId::camera_rays_shifted, {{"axis", axis}, {"centre", stream_text(centre)}}});
}

// All the differences between the student's mapping on `camera` and the handout's; empty when
// the fit finds none (the mistake is then somewhere else, e.g. the direction's length).
std::vector<Message> diagnose_mapping(const Camera& camera) {
  const ScreenFit fit = fit_screen_mapping(camera);
  if (!fit.finite)
    return {{MessageId::camera_direction_not_finite,
             {{"x", std::to_string(fit.non_finite_pixel.x)}, {"y", std::to_string(fit.non_finite_pixel.y)},
              {"width", std::to_string(camera.width)}, {"height", std::to_string(camera.height)}}}};
  const Message basis{MessageId::camera_basis_wrong, {{"also", ""}}};
  if (!fit.in_front) return {{MessageId::camera_basis_wrong, {{"also", Message(MessageId::camera_also_rays_behind)}}}};
  const double scale = std::tan(glm::radians(static_cast<double>(camera.fov_y_degrees)) / 2.0);
  const double pixel_size = 2.0 * scale / camera.height;  // on the plane at distance 1, both axes
  const bool mixed = std::fabs(fit.x.other_axis) > 1e-3 * pixel_size || std::fabs(fit.y.other_axis) > 1e-3 * pixel_size;
  if (!fit.flat || mixed) return {basis};
  std::vector<Message> hints;
  if (std::fabs(fit.x.extent) < 1e-9 || std::fabs(fit.y.extent) < 1e-9) {
    hints.push_back({MessageId::camera_integer_division, {{"axis", std::fabs(fit.x.extent) < 1e-9 ? "x" : "y"}}});
    return hints;
  }
  hints = name_extent_mistakes(camera, fit);
  name_centre_mistakes("x", fit.x, camera.width, hints);
  name_centre_mistakes("y", fit.y, camera.height, hints);
  return hints;
}

// A camera as the failure texts name it: the framework's operator<< (raylab/camera.h), in words of
// either language, each value as GoogleTest's stream writes it.
Message camera_text(const Camera& camera) {
  return {MessageId::camera_description,
          {{"position", gtest_text(camera.position)},
           {"look_at", gtest_text(camera.look_at)},
           {"up", gtest_text(camera.up)},
           {"fov_y", gtest_text(camera.fov_y_degrees)},
           {"width", gtest_text(camera.width)},
           {"height", gtest_text(camera.height)}}};
}

// Names the mistakes that make the student's ray `got` differ from `expected` on `camera`.
void diagnose(const Camera& camera, const glm::vec3& got, const glm::vec3& expected) {
  if (hint_if_not_finite("direction", {got.x, got.y, got.z}, MessageId::camera_advice_division_by_zero)) return;
  Camera probe = camera;
  probe.width = kProbeWidth;
  probe.height = kProbeHeight;
  probe.fov_y_degrees = kProbeFovDegrees;
  std::vector<Message> hints = diagnose_mapping(probe);
  if (hints.empty()) hints = diagnose_mapping(camera);  // a mistake that shows only at this camera's size
  for (const Message& hint : hints) add_hint(hint);
  const float length = glm::length(got);
  if (hints.empty() && std::fabs(length - 1.0f) > 1e-3f && glm::length(got / length - glm::normalize(expected)) < 1e-4f)
    add_hint({MessageId::camera_not_normalised_length, {{"length", std::to_string(length)}}});
}

void expect_camera_ray(const Camera& camera, int pixel_x, int pixel_y, const glm::vec3& expected_direction) {
  const Ray ray = generate_camera_ray(camera, pixel_x, pixel_y);
  const glm::vec3 expected = glm::normalize(expected_direction);
  const bool ok = glm::all(glm::lessThanEqual(glm::abs(ray.direction - expected), glm::vec3(kDirectionTolerance)));
  if (!ok) diagnose(camera, ray.direction, expected);
  if (!ok)
    add_failure({MessageId::camera_failure_ray,
                 {{"x", std::to_string(pixel_x)}, {"y", std::to_string(pixel_y)}, {"camera", camera_text(camera)},
                  {"expected", gtest_text(expected)}, {"tolerance", gtest_text(kDirectionTolerance)},
                  {"got", gtest_text(ray.direction)}}});
}

GRADED_TEST(kStage, Stage01CameraRays, CentrePixelLooksAtLookAt, 2) {
  // An odd-sized image has a pixel whose centre is the image centre: its ray is the view direction.
  Camera camera = make_camera(5, 3, 60.0f);
  camera.position = glm::vec3(1, 2, 3);
  camera.look_at = glm::vec3(4, 6, 3);
  expect_camera_ray(camera, 2, 1, camera.look_at - camera.position);
}

GRADED_TEST(kStage, Stage01CameraRays, CornersOfASmallImage, 4) {
  // 4x2 pixels, 90 degrees: scale = tan(45 deg) = 1, aspect = 2. Pixel (0, 0) has its centre at
  // NDC (0.125, 0.25), so screen (-0.75 * 2, 0.5) = (-1.5, 0.5) on the plane z = -1.
  const Camera camera = make_camera(4, 2, 90.0f);
  expect_camera_ray(camera, 0, 0, glm::vec3(-1.5f, 0.5f, -1.0f));
  expect_camera_ray(camera, 3, 0, glm::vec3(1.5f, 0.5f, -1.0f));
  expect_camera_ray(camera, 0, 1, glm::vec3(-1.5f, -0.5f, -1.0f));
  expect_camera_ray(camera, 3, 1, glm::vec3(1.5f, -0.5f, -1.0f));
}

GRADED_TEST(kStage, Stage01CameraRays, TopRowLooksUpLeftColumnLooksLeft, 2) {
  // The picture must be upright: row 0 is the top, column 0 the left.
  const Camera camera = make_camera(64, 48, 60.0f);
  const Ray top_left = generate_camera_ray(camera, 0, 0);
  if (!(top_left.direction.y > 0.0f && top_left.direction.x < 0.0f))
    diagnose(camera, top_left.direction, glm::vec3(-camera.aspect_ratio(), 1.0f, -1.0f));
  EXPECT_GT(top_left.direction.y, 0.0f)
      << failure_text({MessageId::camera_failure_top_left_up, {{"direction", gtest_text(top_left.direction)}}});
  EXPECT_LT(top_left.direction.x, 0.0f)
      << failure_text({MessageId::camera_failure_top_left_left, {{"direction", gtest_text(top_left.direction)}}});
}

GRADED_TEST(kStage, Stage01CameraRays, OriginAtCameraAndUnitDirection, 2) {
  Camera camera = make_camera(7, 5, 45.0f);
  camera.position = glm::vec3(-3, 0.5f, 9);
  camera.look_at = glm::vec3(0, 0, 0);
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      const Ray ray = generate_camera_ray(camera, x, y);
      ASSERT_EQ(ray.origin, camera.position)
          << failure_text({MessageId::camera_failure_origin, {{"x", std::to_string(x)}, {"y", std::to_string(y)}}});
      if (std::fabs(glm::length(ray.direction) - 1.0f) > 1e-4f)
        add_hint(MessageId::camera_not_normalised);
      ASSERT_NEAR(glm::length(ray.direction), 1.0f, 1e-4f)
          << failure_text({MessageId::camera_failure_length,
                           {{"x", std::to_string(x)}, {"y", std::to_string(y)}, {"direction", gtest_text(ray.direction)}}});
      ASSERT_EQ(ray.t_min, 0.0f) << failure_text(MessageId::camera_failure_t_min);
      ASSERT_EQ(ray.t_max, kInfinity) << failure_text(MessageId::camera_failure_t_max);
    }
}

GRADED_TEST(kStage, Stage01CameraRays, TurnedCamera, 3) {
  // Looking along +x with +z up: right = cross(forward, up) = cross(+x, +z) = -y.
  // 2x2, 90 degrees: pixel (0, 0) is screen (-0.5, 0.5) -> -0.5 right + 0.5 up + forward.
  Camera camera = make_camera(2, 2, 90.0f);
  camera.position = glm::vec3(10, 0, 0);
  camera.look_at = glm::vec3(20, 0, 0);
  camera.up = glm::vec3(0, 0, 3);  // not unit length on purpose
  expect_camera_ray(camera, 0, 0, glm::vec3(1.0f, 0.5f, 0.5f));
  expect_camera_ray(camera, 1, 1, glm::vec3(1.0f, -0.5f, -0.5f));
}

GRADED_TEST(kStage, Stage01CameraRays, RaysThroughOtherPointsOfThePixel, 2) {
  // Anti-aliasing aims at other points than the centre. 4x2 pixels, 90 degrees, aspect 2:
  // point (0, 0) of pixel (0, 0) is the image's top-left corner, NDC (0, 0), screen (-2, 1);
  // point (0.25, 0.75) of pixel (1, 0) is raster (1.25, 0.75), NDC (0.3125, 0.375), screen
  // (-0.75, 0.25).
  const Camera camera = make_camera(4, 2, 90.0f);
  struct Case {
    int pixel_x, pixel_y;
    glm::vec2 position_in_pixel;
    glm::vec3 expected;
  };
  const Case cases[] = {{0, 0, glm::vec2(0.0f, 0.0f), glm::vec3(-2.0f, 1.0f, -1.0f)},
                        {1, 0, glm::vec2(0.25f, 0.75f), glm::vec3(-0.75f, 0.25f, -1.0f)},
                        {3, 1, glm::vec2(0.9375f, 0.125f), glm::vec3(1.9375f, -0.125f, -1.0f)}};
  for (const Case& c : cases) {
    const glm::vec3 got = generate_camera_ray(camera, c.pixel_x, c.pixel_y, c.position_in_pixel).direction;
    const glm::vec3 expected = glm::normalize(c.expected);
    if (glm::all(glm::lessThanEqual(glm::abs(got - expected), glm::vec3(kDirectionTolerance)))) continue;
    if (same_direction(got, generate_camera_ray(camera, c.pixel_x, c.pixel_y).direction, kDirectionTolerance))
      add_hint(MessageId::camera_position_in_pixel_ignored);
    add_failure({MessageId::camera_failure_point_in_pixel,
                 {{"point", gtest_text(c.position_in_pixel)}, {"x", std::to_string(c.pixel_x)},
                  {"y", std::to_string(c.pixel_y)}, {"camera", camera_text(camera)}, {"expected", gtest_text(expected)},
                  {"tolerance", gtest_text(kDirectionTolerance)}, {"got", gtest_text(got)}}});
  }
}

GRADED_TEST(kStage, Stage01CameraRays, MatchesReferenceRays, 3) {
  // Seeded random cameras and pixels; the expected rays come from the reference solution.
  const nlohmann::json data = load_reference_cases("01_camera_rays");
  int failures = 0;
  for (const nlohmann::json& c : data.at("cases")) {
    Camera camera;
    camera.position = vec3_from_json(c.at("position"));
    camera.look_at = vec3_from_json(c.at("look_at"));
    camera.up = vec3_from_json(c.at("up"));
    camera.fov_y_degrees = c.at("fov_y_degrees").get<float>();
    camera.width = c.at("width").get<int>();
    camera.height = c.at("height").get<int>();
    const int x = c.at("pixel_x").get<int>(), y = c.at("pixel_y").get<int>();
    const glm::vec3 expected = vec3_from_json(c.at("direction"));
    const glm::vec3 got = generate_camera_ray(camera, x, y).direction;
    if (glm::all(glm::lessThanEqual(glm::abs(got - expected), glm::vec3(kDirectionTolerance)))) continue;
    if (++failures <= 3) {
      diagnose(camera, got, expected);
      add_failure({MessageId::camera_failure_reference,
                   {{"id", c.at("id").dump()}, {"x", std::to_string(x)}, {"y", std::to_string(y)},
                    {"camera", camera_text(camera)}, {"expected", gtest_text(expected)}, {"got", gtest_text(got)}}});
    }
  }
  EXPECT_EQ(failures, 0)
      << failure_text({MessageId::camera_failure_reference_count,
                 {{"failures", std::to_string(failures)}, {"count", std::to_string(data.at("cases").size())},
                  {"seed", seed_shown(data)}}});
}

GRADED_TEST(kStage, Stage01CameraRays, DirectionImageMatchesReference, 2) {
  // Every pixel's colour is its ray direction: (d + 1) / 2. Top is bluish-green, bottom darker.
  expect_image_matches_reference(kStage, 0.02f, 0.001);
}

}  // namespace
}  // namespace raylab::grading
