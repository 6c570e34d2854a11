// 01_camera_rays: the reference generate_camera_ray, and validate_camera.
//
// Conventions (camera.h, docs/01_camera_rays.md): pixel (i, j) has its centre at
// (i + 0.5, j + 0.5), row 0 at the top; the camera looks down -z with +y up; fov_y_degrees is
// the full vertical angle; aspect = width / height stretches x only. The image plane is at
// distance 1, so with fov 90 it spans y in [-1, 1] and x in [-aspect, aspect].
#include "raylab/camera.h"
#include "raylab/stages/01_camera_rays.h"
#include "raylab/testkit/cameras.h"

#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <thread>
#include <vector>

namespace raylab {
namespace {

using testing::vec3_near;

constexpr float kTolerance = 1e-6f;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

using testkit::make_camera;

TEST(CameraRays, CentreRayOfOddImagePointsAtLookAt) {
  // An odd width and height put a pixel centre exactly on the optical axis. The camera is
  // away from the origin and looks along a slanted axis so that a ray computed in camera
  // space but never moved to world space fails.
  Camera camera = make_camera(5, 3, 60.0f);
  camera.position = glm::vec3(1.0f, 2.0f, 3.0f);
  camera.look_at = glm::vec3(4.0f, 6.0f, 3.0f);
  const Ray ray = generate_camera_ray(camera, 2, 1);
  SCOPED_TRACE(::testing::Message() << camera << ", pixel (2, 1)");
  EXPECT_TRUE(vec3_near(ray.origin, camera.position, 0.0f)) << "the ray must start at the camera";
  EXPECT_TRUE(vec3_near(ray.direction, glm::vec3(0.6f, 0.8f, 0.0f), kTolerance));
}

TEST(CameraRays, CornerPixelsOfA4x2ImageWithFov90) {
  // Worked by hand: fov 90 puts the image plane's top at y = tan(45) = 1; aspect 2 puts its
  // right edge at x = 2. Pixel (0, 0) has its centre at raster (0.5, 0.5), a quarter of the
  // way in from the left and top: x = -2 + 0.5 = -1.5, y = 1 - 0.5 = 0.5.
  const Camera camera = make_camera(4, 2, 90.0f);
  struct Case {
    int x, y;
    glm::vec3 expected;
  };
  const Case cases[] = {
      {0, 0, glm::normalize(glm::vec3(-1.5f, 0.5f, -1.0f))},
      {3, 0, glm::normalize(glm::vec3(1.5f, 0.5f, -1.0f))},
      {0, 1, glm::normalize(glm::vec3(-1.5f, -0.5f, -1.0f))},
      {3, 1, glm::normalize(glm::vec3(1.5f, -0.5f, -1.0f))},
      {1, 0, glm::normalize(glm::vec3(-0.5f, 0.5f, -1.0f))},
  };
  for (const Case& c : cases) {
    const Ray ray = generate_camera_ray(camera, c.x, c.y);
    EXPECT_TRUE(vec3_near(ray.direction, c.expected, kTolerance))
        << "pixel (" << c.x << ", " << c.y << ") of " << camera;
  }
}

TEST(CameraRays, FieldOfViewIsTheFullVerticalAngleInDegrees) {
  // fov 60 on a 3x3 image: the plane's top is at tan(30) = 0.57735; pixel (2, 1) is 2/3 of
  // the way to the right edge. Catches radians-for-degrees and half-angle mistakes.
  const Camera camera = make_camera(3, 3, 60.0f);
  const float top = std::tan(30.0f * kPi / 180.0f);
  const Ray ray = generate_camera_ray(camera, 2, 1);
  EXPECT_TRUE(vec3_near(ray.direction, glm::normalize(glm::vec3(2.0f / 3.0f * top, 0.0f, -1.0f)),
                        kTolerance))
      << camera << ", pixel (2, 1)";
}

TEST(CameraRays, DirectionsAreUnitLengthAndRaysSpanTheWholeOpenInterval) {
  const Camera cameras[] = {make_camera(7, 5, 90.0f), make_camera(16, 9, 30.0f),
                            make_camera(3, 11, 150.0f)};
  for (const Camera& camera : cameras)
    for (int y = 0; y < camera.height; ++y)
      for (int x = 0; x < camera.width; ++x) {
        const Ray ray = generate_camera_ray(camera, x, y);
        EXPECT_NEAR(glm::length(ray.direction), 1.0f, kTolerance)
            << camera << ", pixel (" << x << ", " << y << "): direction " << ray.direction;
        EXPECT_EQ(ray.t_min, 0.0f) << camera << ", pixel (" << x << ", " << y << ")";
        EXPECT_EQ(ray.t_max, kInfinity) << camera << ", pixel (" << x << ", " << y << ")";
      }
}

TEST(CameraRays, ImageIsUprightAndNotMirrored) {
  // Row 0 is the TOP of the picture (y > 0), column 0 the LEFT (x < 0). A missing y flip
  // renders the scene upside down; these signs catch it before any picture is made.
  const Camera camera = make_camera(6, 4, 90.0f);
  for (int x = 0; x < camera.width; ++x) {
    EXPECT_GT(generate_camera_ray(camera, x, 0).direction.y, 0.0f) << "top row, column " << x;
    EXPECT_LT(generate_camera_ray(camera, x, camera.height - 1).direction.y, 0.0f)
        << "bottom row, column " << x;
  }
  for (int y = 0; y < camera.height; ++y) {
    EXPECT_LT(generate_camera_ray(camera, 0, y).direction.x, 0.0f) << "left column, row " << y;
    EXPECT_GT(generate_camera_ray(camera, camera.width - 1, y).direction.x, 0.0f)
        << "right column, row " << y;
  }
}

TEST(CameraRays, AspectRatioStretchesXOnly) {
  // fov_y is vertical: a wide image sees further sideways, a tall one does not see further up.
  // 4x1, fov 90: pixel (3, 0) has x = (3.5 / 4 * 2 - 1) * aspect 4 = 3, y = 0.
  const Ray wide = generate_camera_ray(make_camera(4, 1, 90.0f), 3, 0);
  EXPECT_TRUE(vec3_near(wide.direction, glm::normalize(glm::vec3(3.0f, 0.0f, -1.0f)), kTolerance))
      << "4x1 image, fov 90, pixel (3, 0)";
  // 1x4, fov 90: pixel (0, 0) has y = 1 - 0.5 / 4 * 2 = 0.75 whatever the aspect (0.25).
  const Ray tall = generate_camera_ray(make_camera(1, 4, 90.0f), 0, 0);
  EXPECT_TRUE(vec3_near(tall.direction, glm::normalize(glm::vec3(0.0f, 0.75f, -1.0f)), kTolerance))
      << "1x4 image, fov 90, pixel (0, 0)";
}

TEST(CameraRays, RotatedCameraLookingAlongPlusX) {
  // Looking along +x with +y up, the camera's right is +z (right = forward x up). The 4x2
  // corner pixel (0, 0) is then forward - 1.5 right + 0.5 up = (1, 0.5, -1.5).
  Camera camera = make_camera(4, 2, 90.0f);
  camera.position = glm::vec3(5.0f, 1.0f, 2.0f);
  camera.look_at = glm::vec3(6.0f, 1.0f, 2.0f);
  const Ray corner = generate_camera_ray(camera, 0, 0);
  EXPECT_TRUE(vec3_near(corner.origin, camera.position, 0.0f)) << camera;
  EXPECT_TRUE(vec3_near(corner.direction, glm::normalize(glm::vec3(1.0f, 0.5f, -1.5f)), kTolerance))
      << camera << ", pixel (0, 0)";
  const Ray opposite = generate_camera_ray(camera, 3, 1);
  EXPECT_TRUE(vec3_near(opposite.direction, glm::normalize(glm::vec3(1.0f, -0.5f, 1.5f)), kTolerance))
      << camera << ", pixel (3, 1)";
}

TEST(CameraRays, UpNeedNotBeUnitOrPerpendicular) {
  // camera.h: `up` only says which way is up. A long, tilted up vector in the plane of the
  // view and +y must give the same rays as (0, 1, 0).
  const Camera reference = make_camera(5, 4, 70.0f);
  Camera tilted = reference;
  tilted.up = glm::vec3(0.0f, 5.0f, -3.0f);
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x)
      EXPECT_TRUE(vec3_near(generate_camera_ray(tilted, x, y).direction,
                            generate_camera_ray(reference, x, y).direction, kTolerance))
          << "up " << tilted.up << ", pixel (" << x << ", " << y << ")";
}

// --- validate_camera ----------------------------------------------------------------------

TEST(CameraRays, EachCameraGetsItsOwnRaysWhateverCameraCameBefore) {
  // The reference keeps the frame of the last camera it saw, per thread: a camera that differs
  // in any one field must get the rays it gets on a fresh thread. (Camera 1 differs only by the
  // sign of a zero, which these rays do not show: it checks that such a camera is served too.)
  Camera base = make_camera(7, 5, 60.0f);
  base.position = glm::vec3(0.0f, 1.0f, 2.0f);
  base.look_at = glm::vec3(0.5f, 1.0f, -3.0f);
  std::vector<Camera> cameras(8, base);
  cameras[1].position.x = -0.0f;
  cameras[2].look_at.y = 1.5f;
  cameras[3].up = glm::vec3(0.1f, 1.0f, 0.0f);
  cameras[4].fov_y_degrees = 61.0f;
  cameras[5].width = 9;
  cameras[6].height = 4;
  cameras[7].position = glm::vec3(0.0f, 1.0f, 2.5f);
  const auto rays_of = [](const Camera& camera) {
    std::vector<Ray> rays;
    for (const glm::vec2 position_in_pixel : {glm::vec2(0.5f), glm::vec2(0.0f), glm::vec2(0.99f, 0.25f)})
      for (int y = 0; y < camera.height; y += 2)
        for (int x = 0; x < camera.width; x += 3) rays.push_back(generate_camera_ray(camera, x, y, position_in_pixel));
    return rays;
  };
  const auto same_bits = [](const std::vector<Ray>& a, const std::vector<Ray>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (std::memcmp(&a[i].origin, &b[i].origin, sizeof(glm::vec3)) != 0 ||
          std::memcmp(&a[i].direction, &b[i].direction, sizeof(glm::vec3)) != 0)
        return false;
    return true;
  };
  std::vector<std::vector<Ray>> fresh(cameras.size());
  for (std::size_t c = 0; c < cameras.size(); ++c) std::thread([&] { fresh[c] = rays_of(cameras[c]); }).join();
  // Every camera right after every other (each pair with the base differs in one field only).
  for (std::size_t c = 0; c < cameras.size(); ++c)
    for (std::size_t before = 0; before < cameras.size(); ++before) {
      (void)rays_of(cameras[before]);
      EXPECT_TRUE(same_bits(rays_of(cameras[c]), fresh[c])) << "camera " << c << " after camera " << before;
    }
  EXPECT_FALSE(same_bits(fresh[0], fresh[4])) << "the cameras must differ for this test to mean anything";
}

TEST(ValidateCamera, AcceptsAUsualCamera) {
  // The counterpart of the rejections below: a valid camera must not throw.
  Camera camera = make_camera(640, 480, 45.0f);
  camera.up = glm::vec3(0.0f, 2.0f, 0.5f);
  EXPECT_NO_THROW(validate_camera(camera)) << camera;
}

TEST(ValidateCamera, RejectsCamerasThatCannotFormAnImage) {
  struct Case {
    const char* why;
    Camera camera;
  };
  auto with = [](auto change) {
    Camera camera = make_camera(64, 48, 60.0f);
    change(camera);
    return camera;
  };
  const Case cases[] = {
      {"look_at == position: no view direction",
       with([](Camera& c) { c.look_at = c.position = glm::vec3(1.0f, 2.0f, 3.0f); })},
      {"up parallel to the view", with([](Camera& c) { c.up = glm::vec3(0.0f, 0.0f, -2.0f); })},
      {"up anti-parallel to the view", with([](Camera& c) { c.up = glm::vec3(0.0f, 0.0f, 1.0f); })},
      {"up is the zero vector", with([](Camera& c) { c.up = glm::vec3(0.0f); })},
      {"fov 0", with([](Camera& c) { c.fov_y_degrees = 0.0f; })},
      {"fov 180: tan(90) is infinite", with([](Camera& c) { c.fov_y_degrees = 180.0f; })},
      {"negative fov", with([](Camera& c) { c.fov_y_degrees = -30.0f; })},
      {"NaN fov", with([](Camera& c) { c.fov_y_degrees = kNaN; })},
      {"zero width", with([](Camera& c) { c.width = 0; })},
      {"zero height", with([](Camera& c) { c.height = 0; })},
      {"negative width", with([](Camera& c) { c.width = -4; })},
      {"NaN in position", with([](Camera& c) { c.position.x = kNaN; })},
      {"NaN in look_at", with([](Camera& c) { c.look_at.y = kNaN; })},
      {"NaN in up", with([](Camera& c) { c.up.z = kNaN; })},
      {"infinite position", with([](Camera& c) { c.position.z = kInfinity; })},
  };
  for (const Case& c : cases)
    EXPECT_THROW(validate_camera(c.camera), std::invalid_argument) << c.why << ": " << c.camera;
}

}  // namespace
}  // namespace raylab
