// raylab view's parts: the projection that draws paths and boxes on the picture, the render in
// passes, the trees' boxes by level, and the server (framework/view/view_server.h) with the
// reference's program as its renderer: the picture refines and ends at the whole render, stop and
// continue, a trace, and a renderer that crashes, loops or is not written.
#include "test_helpers.h"

#include "raylab/camera.h"
#include "raylab/geometry.h"
#include "raylab/render.h"
#include "raylab/scene_loader.h"
#include "raylab/testkit/exact_tracing.h"
#include "raylab/view_worker.h"
#include "view_server.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <signal.h>
#include <filesystem>
#include <thread>

namespace raylab {
namespace {

using testing::source_path;

TEST(ViewProjection, IsTheInverseOfTheExactCameraRays) {
  std::vector<Camera> cameras(3);
  cameras[0].width = 320;
  cameras[0].height = 240;
  cameras[1].position = {278.0f, 273.0f, -800.0f};
  cameras[1].look_at = {278.0f, 273.0f, 0.0f};
  cameras[1].fov_y_degrees = 39.0f;
  cameras[1].width = 100;
  cameras[1].height = 200;
  cameras[2].position = {1.0f, 2.0f, 3.0f};
  cameras[2].look_at = {-4.0f, 0.5f, 1.0f};
  cameras[2].up = {0.3f, 1.0f, 0.2f};  // not perpendicular to the view
  cameras[2].fov_y_degrees = 120.0f;
  for (const Camera& camera : cameras)
    for (const glm::vec2 at : {glm::vec2(0.5f, 0.5f), glm::vec2(17.25f, 3.75f), glm::vec2(99.0f, 1.0f)})
      for (const float distance : {0.01f, 1.0f, 30.0f}) {
        const float t = distance * glm::length(camera.look_at - camera.position);
        const Ray ray = testkit::exact_camera_ray(camera, static_cast<int>(at.x), static_cast<int>(at.y),
                                                  at - glm::floor(at));
        const std::optional<glm::vec2> raster = project_to_raster(camera, ray.origin + ray.direction * t);
        ASSERT_TRUE(raster.has_value());
        EXPECT_NEAR(raster->x, at.x, 2e-3f) << camera << " t " << t;
        EXPECT_NEAR(raster->y, at.y, 2e-3f) << camera << " t " << t;
      }
}

TEST(ViewProjection, CutsWhatIsBehindTheCamera) {
  Camera camera;  // at the origin, looking down -z
  EXPECT_FALSE(project_to_raster(camera, {0.0f, 0.0f, 1.0f}).has_value());
  EXPECT_FALSE(project_to_raster(camera, {0.0f, 0.0f, 0.0f}).has_value());
  EXPECT_FALSE(project_segment_to_raster(camera, {0.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 2.0f}).has_value());
  // From in front to behind: the front end exactly, the other cut where the picture ends.
  const auto ends = project_segment_to_raster(camera, {0.0f, 0.0f, -1.0f}, {0.0f, 1.0f, 1.0f});
  ASSERT_TRUE(ends.has_value());
  EXPECT_NEAR((*ends)[0].x, 320.0f, 1e-3f);
  EXPECT_NEAR((*ends)[0].y, 240.0f, 1e-3f);
  EXPECT_TRUE(std::isfinite((*ends)[1].y));
  EXPECT_LT((*ends)[1].y, -1000.0f);  // upwards, far off the picture
}

Scene small_scene(const std::string& name, int width, int height) {
  Scene scene = load_scene(source_path("scenes/" + name));
  scene.camera.width = width;
  scene.camera.height = height;
  return scene;
}

TEST(ViewPasses, AddUpToTheWholeRender) {
  const Scene scene = small_scene("cornell.json", 24, 18);
  RenderSettings settings;
  settings.integrator = IntegratorKind::Path;
  settings.samples_per_pixel = 8;
  settings.seed = 3;
  const Image whole = render(scene, settings);
  std::vector<glm::dvec3> sum(whole.pixels().size(), glm::dvec3(0.0));
  for (const auto& [first, count] : {std::pair<int, int>{0, 1}, {1, 2}, {3, 5}}) {
    RenderSettings pass = settings;
    pass.first_sample = first;
    pass.sample_count = count;
    const Image mean = render(scene, pass);
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += glm::dvec3(mean.pixels()[i]) * static_cast<double>(count);
  }
  double largest = 0.0;
  for (std::size_t i = 0; i < sum.size(); ++i) {
    const glm::dvec3 difference = glm::abs(sum[i] / 8.0 - glm::dvec3(whole.pixels()[i]));
    largest = std::max({largest, difference.x, difference.y, difference.z});
  }
  EXPECT_LT(largest, 1e-5) << "the passes' mean differs from the whole render's";
  // And the passes do differ from each other (each is its own samples).
  RenderSettings first = settings, second = settings;
  first.sample_count = 1;
  second.first_sample = 1;
  second.sample_count = 1;
  EXPECT_NE(render(scene, first).pixels(), render(scene, second).pixels());
}

TEST(ViewPasses, RefuseSamplesOutsideThePixel) {
  const Scene scene = small_scene("cornell.json", 8, 8);
  RenderSettings settings;
  settings.samples_per_pixel = 4;
  for (const auto& [first, count] : {std::pair<int, int>{4, 0}, {-1, 1}, {2, 3}, {0, -1}}) {
    RenderSettings pass = settings;
    pass.first_sample = first;
    pass.sample_count = count;
    EXPECT_THROW(render(scene, pass), std::invalid_argument) << first << " " << count;
  }
  RenderSettings adaptive = settings;
  adaptive.adaptive_tolerance = 0.1f;
  adaptive.sample_count = 2;
  EXPECT_THROW(render(scene, adaptive), std::invalid_argument);
}

TEST(ViewTree, LevelsHoldEveryNodeBelowTheRoot) {
  for (const char* name : {"bunny.json", "cornell.json", "whitted.json"}) {
    const Scene scene = small_scene(name, 64, 48);
    const SceneGeometry geometry(scene);
    const std::vector<std::vector<Bounds3>> levels = geometry.tree_boxes_by_level();
    if (geometry.bvh_count() == 0) {
      EXPECT_TRUE(levels.empty()) << name;
      continue;
    }
    ASSERT_FALSE(levels.empty()) << name;
    ASSERT_FALSE(levels[0].empty()) << name;
    Bounds3 roots;
    for (const Bounds3& root : levels[0]) roots.extend(root);
    for (std::size_t level = 1; level < levels.size(); ++level) {
      EXPECT_FALSE(levels[level].empty()) << name << " level " << level;
      for (const Bounds3& box : levels[level])
        EXPECT_TRUE(glm::all(glm::lessThanEqual(roots.min, box.min)) && glm::all(glm::lessThanEqual(box.max, roots.max)))
            << name << ": a box of level " << level << " outside the roots";
    }
    // The JSON the view draws: as many levels, and a rectangle for each box in front of the camera.
    const nlohmann::json json = nlohmann::json::parse(tree_levels_json(geometry, scene.camera));
    ASSERT_EQ(json["levels"].size(), levels.size()) << name;
    EXPECT_EQ(json["levels"][0].size(), levels[0].size()) << name;
  }
  // The bunny's one mesh: its tree from level 0, one root, at most twice the boxes a level down.
  const Scene bunny = small_scene("bunny.json", 64, 48);
  const std::vector<std::vector<Bounds3>> levels = SceneGeometry(bunny).tree_boxes_by_level();
  ASSERT_GT(levels.size(), 3u);
  EXPECT_EQ(levels[0].size(), 1u);
  for (std::size_t level = 1; level < levels.size(); ++level) EXPECT_LE(levels[level].size(), 2 * levels[level - 1].size());
}

TEST(ViewChild, IsKilledWhenItsTimeIsUp) {
  const auto start = std::chrono::steady_clock::now();
  const view::ChildResult result = view::run_child({"/bin/sh", "-c", "echo started; sleep 30"}, 3.0, 1000);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  EXPECT_TRUE(result.timed_out);
  EXPECT_EQ(result.output, "started\n");
  EXPECT_EQ(view::describe_child_end(result, "tracing this pixel", false),
            "your code did not finish tracing this pixel in time: it may loop forever.");
}

TEST(ViewChild, ACrashIsNamedInWords) {
  const view::ChildResult crash = view::run_child({"/bin/sh", "-c", "kill -SEGV $$"}, 10.0, 1000);
  EXPECT_EQ(crash.signal, SIGSEGV);
  EXPECT_EQ(view::describe_child_end(crash, "rendering", false),
            "your code crashed while rendering: segmentation fault (signal 11).");
  EXPECT_EQ(view::describe_child_end(crash, "渲染", true), "你的代码在渲染时崩溃了：段错误（segmentation fault，信号 11）。");
  // The program's own last message, e.g. a stage not written yet.
  const view::ChildResult stub = view::run_child(
      {"/bin/sh", "-c", "echo 'raylab: stage 02_sphere is not implemented yet' >&2; exit 2"}, 10.0, 1000);
  EXPECT_EQ(stub.exit_code, 2);
  EXPECT_EQ(view::describe_child_end(stub, "rendering", false), "raylab: stage 02_sphere is not implemented yet");
  const view::ChildResult missing = view::run_child({"/nonexistent/raylab"}, 10.0, 1000);
  EXPECT_EQ(missing.exit_code, 127);
  EXPECT_EQ(view::describe_child_end(missing, "tracing this pixel", false),
            "raylab: cannot start the program /nonexistent/raylab");
  // A child that closes its output and goes on is still stopped in time, and its group with it.
  const auto start = std::chrono::steady_clock::now();
  const view::ChildResult closed = view::run_child({"/bin/sh", "-c", "exec >&- 2>&-; sleep 30"}, 2.0, 1000);
  EXPECT_TRUE(closed.timed_out);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  // Exit 0 with no answer is said as such.
  const view::ChildResult silent = view::run_child({"/bin/sh", "-c", "exit 0"}, 10.0, 1000);
  EXPECT_EQ(view::describe_child_end(silent, "tracing this pixel", false),
            "your program gave no answer while tracing this pixel (its output was not what was expected).");
  // Output is kept to its last bytes.
  const view::ChildResult flood = view::run_child({"/bin/sh", "-c", "yes raylab | head -c 100000"}, 10.0, 64);
  EXPECT_EQ(flood.output.size(), 64u);
}

TEST(ViewTreeJson, OnlyLevelsOfFiniteRectanglesAreTaken) {
  const auto taken = view::checked_tree_json(R"({"levels": [[[0, 1, 2, 3]], [[0, 0, 1, 1], [2, 2, 3.5, 4]]]})");
  ASSERT_TRUE(taken.has_value());
  EXPECT_EQ(taken->second, 2);
  EXPECT_EQ(nlohmann::json::parse(taken->first)["levels"][1][1][2], 3.5);
  for (const char* refused : {"", "[]", R"({"levels": 3})", R"({"levels": [[[0, 1, 2]]]})",
                              R"({"levels": [[[0, 1, 2, "3"]]]})", R"({"levels": [[[0, 1, 2, 1e999]]]})",
                              R"({"levels": [[[[[[0]]]]]]})"})
    EXPECT_FALSE(view::checked_tree_json(refused).has_value()) << refused;
  // Deeply nested JSON is refused, not followed down.
  EXPECT_FALSE(view::checked_tree_json(R"({"levels": )" + std::string(100000, '[') + std::string(100000, ']') + "}")
                   .has_value());
}

TEST(ViewDifference, IsBlackWhereEqualAndYellowFromATenth) {
  Image yours(3, 1, glm::vec3(0.5f)), reference(3, 1, glm::vec3(0.5f));
  reference.at(1, 0) = glm::vec3(0.0f);
  reference.at(2, 0).y = 0.48f;  // a few 8-bit steps
  const Image map = view::difference_heat_map(yours, reference);
  EXPECT_EQ(map.at(0, 0), glm::vec3(0.0f));
  EXPECT_EQ(map.at(1, 0), glm::vec3(1.0f, 1.0f, 0.0f));
  EXPECT_GT(map.at(2, 0).x, 0.0f);
  EXPECT_EQ(map.at(2, 0).y, 0.0f);
}

// The server with a program as its renderer, asked as the page asks.
class ViewServerTest : public ::testing::Test {
 protected:
  static view::ViewOptions options(const std::string& renderer, const std::string& scene_name, int goal) {
    view::ViewOptions options;
    options.renderer = renderer;
    options.scene_path = source_path("scenes/" + scene_name);
    options.camera = small_scene(scene_name, 32, 24).camera;
    options.integrator = goal == 1 ? "whitted" : "path";
    options.goal = goal;
    options.trace_seconds = 5.0;
    options.render_arguments = {"--width", "32", "--height", "24", "--spp", std::to_string(goal), "--integrator",
                                options.integrator, "--threads", "2"};
    return options;
  }
  static nlohmann::json status(view::ViewServer& server) { return nlohmann::json::parse(server.status_json()); }
  // Waits (up to 60 s) until the state is one of `states`.
  static nlohmann::json wait_for(view::ViewServer& server, const std::vector<std::string>& states) {
    for (int i = 0; i < 600; ++i) {
      const nlohmann::json now = status(server);
      if (std::find(states.begin(), states.end(), now["state"].get<std::string>()) != states.end()) return now;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    ADD_FAILURE() << "the state never became one awaited: " << server.status_json();
    return status(server);
  }
};

TEST_F(ViewServerTest, RefinesToTheWholeRender) {
  view::ViewServer server(options(RAYLAB_REFERENCE_PROGRAM, "cornell.json", 64));
  server.start();
  const nlohmann::json done = wait_for(server, {"done", "failed"});
  ASSERT_EQ(done["state"], "done") << done.dump();
  EXPECT_EQ(done["samples_per_pixel"], 64);
  EXPECT_GE(done["version"].get<int>(), 2) << "one pass: nothing refined";
  EXPECT_GT(done["tree_levels"].get<int>(), 1);
  const std::optional<std::string> png = server.picture_png("yours");
  ASSERT_TRUE(png.has_value());
  EXPECT_EQ(png->substr(1, 3), "PNG");
  // The same picture as the program's whole render (raylab render --spp 64), within a step of the
  // 8-bit values.
  const auto dir = testing::scratch_dir();
  testing::write_text_file(dir / "view.png", *png);
  const view::ChildResult whole_render =
      view::run_child({RAYLAB_REFERENCE_PROGRAM, "render", source_path("scenes/cornell.json"), "-o",
                       (dir / "whole.png").string(), "--width", "32", "--height", "24", "--spp", "64", "--integrator",
                       "path", "-q"},
                      60.0, 10000);
  ASSERT_EQ(whole_render.exit_code, 0) << whole_render.errors;
  const Image whole = read_image((dir / "whole.png").string());
  const Image viewed = read_image((dir / "view.png").string());
  ASSERT_EQ(whole.pixels().size(), viewed.pixels().size());
  double largest = 0.0;
  for (std::size_t i = 0; i < whole.pixels().size(); ++i)
    for (int c = 0; c < 3; ++c)
      largest = std::max(largest, std::abs(static_cast<double>(whole.pixels()[i][c]) - viewed.pixels()[i][c]));
  EXPECT_LE(largest, 1.0 / 255.0);
  EXPECT_FALSE(server.picture_png("reference").has_value());
  EXPECT_FALSE(server.picture_png("nonsense").has_value());
  const nlohmann::json tree = nlohmann::json::parse(server.tree_json());
  EXPECT_EQ(tree["levels"].size(), done["tree_levels"].get<std::size_t>());
}

TEST_F(ViewServerTest, StopsAndGoesOn) {
  view::ViewServer server(options(RAYLAB_REFERENCE_PROGRAM, "cornell.json", 1 << 20));
  server.start();
  for (int i = 0; i < 600 && status(server)["samples_per_pixel"].get<int>() < 2; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_EQ(nlohmann::json::parse(server.stop())["ok"], true);
  const nlohmann::json stopped = wait_for(server, {"stopped"});
  const int samples = stopped["samples_per_pixel"];
  EXPECT_GE(samples, 2);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(status(server)["samples_per_pixel"], samples) << "it went on after stop";
  EXPECT_EQ(nlohmann::json::parse(server.go_on())["ok"], true);
  for (int i = 0; i < 600 && status(server)["samples_per_pixel"].get<int>() <= samples; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_GT(status(server)["samples_per_pixel"].get<int>(), samples) << "continue did not go on";
  EXPECT_EQ(nlohmann::json::parse(server.go_on())["ok"], false);  // it is rendering
  const int group = view::ViewServer::running_group();
  ASSERT_GT(group, 0);
  EXPECT_EQ(::kill(group, 0), 0);
}

TEST_F(ViewServerTest, LeavesNoProcessBehind) {
  int group = 0;
  {
    view::ViewServer server(options(RAYLAB_REFERENCE_PROGRAM, "cornell.json", 1 << 20));
    server.start();
    for (int i = 0; i < 600 && (group = view::ViewServer::running_group()) == 0; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    ASSERT_GT(group, 0);
  }
  EXPECT_EQ(view::ViewServer::running_group(), 0);
  EXPECT_EQ(::kill(-group, 0), -1) << "the renderer's group outlived the server";
}

TEST_F(ViewServerTest, TracesAPixel) {
  view::ViewServer server(options(RAYLAB_REFERENCE_PROGRAM, "cornell.json", 4));
  const nlohmann::json trace = nlohmann::json::parse(server.trace_json(16, 12));
  ASSERT_EQ(trace["ok"], true) << trace.dump();
  EXPECT_EQ(trace["first_disagreement"], -1);
  EXPECT_GT(trace["steps"].size(), 3u);
  ASSERT_GE(trace["segments"].size(), 2u);
  EXPECT_EQ(trace["segments"][0]["kind"], "camera");
  for (std::size_t i = 1; i < trace["segments"].size(); ++i)
    EXPECT_TRUE(trace["segments"][i]["kind"] == "bounce" || trace["segments"][i]["kind"] == "shadow") << trace.dump();
  const nlohmann::json outside = nlohmann::json::parse(server.trace_json(32, 0));
  EXPECT_EQ(outside["ok"], false);
}

TEST_F(ViewServerTest, ARendererThatFailsLeavesTheServerUp) {
  // Programs that stand for the student's: one not written yet, one that crashes, one that loops.
  const std::filesystem::path dir = testing::scratch_dir();
  const auto program = [&](const std::string& name, const std::string& script) {
    const std::filesystem::path path = dir / name;
    testing::write_text_file(path, "#!/bin/sh\n" + script + "\n");
    std::filesystem::permissions(path, std::filesystem::perms::owner_all);
    return path.string();
  };
  struct Case {
    std::string renderer, message, trace_error;
  };
  for (const Case& c :
       {Case{program("stub", "echo 'raylab: stage 01_camera_rays is not implemented yet' >&2; exit 2"),
             "raylab: stage 01_camera_rays is not implemented yet. The page stays up: fix your code, build it again and "
             "press continue.",
             "raylab: stage 01_camera_rays is not implemented yet"},
        Case{program("crash", "echo 'my debug line'; kill -SEGV $$"),
             "your code crashed while rendering: segmentation fault (signal 11). The page stays up",
             "your code crashed while tracing this pixel: segmentation fault (signal 11)"}}) {
    view::ViewOptions o = options(c.renderer, "cornell.json", 4);
    view::ViewServer server(o);
    server.start();
    const nlohmann::json failed = wait_for(server, {"failed", "done"});
    EXPECT_EQ(failed["state"], "failed") << failed.dump();
    EXPECT_EQ(failed["message"].get<std::string>().rfind(c.message, 0), 0u) << failed.dump();
    EXPECT_EQ(failed["views"].size(), 0u);
    // Still answering: a trace's failure in words, nothing to stop, and continue tries again.
    const nlohmann::json trace = nlohmann::json::parse(server.trace_json(1, 1));
    EXPECT_EQ(trace["ok"], false);
    EXPECT_EQ(trace["error"].get<std::string>().rfind(c.trace_error, 0), 0u) << trace.dump();
    EXPECT_EQ(nlohmann::json::parse(server.stop())["ok"], false);
    EXPECT_EQ(nlohmann::json::parse(server.go_on())["ok"], true);
    EXPECT_EQ(wait_for(server, {"failed", "done"})["state"], "failed");
  }
  const nlohmann::json crashed_output = [&] {
    view::ViewServer server(options((dir / "crash").string(), "cornell.json", 4));
    server.start();
    return wait_for(server, {"failed", "done"});
  }();
  EXPECT_EQ(crashed_output["output"], "my debug line\n");  // what it printed, for the page
  // A trace that never ends is stopped after its time (options(): 5 s), and said so.
  view::ViewOptions o = options(program("loop", "while :; do :; done"), "cornell.json", 4);
  o.trace_seconds = 1.0;
  view::ViewServer looping(o);
  looping.start();
  const nlohmann::json trace = nlohmann::json::parse(looping.trace_json(1, 1));
  EXPECT_EQ(trace["error"], "your code did not finish tracing this pixel in time: it may loop forever.");
  EXPECT_EQ(status(looping)["state"], "starting");  // its render never ends a pass
  EXPECT_EQ(nlohmann::json::parse(looping.stop())["ok"], true);
  EXPECT_EQ(wait_for(looping, {"stopped"})["state"], "stopped");
}

}  // namespace
}  // namespace raylab
