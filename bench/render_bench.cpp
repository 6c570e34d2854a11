// raylab-bench-render: what the renderer's skips save, and run time against image error.
//
//   raylab-bench-render [--output DIR] [--repetitions N]
//
// 1. Skips (shading.h, Skips): each scene is rendered with every skip on, then with one skip
//    off, in the same run (best of N, one thread); the table gives time(off) / time(on) (above
//    1: the skip pays) with the counted work, and checks that the two images are bit-identical.
// 2. Time against error: renders at several bounce depths and image sizes, each compared with
//    a high-quality reference (depth 16, 1280x960) by RMS error, PSNR and the fraction of
//    pixels with a channel off by more than 0.05. Written to DIR/render_error.csv; plot it with
//    tools/plot_render_error.py.
#include "raylab/image.h"
#include "raylab/render.h"
#include "raylab/scene_loader.h"

#include "../solutions/05c_wide_bvh/fast_tree.h"  // the reference's fastest tree, as raylab-reference traces it

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace {

using namespace raylab;

struct Timed {
  Image image;
  RenderStats stats;
  double seconds = 0.0;
};

// As raylab-reference renders: the reference's fastest tree (TracingFunctions::own_tree).
Timed render_best_of(const Scene& scene, RenderSettings settings, int repetitions) {
  settings.tracing.own_tree = &reference::build_fast_tree;
  Timed best;
  best.seconds = 1e30;
  for (int i = 0; i < repetitions; ++i) {
    RenderStats stats;
    Image image = render(scene, settings, &stats);
    if (stats.seconds < best.seconds) best = Timed{std::move(image), stats, stats.seconds};
  }
  return best;
}

bool bit_identical(const Image& a, const Image& b) {
  return a.width() == b.width() && a.height() == b.height() &&
         std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(glm::vec3)) == 0;
}

struct NamedScene {
  std::string name;
  Scene scene;
};

std::vector<NamedScene> skip_scenes() {
  const std::string dir = std::string(RAYLAB_SOURCE_DIR) + "/scenes/";
  std::vector<NamedScene> scenes;
  Scene whitted = load_scene(dir + "whitted.json");  // mostly background, 4 primitives
  scenes.push_back({"whitted", whitted});
  Scene bunny = load_scene(dir + "bunny.json");
  scenes.push_back({"bunny", bunny});
  // The bunny filling the frame: no camera ray misses the scene.
  Scene close = bunny;
  close.camera.position = glm::vec3(-1.5f, 4.5f, 5.0f);
  close.camera.look_at = glm::vec3(-0.5f, 3.5f, 0.0f);
  scenes.push_back({"bunny close-up", close});
  // One light low behind the bunny: its shadow covers much of the floor.
  Scene shadowed = bunny;
  shadowed.lights = {PointLight{glm::vec3(6.0f, 5.0f, -10.0f), glm::vec3(0.9f)}};
  scenes.push_back({"bunny, long shadow", shadowed});
  return scenes;
}

unsigned long long traced(const Timed& timed) {
  return static_cast<unsigned long long>(timed.stats.work.traced_rays());
}

struct SkipCase {
  const char* name;
  bool Skips::*flag;
};

