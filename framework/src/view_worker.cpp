#include "raylab/view_worker.h"

#include "raylab/error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>
#if defined(_WIN32)
#include <io.h>
#else
#include <csignal>
#include <unistd.h>
#endif

namespace raylab {
namespace {

// Writes all of `bytes`; false when the server is gone (or the descriptor is bad).
bool write_all(int fd, const void* bytes, std::size_t size) {
  const char* at = static_cast<const char*>(bytes);
  while (size > 0) {
#if defined(_WIN32)
    const int written = ::_write(fd, at, static_cast<unsigned>(std::min<std::size_t>(size, 1u << 30)));
#else
    const ssize_t written = ::write(fd, at, size);
#endif
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    at += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

bool write_frame(int fd, const std::string& header, const void* bytes, std::size_t size) {
  return write_all(fd, header.data(), header.size()) && write_all(fd, bytes, size);
}

bool write_image_frame(int fd, const std::string& header, const Image& image) {
  return write_frame(fd, header, image.pixels().data(), image.pixels().size() * sizeof(glm::vec3));
}

}  // namespace

std::string tree_levels_json(const SceneGeometry& geometry, const Camera& camera) {
  nlohmann::json levels = nlohmann::json::array();
  std::size_t total = 0;
  for (const std::vector<Bounds3>& boxes : geometry.tree_boxes_by_level()) {
    // At most 2^20 boxes and 256 levels (what the server takes): the deeper levels are left out.
    if ((total += boxes.size()) > (1u << 20) || levels.size() == 256) break;
    nlohmann::json rectangles = nlohmann::json::array();
    for (const Bounds3& box : boxes) {
      // The box's corners, corner i taking max on axis a where bit a of i is set.
      std::array<glm::vec3, 8> corner;
      for (int i = 0; i < 8; ++i)
        corner[static_cast<std::size_t>(i)] = {(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                                               (i & 4) ? box.max.z : box.min.z};
      glm::vec2 low(kInfinity), high(-kInfinity);
      for (int i = 0; i < 8; ++i)
        for (int axis = 0; axis < 3; ++axis) {
          const int j = i | (1 << axis);  // the edge from corner i along this axis
          if (j == i) continue;
          const auto ends = project_segment_to_raster(camera, corner[static_cast<std::size_t>(i)],
                                                      corner[static_cast<std::size_t>(j)]);
          if (!ends) continue;
          for (const glm::vec2& end : *ends) {
            low = glm::min(low, end);
            high = glm::max(high, end);
          }
        }
      if (low.x <= high.x && std::isfinite(low.x) && std::isfinite(high.x) && std::isfinite(low.y) &&
          std::isfinite(high.y))
        rectangles.push_back({low.x, low.y, high.x, high.y});
    }
    levels.push_back(std::move(rectangles));
  }
  return nlohmann::json{{"levels", levels}}.dump();
}

int run_view_worker(const Scene& scene, const RenderSettings& settings, int frames_fd, bool send_tree) {
#if !defined(_WIN32)
  std::signal(SIGPIPE, SIG_IGN);  // a server that went away: a failed write, not a signal
#endif
  // The geometry once for every pass (the student's trees are built once).
  const SceneGeometry geometry = render_geometry(scene, settings);
  if (send_tree) {
    const std::string tree = tree_levels_json(geometry, scene.camera);
    if (!write_frame(frames_fd, "tree " + std::to_string(tree.size()) + "\n", tree.data(), tree.size()))
      return kExitOk;
  }
  const bool one_pass = settings.adaptive_tolerance != 0.0f || settings.samples_by_noise;
  const auto header = [](const char* kind, int first, int count, const RenderStats& stats) {
    char text[160];
    std::snprintf(text, sizeof text, "%s %d %d %.6f %llu\n", kind, first, count, stats.seconds,
                  static_cast<unsigned long long>(stats.work.rays()));
    return std::string(text);
  };
  if (one_pass) {
    RenderStats stats;
    const RenderOutput output = render_with_variance(scene, geometry, settings, &stats);
    if (write_image_frame(frames_fd, header("pass", 0, settings.samples_per_pixel, stats), output.mean))
      (void)write_image_frame(frames_fd, "rate\n", output.sample_rate);
    return kExitOk;
  }
  int count = 1;
  for (int first = settings.first_sample; first < settings.samples_per_pixel;) {
    RenderSettings pass = settings;
    pass.first_sample = first;
    pass.sample_count = std::min(count, settings.samples_per_pixel - first);
    RenderStats stats;
    const Image mean = render_with_variance(scene, geometry, pass, &stats).mean;
    if (!write_image_frame(frames_fd, header("pass", first, pass.sample_count, stats), mean)) return kExitOk;
    first += pass.sample_count;
    if (stats.seconds < 0.25) count = std::min(2 * count, 64);
  }
  return kExitOk;
}

}  // namespace raylab
