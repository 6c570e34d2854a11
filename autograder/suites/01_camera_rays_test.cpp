// Autograder suite for stage 01_camera_rays (20 points).
#include "grading.h"
#include "support.h"

#include "raylab/stages/01_camera_rays.h"

#include <cmath>
#include <sstream>

namespace raylab::grading {
namespace {

constexpr const char* kStage = "01_camera_rays";
const bool kRegistered = register_stage(kStage, [] { (void)generate_camera_ray(Camera{}, 0, 0); });

constexpr float kDirectionTolerance = 1e-4f;

Camera make_camera(int width, int height, float fov_y_degrees) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  camera.fov_y_degrees = fov_y_degrees;
  return camera;
}

bool same_direction(const glm::vec3& a, const glm::vec3& b, float tolerance) {
  const float la = glm::length(a), lb = glm::length(b);
  if (!(la > 0.0f && lb > 0.0f)) return false;
  return glm::all(glm::lessThanEqual(glm::abs(a / la - b / lb), glm::vec3(tolerance)));
}

// Names the common mistake that turns `expected` into `got`, if one does. Every candidate is
// built from the expected ray's screen position (x_s, y_s) on the plane one unit in front.
void diagnose(const Camera& camera, int pixel_x, int pixel_y, const glm::vec3& got, const glm::vec3& expected) {
  if (!is_finite(got)) {
    add_hint("the direction has NaN or infinite components: check for a division by zero");
    return;
  }
  const glm::vec3 forward = glm::normalize(camera.look_at - camera.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::vec3 true_up = glm::cross(right, forward);
  const glm::vec3 e = glm::normalize(expected);
  const float x_s = glm::dot(e, right) / glm::dot(e, forward);
  const float y_s = glm::dot(e, true_up) / glm::dot(e, forward);
  const float aspect = camera.aspect_ratio();
  const float half = degrees_to_radians(camera.fov_y_degrees) * 0.5f;
  const float scale = std::tan(half);
  auto direction = [&](float x, float y) { return x * right + y * true_up + forward; };
  const float pixel_w = 2.0f * aspect * scale / static_cast<float>(camera.width);
  const float pixel_h = 2.0f * scale / static_cast<float>(camera.height);
  (void)pixel_x;
  (void)pixel_y;

  if (same_direction(got, expected, kDirectionTolerance) && std::fabs(glm::length(got) - 1.0f) > 1e-3f) {
    add_hint("direction not normalised: the direction is right but its length is " + std::to_string(glm::length(got)) +
             "; return normalize(...) (docs/01_camera_rays.md, section 2)");
    return;
  }
  struct Candidate {
    glm::vec3 direction;
    const char* hint;
  };
  const Candidate candidates[] = {
      {direction(x_s, -y_s), "picture upside down: row 0 is the TOP of the image, so screen_y = (1 - 2 ndc_y) * scale (docs/01_camera_rays.md, section 2)"},
      {direction(-x_s, y_s), "picture mirrored left-right: column 0 is the LEFT edge, so screen_x = (2 ndc_x - 1) * aspect * scale, and right = cross(forward, up)"},
      {direction(x_s / aspect, y_s * aspect), "aspect ratio applied to y instead of x: multiply screen_x (not screen_y) by width / height"},
      {direction(x_s / (aspect * aspect), y_s), "aspect ratio inverted: aspect = width / height, not height / width"},
      {direction(x_s / aspect, y_s), "aspect ratio missing: multiply screen_x by aspect = width / height"},
      {direction(x_s * std::tan(2.0f * half) / scale, y_s * std::tan(2.0f * half) / scale),
       "field of view not halved: scale = tan(fov_y / 2), half the angle"},
      {direction(x_s * std::tan(camera.fov_y_degrees * 0.5f) / scale, y_s * std::tan(camera.fov_y_degrees * 0.5f) / scale),
       "field of view still in degrees: std::tan takes radians, use degrees_to_radians(camera.fov_y_degrees)"},
      {direction(x_s * std::tan(camera.fov_y_degrees) / scale, y_s * std::tan(camera.fov_y_degrees) / scale),
       "field of view in degrees and not halved: scale = tan(degrees_to_radians(fov_y) / 2)"},
      {direction(x_s - 0.5f * pixel_w, y_s + 0.5f * pixel_h),
       "pixel centre missing: aim through (pixel_x + 0.5, pixel_y + 0.5), the centre of the pixel, not its corner"},
      {direction(x_s / scale, y_s / scale), "field of view ignored: multiply the screen coordinates by scale = tan(fov_y / 2)"},
  };
  for (const Candidate& candidate : candidates)
    if (same_direction(got, candidate.direction, 2e-4f)) {
      add_hint(candidate.hint);
      return;
    }
}

void expect_camera_ray(const Camera& camera, int pixel_x, int pixel_y, const glm::vec3& expected_direction) {
  const Ray ray = generate_camera_ray(camera, pixel_x, pixel_y);
  const glm::vec3 expected = glm::normalize(expected_direction);
  const bool ok = glm::all(glm::lessThanEqual(glm::abs(ray.direction - expected), glm::vec3(kDirectionTolerance)));
  if (!ok) diagnose(camera, pixel_x, pixel_y, ray.direction, expected);
  if (!ok) ADD_FAILURE() << "pixel (" << pixel_x << ", " << pixel_y << ") of a " << camera << ":\n  expected direction "
                  << expected << " (each component within " << kDirectionTolerance << ")\n  got               "
                  << ray.direction;
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
  if (top_left.direction.y < 0) add_hint("picture upside down: row 0 is the TOP of the image (docs/01_camera_rays.md, section 2)");
  if (top_left.direction.x > 0) add_hint("picture mirrored left-right: column 0 is the LEFT edge");
  EXPECT_GT(top_left.direction.y, 0.0f) << "the ray of pixel (0, 0), top left, must point up: got " << top_left.direction;
  EXPECT_LT(top_left.direction.x, 0.0f) << "the ray of pixel (0, 0), top left, must point left: got " << top_left.direction;
}

GRADED_TEST(kStage, Stage01CameraRays, OriginAtCameraAndUnitDirection, 2) {
  Camera camera = make_camera(7, 5, 45.0f);
  camera.position = glm::vec3(-3, 0.5f, 9);
  camera.look_at = glm::vec3(0, 0, 0);
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) {
      const Ray ray = generate_camera_ray(camera, x, y);
      ASSERT_EQ(ray.origin, camera.position) << "pixel (" << x << ", " << y << "): the ray must start at the camera";
      if (std::fabs(glm::length(ray.direction) - 1.0f) > 1e-4f)
        add_hint("direction not normalised: return normalize(...) (docs/01_camera_rays.md, section 2)");
      ASSERT_NEAR(glm::length(ray.direction), 1.0f, 1e-4f) << "pixel (" << x << ", " << y << "): direction " << ray.direction;
      ASSERT_EQ(ray.t_min, 0.0f) << "leave t_min at 0";
      ASSERT_EQ(ray.t_max, kInfinity) << "leave t_max at infinity";
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
      add_hint("position_in_pixel ignored: aim through raster point (pixel_x + position_in_pixel.x, pixel_y + "
               "position_in_pixel.y); (0.5, 0.5) is only the centre (docs/01_camera_rays.md, section 2)");
    ADD_FAILURE() << "point " << c.position_in_pixel << " of pixel (" << c.pixel_x << ", " << c.pixel_y << ") of a "
                  << camera << ":\n  expected direction " << expected << " (each component within "
                  << kDirectionTolerance << ")\n  got               " << got;
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
      diagnose(camera, x, y, got, expected);
      ADD_FAILURE() << "case " << c.at("id") << ", pixel (" << x << ", " << y << ") of a " << camera
                    << ":\n  expected direction " << expected << "\n  got               " << got;
    }
  }
  EXPECT_EQ(failures, 0) << failures << " of " << data.at("cases").size() << " reference rays differ (seed "
                         << data.at("seed") << "); the first are shown above";
}

GRADED_TEST(kStage, Stage01CameraRays, DirectionImageMatchesReference, 2) {
  // Every pixel's colour is its ray direction: (d + 1) / 2. Top is bluish-green, bottom darker.
  expect_image_matches_reference(kStage, 0.02f, 0.001);
}

}  // namespace
}  // namespace raylab::grading
