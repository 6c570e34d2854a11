// The renderer's skips (shading.h, Skips; scene_analysis.h) leave out only work that cannot
// change the image: every skip off, one at a time and all together, gives the same bits; and
// the scene's bounding sphere never ends a ray that would hit something.
#include "raylab/geometry.h"
#include "raylab/render.h"
#include "raylab/scene_analysis.h"
#include "raylab/scene_loader.h"

#include "test_helpers.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>

namespace raylab {
namespace {

using testing::source_path;

bool bit_identical(const Image& a, const Image& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(glm::vec3)) == 0;
}

class SkipsLeaveTheImageAlone : public ::testing::TestWithParam<const char*> {};

TEST_P(SkipsLeaveTheImageAlone, EachSkipOffGivesTheSameBits) {
  Scene scene = load_scene(source_path(std::string("scenes/") + GetParam()));
  scene.camera.width = 96;
  scene.camera.height = 72;
  RenderSettings settings;
  settings.max_depth = scene.max_depth;
  const Image with_skips = render(scene, settings);
  bool Skips::*const flags[] = {&Skips::rays_outside_bounds, &Skips::zero_weight_bounces, &Skips::needless_shadow_rays,
                                &Skips::any_hit_shadow_rays, &Skips::no_bvh_for_small_sets};
  for (bool Skips::*flag : flags) {
    RenderSettings without = settings;
    without.skips.*flag = false;
    EXPECT_TRUE(bit_identical(with_skips, render(scene, without))) << "one skip turned off changed the image";
  }
  RenderSettings none = settings;
  none.skips = Skips::none();
  RenderStats stats_with, stats_without;
  (void)render(scene, settings, &stats_with);
  EXPECT_TRUE(bit_identical(with_skips, render(scene, none, &stats_without))) << "all skips off changed the image";
  // The skips must save something countable on these scenes, or this test proves little.
  EXPECT_LT(stats_with.work.traced_rays(), stats_without.work.traced_rays()) << "rays traced with and without the skips";
}

INSTANTIATE_TEST_SUITE_P(Scenes, SkipsLeaveTheImageAlone, ::testing::Values("whitted.json", "bunny.json"));

TEST(SceneBounds, NeverEndsARayThatHitsSomething) {
  // Seeded rays from all around the Whitted scene, some grazing its objects; the bounding
  // sphere may only end rays that the geometry itself reports as misses.
  const Scene scene = load_scene(source_path("scenes/whitted.json"));
  const SceneGeometry geometry(scene);
  const SceneNeeds needs = analyse_scene(scene);
  std::mt19937 random(1234);
  std::uniform_real_distribution<float> coordinate(-40.0f, 40.0f), target(-6.0f, 6.0f);
  int ended = 0, hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const glm::vec3 origin(coordinate(random), coordinate(random), coordinate(random));
    const glm::vec3 aim = glm::vec3(0, -0.5f, -11) + glm::vec3(target(random), target(random), target(random));
    const Ray ray = make_ray(origin, aim - origin);
    const bool hit = geometry.intersect(ray).has_value();
    hits += hit;
    if (!may_hit_scene(needs, ray)) {
      ++ended;
      ASSERT_FALSE(hit) << "the bounding sphere ended a ray that hits the scene (seed 1234, ray " << i << "): " << ray;
    }
  }
  EXPECT_GT(ended, 1000) << "rays the bounding sphere ended: too few for the test to mean anything";
  EXPECT_GT(hits, 1000) << "rays that hit the scene";
}

TEST(SceneBounds, AnEmptySceneEndsEveryRay) {
  Scene scene;
  const SceneNeeds needs = analyse_scene(scene);
  EXPECT_FALSE(needs.has_geometry);
  EXPECT_FALSE(may_hit_scene(needs, make_ray(glm::vec3(0), glm::vec3(0, 0, -1))));
}

}  // namespace
}  // namespace raylab