void run_skips(int repetitions, const std::string& output) {
  const SkipCase cases[] = {
      {"rays_outside_bounds", &Skips::rays_outside_bounds},
      {"zero_weight_bounces", &Skips::zero_weight_bounces},
      {"needless_shadow_rays", &Skips::needless_shadow_rays},
      {"any_hit_shadow_rays", &Skips::any_hit_shadow_rays},
      {"no_bvh_for_small_sets", &Skips::no_bvh_for_small_sets},
  };
  std::ofstream csv(output + "/skips.csv");
  csv << "scene,skip,seconds_with,seconds_without,speedup,traced_rays_with,traced_rays_without,identical\n";
  std::printf("\nSkips at 1280x960: time without the skip / time with it (one thread, best of %d; > 1: the skip\n"
              "pays), and rays traced through the geometry (exact)\n\n", repetitions);
  std::printf("%-20s %-22s %9s %9s %8s %12s %12s %9s\n", "scene", "skip", "with", "without", "speedup", "traced with",
              "without", "identical");
  for (const NamedScene& named : skip_scenes()) {
    RenderSettings settings;
    settings.threads = 1;
    settings.max_depth = named.scene.max_depth;
    const Timed with = render_best_of(named.scene, settings, repetitions);
    for (const SkipCase& c : cases) {
      RenderSettings without_settings = settings;
      without_settings.skips.*(c.flag) = false;
      const Timed without = render_best_of(named.scene, without_settings, repetitions);
      const bool identical = bit_identical(with.image, without.image);
      const double speedup = without.seconds / with.seconds;
      std::printf("%-20s %-22s %8.3fs %8.3fs %7.2fx %12llu %12llu %9s\n", named.name.c_str(), c.name, with.seconds,
                  without.seconds, speedup, traced(with), traced(without), identical ? "yes" : "NO");
      csv << '"' << named.name << "\"," << c.name << ',' << with.seconds << ',' << without.seconds << ',' << speedup
          << ',' << traced(with) << ',' << traced(without) << ',' << (identical ? "yes" : "no") << '\n';
    }
    RenderSettings none = settings;
    none.skips = Skips::none();
    const Timed all_off = render_best_of(named.scene, none, repetitions);
    std::printf("%-20s %-22s %8.3fs %8.3fs %7.2fx %12llu %12llu %9s\n", named.name.c_str(), "(all of them)", with.seconds,
                all_off.seconds, all_off.seconds / with.seconds, traced(with), traced(all_off),
                bit_identical(with.image, all_off.image) ? "yes" : "NO");
  }
}

void run_error(int repetitions, const std::string& output) {
  const std::string dir = std::string(RAYLAB_SOURCE_DIR) + "/scenes/";
  std::ofstream csv(output + "/render_error.csv");
  csv << "scene,sweep,setting,seconds,rms_error,psnr,fraction_over_0.05\n";
  std::printf("\nTime against error (one thread, best of %d), against depth 16 at 1280x960\n\n", repetitions);
  std::printf("%-8s %-10s %8s %9s %11s %8s %10s\n", "scene", "sweep", "setting", "seconds", "RMS error", "PSNR", "> 0.05");
  for (const char* scene_name : {"whitted", "bunny"}) {
    Scene scene = load_scene(dir + scene_name + ".json");
    scene.camera.width = 1280;
    scene.camera.height = 960;
    RenderSettings settings;
    settings.max_depth = 16;
    const Image reference = render(scene, settings);
    const std::string scene_label = scene_name;  // GCC 14 cannot see that scene_name is never null
    auto report = [&](const char* sweep, int setting, const Timed& timed) {
      const Image compared = timed.image.width() == reference.width()
                                 ? timed.image
                                 : resize_image(timed.image, reference.width(), reference.height());
      const ImageDifference d = compare_images(compared, reference, 0.05f);
      std::printf("%-8s %-10s %8d %8.4fs %11.5f %8.2f %9.3f%%\n", scene_label.c_str(), sweep, setting, timed.seconds, d.rms_error,
                  d.psnr, 100.0 * d.fraction_over_threshold);
      csv << scene_name << ',' << sweep << ',' << setting << ',' << timed.seconds << ',' << d.rms_error << ','
          << d.psnr << ',' << d.fraction_over_threshold << '\n';
    };
    for (int depth = 0; depth <= 6; ++depth) {
      RenderSettings s;
      s.threads = 1;
      s.max_depth = depth;
      report("depth", depth, render_best_of(scene, s, repetitions));
    }
    for (int width : {80, 160, 320, 640, 1280}) {
      Scene sized = scene;
      sized.camera.width = width;
      sized.camera.height = width * 3 / 4;
      RenderSettings s;
      s.threads = 1;
      s.max_depth = 5;
      report("width", width, render_best_of(sized, s, repetitions));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"raylab-bench-render: the renderer's skips, and run time against image error"};
  std::string output = "bench-results";
  int repetitions = 5;
  app.add_option("--output", output, "Folder for the CSV files")->capture_default_str();
  app.add_option("--repetitions", repetitions, "Renders per measurement (the fastest counts)")
      ->check(CLI::Range(1, 100))->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    std::filesystem::create_directories(output);
    run_skips(repetitions, output);
    run_error(repetitions, output);
    std::printf("\nCSV written to %s/skips.csv and %s/render_error.csv\n", output.c_str(), output.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "raylab-bench-render: %s\n", e.what());
    return 1;
  }
  return 0;
}
