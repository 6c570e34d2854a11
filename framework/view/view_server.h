// raylab view's server (the program raylab-view, which `raylab view` starts): the picture as the
// student's program renders it, pass by pass, for the page (index.html) to show, and one pixel
// traced when the page asks. No stage function is called in this process: the renderer is the student's
// program, started as a child (`raylab view-worker`, view_worker.h; `raylab trace --json` for a
// pixel), so a crash or an endless loop there costs that child, which the page then names in
// words; the page stays up.
#pragma once

#include "raylab/camera.h"
#include "raylab/image.h"

#include <glm/glm.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace raylab::view {

struct ViewOptions {
  std::string renderer;     // the student's program (raylab or raylab-reference)
  std::string scene_path;
  Camera camera;            // the scene's, with --width and --height
  std::string integrator;   // "whitted", "direct", "path" or "mis"
  int goal = 1;             // samples per pixel when done
  bool one_pass = false;    // --adaptive or --spp-by-noise: the picture comes in one pass
  bool chinese = false;     // --lang zh
  double trace_seconds = 20.0;
  // The options every child is given after the scene (--width, --height, --spp, --integrator, ...).
  std::vector<std::string> render_arguments;
  // The kit's reference picture of this scene at these settings (autograder/reference), if any,
  // else why there is none.
  std::optional<Image> reference;
  std::string reference_note;
};

// A child's end, as the page is told it.
struct ChildResult {
  bool started = false;      // false: it could not be started (`output` says why)
  bool timed_out = false;    // killed after its time was up
  int exit_code = -1;        // when it exited
  int signal = 0;            // when a signal ended it
  std::string output;        // its stdout (trace) or stdout and stderr (worker)
  std::string errors;        // its stderr (trace)
};

// Runs `arguments` (the program first) in a process group of its own, its stdin /dev/null, and
// collects its stdout and stderr, each cut to its last `most_bytes`; kills the group after
// `seconds`, and when the child ends whatever it left in it. `group`, if given, holds the group's
// number while the child runs (0 otherwise): a kill of it ends the child early.
ChildResult run_child(const std::vector<std::string>& arguments, double seconds, std::size_t most_bytes,
                      std::atomic<int>* group = nullptr);

// The tree frame's JSON (view_worker.h), checked: {"levels": [[[x0, y0, x1, y1], ...], ...]} with
// finite numbers, at most 256 levels and 2^20 boxes in all, written again (so that what the server
// serves is its own writing), and its count of levels; nullopt for anything else.
std::optional<std::pair<std::string, int>> checked_tree_json(const std::string& text);

// The words for a child that did not end well ("your code crashed: segmentation fault
// (signal 11)"), in English or Chinese, with the last line the program wrote that starts with
// "raylab:" (its own message, e.g. a stage not written yet).
std::string describe_child_end(const ChildResult& result, const std::string& doing, bool chinese);

// |yours - reference| per pixel as a heat map: black where equal, through red to yellow at a
// difference of a tenth or more of the brightest value a picture file stores (in the 8-bit
// values the PNG files hold).
Image difference_heat_map(const Image& yours, const Image& reference);

class ViewServer {
 public:
  explicit ViewServer(ViewOptions options);
  ~ViewServer();  // stops the renderer
  ViewServer(const ViewServer&) = delete;
  ViewServer& operator=(const ViewServer&) = delete;

  // The page's requests (the HTTP routes of view_main.cpp): JSON texts and PNG bytes.
  std::string status_json();
  std::string tree_json();
  // The picture `view` ("yours", "reference", "difference" (difference_heat_map), "samples": with
  // --adaptive or --spp-by-noise, each pixel's samples, white for the most); nullopt: no such
  // picture now.
  std::optional<std::string> picture_png(const std::string& view);
  std::string stop();
  std::string go_on();  // POST /continue
  std::string trace_json(int x, int y);

  // Starts rendering from the first sample.
  void start();
  // For a signal handler: the renderer's process group, or 0.
  static int running_group();

 private:
  enum class State { Starting, Rendering, Stopped, Done, Failed };
  void render_from(int first_sample);  // the worker thread
  Image picture_locked() const;        // the mean so far
  std::string renderer_identity() const;  // the program's file: its inode, size and time
  std::string words(const char* english, const char* chinese) const;

  ViewOptions options_;
  std::mutex mutex_;
  State state_ = State::Starting;
  std::string message_;
  std::string output_;               // the last of what the renderer printed
  std::vector<glm::dvec3> sum_;      // each pixel's samples' sum
  int samples_done_ = 0;
  double seconds_done_ = 0.0;
  std::uint64_t rays_done_ = 0;
  int version_ = 0;
  std::optional<Image> rate_;        // one pass with --adaptive or --spp-by-noise
  std::string tree_json_;
  int tree_levels_ = 0;
  bool stop_requested_ = false;
  std::chrono::steady_clock::time_point pass_started_;
  std::thread worker_thread_;
  std::string renderer_identity_;    // of the program that rendered the picture so far
  // The trace running, if any: its process group; the number of the latest click; one at a time.
  std::atomic<int> trace_group_{0};
  std::atomic<std::uint64_t> trace_number_{0};
  std::mutex trace_mutex_, tracing_mutex_;
  // PNG bytes of the pictures, kept until the picture changes.
  int cached_version_ = -1;
  std::string cached_view_, cached_png_;
};

}  // namespace raylab::view
