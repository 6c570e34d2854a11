#include "view_server.h"

#include "raylab/progress.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <poll.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#if defined(__linux__)
#include <sys/prctl.h>
#endif

namespace raylab::view {
namespace {

// The renderer's process group while one runs (for ViewServer::running_group).
std::atomic<int> running_group_id{0};

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Keeps the last `most` bytes of what is appended.
void append_tail(std::string& text, const char* bytes, std::size_t size, std::size_t most) {
  text.append(bytes, size);
  if (text.size() > most) text.erase(0, text.size() - most);
}

struct Spawned {
  pid_t pid = -1;
  int out = -1;     // its stdout (and stderr when merged)
  int err = -1;     // its stderr, unless merged
  int frames = -1;  // what it writes to its descriptor 3, when asked for
  std::string error;
};

// Starts `arguments` in a process group of its own (killed with this process on Linux), stdin
// /dev/null, stdout to a pipe, stderr to another or the same, and a pipe on its descriptor 3
// when `frames`. Every other descriptor of ours is closed in it.
Spawned spawn(const std::vector<std::string>& arguments, bool merge_errors, bool frames) {
  Spawned spawned;
  int out[2] = {-1, -1}, err[2] = {-1, -1}, frame[2] = {-1, -1};
  const auto close_all = [&] {
    for (int fd : {out[0], out[1], err[0], err[1], frame[0], frame[1]})
      if (fd >= 0) ::close(fd);
  };
  if (::pipe2(out, O_CLOEXEC) != 0 || (!merge_errors && ::pipe2(err, O_CLOEXEC) != 0) ||
      (frames && ::pipe2(frame, O_CLOEXEC) != 0)) {
    spawned.error = std::string("cannot make a pipe: ") + std::strerror(errno);
    close_all();
    return spawned;
  }
  std::vector<char*> argv;
  std::vector<std::string> words = arguments;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const long open_max = std::min(::sysconf(_SC_OPEN_MAX), 65536L);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    spawned.error = std::string("cannot start a process: ") + std::strerror(errno);
    close_all();
    return spawned;
  }
  if (pid == 0) {  // the child: only async-signal-safe calls from here on
    ::setpgid(0, 0);
#if defined(__linux__)
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);  // the server ended before the line above
#endif
    const int null = ::open("/dev/null", O_RDONLY);
    if (null >= 0) ::dup2(null, 0);
    ::dup2(out[1], 1);
    ::dup2(merge_errors ? out[1] : err[1], 2);
    if (frames) {
      if (frame[1] == 3)
        ::fcntl(3, F_SETFD, 0);
      else
        ::dup2(frame[1], 3);
    }
    for (long fd = frames ? 4 : 3; fd < open_max; ++fd) ::close(static_cast<int>(fd));
    ::signal(SIGPIPE, SIG_DFL);
    ::execv(argv[0], argv.data());
    const char* reason = "raylab: cannot start the program ";
    (void)!::write(2, reason, std::strlen(reason));
    (void)!::write(2, argv[0], std::strlen(argv[0]));
    (void)!::write(2, "\n", 1);
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // (also in the child: whichever runs first)
  ::close(out[1]);
  if (err[1] >= 0) ::close(err[1]);
  if (frame[1] >= 0) ::close(frame[1]);
  spawned.pid = pid;
  spawned.out = out[0];
  spawned.err = err[0];
  spawned.frames = frame[0];
  return spawned;
}

void record_end(ChildResult& result, int status) {
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
}

// Reads exactly `size` bytes; false at the end of the stream or an error.
bool read_exactly(int fd, void* bytes, std::size_t size) {
  char* at = static_cast<char*>(bytes);
  while (size > 0) {
    const ssize_t got = ::read(fd, at, size);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) return false;
    at += got;
    size -= static_cast<std::size_t>(got);
  }
  return true;
}

// A frame's line (view_worker.h), at most 200 bytes; false at the end or on a longer line.
bool read_line(int fd, std::string& line) {
  line.clear();
  char c = 0;
  while (line.size() < 200) {
    if (!read_exactly(fd, &c, 1)) return false;
    if (c == '\n') return true;
    line += c;
  }
  return false;
}

std::string signal_words(int signal, bool chinese) {
  switch (signal) {
    case SIGSEGV: return chinese ? "段错误（segmentation fault，信号 11）" : "segmentation fault (signal 11)";
    case SIGFPE: return chinese ? "算术异常（信号 8）" : "arithmetic exception (signal 8)";
    case SIGABRT: return chinese ? "中止（abort，信号 6）" : "abort (signal 6)";
    case SIGBUS: return chinese ? "总线错误（信号 7）" : "bus error (signal 7)";
    case SIGILL: return chinese ? "非法指令（信号 4）" : "illegal instruction (signal 4)";
    case SIGKILL: return chinese ? "被杀死（信号 9）" : "killed (signal 9)";
    default: return (chinese ? "信号 " : "signal ") + std::to_string(signal);
  }
}

// The last line of `output` that starts with "raylab:" (the program's own message), or "".
std::string last_raylab_line(const std::string& output) {
  std::istringstream lines(output);
  std::string line, last;
  while (std::getline(lines, line))
    if (line.rfind("raylab:", 0) == 0) last = line;
  return last;
}

}  // namespace

ChildResult run_child(const std::vector<std::string>& arguments, double seconds, std::size_t most_bytes,
                      std::atomic<int>* group) {
  ChildResult result;
  Spawned child = spawn(arguments, /*merge_errors=*/false, /*frames=*/false);
  if (child.pid < 0) {
    result.output = child.error;
    return result;
  }
  result.started = true;
  if (group) *group = child.pid;
  const Clock::time_point start = Clock::now();
  pollfd fds[2] = {{child.out, POLLIN, 0}, {child.err, POLLIN, 0}};
  std::string* into[2] = {&result.output, &result.errors};
  int open_count = 2;
  char buffer[65536];
  while (open_count > 0) {
    const double left = seconds - seconds_since(start);
    if (left <= 0.0) {
      result.timed_out = true;
      break;
    }
    const int ready = ::poll(fds, 2, static_cast<int>(std::min(left, 1.0) * 1000.0) + 1);
    if (ready < 0 && errno != EINTR) break;
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t got = ::read(fds[i].fd, buffer, sizeof buffer);
      if (got > 0) {
        append_tail(*into[i], buffer, static_cast<std::size_t>(got), most_bytes);
      } else if (got == 0 || errno != EINTR) {
        ::close(fds[i].fd);
        fds[i].fd = -1;
        --open_count;
      }
    }
  }
  for (const pollfd& fd : fds)
    if (fd.fd >= 0) ::close(fd.fd);
  // Its end, within the same deadline (a child may close its output and go on).
  siginfo_t info{};
  for (;;) {
    info.si_pid = 0;
    if (::waitid(P_PID, static_cast<id_t>(child.pid), &info, WEXITED | WNOHANG | WNOWAIT) < 0 && errno != EINTR) break;
    if (info.si_pid != 0) break;
    if (seconds_since(start) >= seconds) {
      result.timed_out = true;
      break;
    }
    ::usleep(10000);
  }
  // Whatever is left in its group goes (it too, when its time was up), before it is reaped, so
  // that the group's number cannot have been given to another.
  ::kill(-child.pid, SIGKILL);
  if (group) *group = 0;
  int status = 0;
  while (::waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {
  }
  record_end(result, status);
  if (result.timed_out) result.signal = 0;  // killed by us, not by its own fault
  return result;
}

std::string describe_child_end(const ChildResult& result, const std::string& doing, bool chinese) {
  const std::string own = last_raylab_line(result.output + "\n" + result.errors);
  if (!result.started) return (chinese ? "无法启动你的程序：" : "cannot start your program: ") + result.output;
  if (result.timed_out)
    return chinese ? "你的代码在" + doing + "时没有在限定时间内结束：它可能陷入了死循环。"
                   : "your code did not finish " + doing + " in time: it may loop forever.";
  if (result.signal != 0)
    return (chinese ? "你的代码在" + doing + "时崩溃了：" : "your code crashed while " + doing + ": ") +
           signal_words(result.signal, chinese) + (chinese ? "。" : ".") + (own.empty() ? "" : " " + own);
  if (!own.empty()) return own;
  if (result.exit_code == 0)
    return chinese ? "你的程序在" + doing + "时没有给出结果（它的输出不是预期的格式）。"
                   : "your program gave no answer while " + doing + " (its output was not what was expected).";
  return chinese ? "你的程序在" + doing + "时以退出码 " + std::to_string(result.exit_code) + " 结束。"
                 : "your program stopped while " + doing + " with exit code " + std::to_string(result.exit_code) + ".";
}

Image difference_heat_map(const Image& yours, const Image& reference) {
  Image map(yours.width(), yours.height());
  for (int y = 0; y < yours.height(); ++y)
    for (int x = 0; x < yours.width(); ++x) {
      int largest = 0;
      for (int c = 0; c < 3; ++c)
        largest = std::max(largest, std::abs(static_cast<int>(srgb_byte(yours.at(x, y)[c])) -
                                             static_cast<int>(srgb_byte(reference.at(x, y)[c]))));
      const float d = std::min(1.0f, static_cast<float>(largest) / 25.5f);  // a tenth of 255: full
      // Black, then red (d = 0.5), then yellow (d = 1), as linear values the PNG's sRGB keeps.
      map.at(x, y) = glm::vec3(std::min(1.0f, 2.0f * d), std::max(0.0f, 2.0f * d - 1.0f), 0.0f);
    }
  return map;
}

ViewServer::ViewServer(ViewOptions options) : options_(std::move(options)) {
  sum_.assign(static_cast<std::size_t>(options_.camera.width) * static_cast<std::size_t>(options_.camera.height),
              glm::dvec3(0.0));
}

ViewServer::~ViewServer() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_requested_ = true;
    if (const int group = running_group_id.load()) ::kill(-group, SIGKILL);
  }
  if (worker_thread_.joinable()) worker_thread_.join();
}

int ViewServer::running_group() { return running_group_id.load(); }

std::string ViewServer::words(const char* english, const char* chinese) const {
  return options_.chinese ? chinese : english;
}

void ViewServer::start() {
  std::lock_guard<std::mutex> lock(mutex_);
  renderer_identity_ = renderer_identity();
  state_ = State::Starting;
  pass_started_ = Clock::now();
  worker_thread_ = std::thread([this] { render_from(0); });
}

// The renderer's file as it is now (to tell a rebuilt program from the one that rendered so far).
std::string ViewServer::renderer_identity() const {
  struct stat file {};
  if (::stat(options_.renderer.c_str(), &file) != 0) return "";
  return std::to_string(file.st_ino) + ":" + std::to_string(file.st_size) + ":" + std::to_string(file.st_mtim.tv_sec) +
         "." + std::to_string(file.st_mtim.tv_nsec);
}

std::optional<std::pair<std::string, int>> checked_tree_json(const std::string& text) {
  constexpr std::size_t kMostTreeLevels = 256, kMostTreeBoxes = 1u << 20;
  const nlohmann::json parsed = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!parsed.is_object() || !parsed.contains("levels") || !parsed["levels"].is_array() ||
      parsed["levels"].size() > kMostTreeLevels)
    return std::nullopt;
  nlohmann::json levels = nlohmann::json::array();
  std::size_t boxes = 0;
  for (const nlohmann::json& level : parsed["levels"]) {
    if (!level.is_array() || (boxes += level.size()) > kMostTreeBoxes) return std::nullopt;
    nlohmann::json rectangles = nlohmann::json::array();
    for (const nlohmann::json& box : level) {
      if (!box.is_array() || box.size() != 4) return std::nullopt;
      std::array<double, 4> corners{};
      for (std::size_t k = 0; k < 4; ++k) {
        if (!box[k].is_number() || !std::isfinite(box[k].get<double>())) return std::nullopt;
        corners[k] = box[k].get<double>();
      }
      rectangles.push_back(corners);
    }
    levels.push_back(std::move(rectangles));
  }
  const int count = static_cast<int>(levels.size());
  return std::make_pair(nlohmann::json{{"levels", std::move(levels)}}.dump(), count);
}

void ViewServer::render_from(int first_sample) {
  std::vector<std::string> arguments{options_.renderer, "view-worker", options_.scene_path, "--frames-fd", "3",
                                     "--first-sample", std::to_string(first_sample)};
  if (first_sample == 0) arguments.push_back("--tree");
  arguments.insert(arguments.end(), options_.render_arguments.begin(), options_.render_arguments.end());
  Spawned child = spawn(arguments, /*merge_errors=*/true, /*frames=*/true);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (child.pid < 0) {
      state_ = State::Failed;
      message_ = words("cannot start your program: ", "无法启动你的程序：") + child.error;
      return;
    }
    running_group_id = child.pid;
    // A stop that came while it started: it goes at once.
    if (stop_requested_) ::kill(-child.pid, SIGKILL);
  }
  // What it prints, read beside the frames.
  std::thread output_reader([this, fd = child.out] {
    char buffer[4096];
    for (;;) {
      const ssize_t got = ::read(fd, buffer, sizeof buffer);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) break;
      std::lock_guard<std::mutex> lock(mutex_);
      append_tail(output_, buffer, static_cast<std::size_t>(got), 16384);
    }
    ::close(fd);
  });
  const std::size_t pixels = sum_.size();
  std::vector<glm::vec3> pass(pixels);
  std::string line, broken;
  while (read_line(child.frames, line)) {
    std::istringstream fields(line);
    std::string kind;
    fields >> kind;
    if (kind == "tree") {
      std::size_t size = 0;
      if (!(fields >> size) || size > (64u << 20)) {
        broken = line;
        break;
      }
      std::string tree(size, '\0');
      if (!read_exactly(child.frames, tree.data(), size)) break;
      const std::optional<std::pair<std::string, int>> checked = checked_tree_json(tree);
      std::lock_guard<std::mutex> lock(mutex_);
      if (checked) std::tie(tree_json_, tree_levels_) = *checked;
      state_ = State::Rendering;
      continue;
    }
    if (kind == "pass") {
      int first = 0, count = 0;
      double seconds = 0.0;
      unsigned long long rays = 0;
      // The samples that come next, as the worker was asked for them, in a time that is one.
      if (!(fields >> first >> count >> seconds >> rays) || first < 0 || count < 1 || first > options_.goal ||
          count > options_.goal - first || !(seconds >= 0.0 && seconds < 1e9) ||
          !read_exactly(child.frames, pass.data(), pixels * sizeof(glm::vec3))) {
        broken = line;
        break;
      }
      std::lock_guard<std::mutex> lock(mutex_);
      state_ = State::Rendering;
      if (first != samples_done_) continue;  // not the pass that comes next: not ours to add
      for (std::size_t i = 0; i < pixels; ++i) sum_[i] += glm::dvec3(pass[i]) * static_cast<double>(count);
      samples_done_ += count;
      seconds_done_ += seconds;
      rays_done_ += rays;
      ++version_;
      pass_started_ = Clock::now();
      continue;
    }
    if (kind == "rate") {
      if (!read_exactly(child.frames, pass.data(), pixels * sizeof(glm::vec3))) break;
      Image rate(options_.camera.width, options_.camera.height);
      for (int y = 0, i = 0; y < rate.height(); ++y)
        for (int x = 0; x < rate.width(); ++x) rate.at(x, y) = pass[static_cast<std::size_t>(i++)];
      std::lock_guard<std::mutex> lock(mutex_);
      rate_ = std::move(rate);
      ++version_;
      continue;
    }
    broken = line;
    break;
  }
  ::close(child.frames);
  // Its end: known (not reaped) before its group is killed, so that the group's number is still
  // its own, and the state is set before a stop could take this end for its own.
  siginfo_t info{};
  while (::waitid(P_PID, static_cast<id_t>(child.pid), &info, WEXITED | WNOWAIT) < 0 && errno == EINTR) {
  }
  ChildResult result;
  result.started = true;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ::kill(-child.pid, SIGKILL);  // whatever it left behind in its group
    running_group_id = 0;
  }
  int status = 0;
  while (::waitpid(child.pid, &status, 0) < 0 && errno == EINTR) {
  }
  output_reader.join();
  record_end(result, status);
  std::lock_guard<std::mutex> lock(mutex_);
  result.output = output_;
  if (stop_requested_) {
    state_ = State::Stopped;
  } else if (!broken.empty()) {
    state_ = State::Failed;
    message_ = words("your program sent the view something it does not understand: ", "你的程序向预览发送了无法理解的内容：") +
               broken.substr(0, 80);
  } else if (result.exit_code == 0 && samples_done_ >= options_.goal) {
    state_ = State::Done;
  } else {
    state_ = State::Failed;
    message_ = describe_child_end(result, words("rendering", "渲染"), options_.chinese);
    if (!options_.chinese && !message_.empty() && message_.back() != '.') message_ += '.';
    if (options_.chinese && (message_.size() < 3 || message_.compare(message_.size() - 3, 3, "。") != 0)) message_ += "。";
    message_ += words(" The page stays up: fix your code, build it again and press continue.",
                      "页面仍然可用：修改代码、重新编译后按“继续”。");
  }
}

Image ViewServer::picture_locked() const {
  Image image(options_.camera.width, options_.camera.height);
  const double scale = samples_done_ > 0 ? 1.0 / samples_done_ : 0.0;
  for (int y = 0, i = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) image.at(x, y) = glm::vec3(sum_[static_cast<std::size_t>(i++)] * scale);
  return image;
}

std::string ViewServer::status_json() {
  std::lock_guard<std::mutex> lock(mutex_);
  const char* state = state_ == State::Starting    ? "starting"
                      : state_ == State::Rendering ? "rendering"
                      : state_ == State::Stopped   ? "stopped"
                      : state_ == State::Done      ? "done"
                                                   : "failed";
  const bool running = state_ == State::Starting || state_ == State::Rendering;
  const double pass_seconds = running ? seconds_since(pass_started_) : 0.0;
  const double seconds = seconds_done_ + pass_seconds;
  double left = -1.0;
  if (samples_done_ > 0) left = std::max(0.0, seconds_done_ / samples_done_ * (options_.goal - samples_done_) - pass_seconds);
  if (state_ == State::Done) left = 0.0;
  std::string message = message_;
  if (running && pass_seconds > 30.0)
    message = options_.chinese ? "已经 " + format_duration(pass_seconds) +
                                     " 没有新的一遍完成：如果你的代码陷入了死循环，请按“停止”。"
                               : "no pass has finished for " + format_duration(pass_seconds) +
                                     ": if your code loops forever, press stop.";
  nlohmann::json views = nlohmann::json::array();
  if (version_ > 0 && samples_done_ > 0) views.push_back("yours");
  if (options_.reference) {
    views.push_back("reference");
    if (samples_done_ > 0) views.push_back("difference");
  }
  if (rate_) views.push_back("samples");
  const nlohmann::json status{{"scene", options_.scene_path},
                              {"width", options_.camera.width},
                              {"height", options_.camera.height},
                              {"integrator", options_.integrator},
                              {"language", options_.chinese ? "zh" : "en"},
                              {"state", state},
                              {"samples_per_pixel", samples_done_},
                              {"goal", options_.goal},
                              {"seconds", seconds},
                              {"seconds_left", left},
                              {"rays_per_second", seconds_done_ > 0.0 ? rays_done_ / seconds_done_ : 0.0},
                              {"version", version_},
                              {"message", message},
                              {"output", output_},
                              {"views", views},
                              {"reference_note", options_.reference_note},
                              {"tree_levels", tree_levels_}};
  return status.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string ViewServer::tree_json() {
  std::lock_guard<std::mutex> lock(mutex_);
  const std::string note =
      tree_levels_ > 0 ? ""
                       : words("no tree: the scene has too few objects for one, or stage 05 (build_bvh, intersect_bvh) "
                               "or stage 04 is not written yet",
                               "没有树：场景的物体太少而不需要树，或者阶段 05（build_bvh、intersect_bvh）或阶段 04 还没有编写");
  // tree_json_ is the server's own writing ({"levels": ...}): the note goes in beside it.
  const std::string levels = tree_json_.empty() ? "{\"levels\":[]}" : tree_json_;
  return levels.substr(0, levels.size() - 1) + ",\"note\":" + nlohmann::json(note).dump() + "}";
}

std::optional<std::string> ViewServer::picture_png(const std::string& view) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (cached_version_ == version_ && cached_view_ == view) return cached_png_;
  Image picture;
  if (view == "yours" && samples_done_ > 0) {
    picture = picture_locked();
  } else if (view == "reference" && options_.reference) {
    picture = *options_.reference;
  } else if (view == "difference" && options_.reference && samples_done_ > 0) {
    picture = difference_heat_map(picture_locked(), *options_.reference);
  } else if (view == "samples" && rate_) {
    // White: the most samples a pixel got (by noise a pixel may get many times the average).
    float most = 0.0f;
    for (const glm::vec3& rate : rate_->pixels()) most = std::max(most, rate.x);
    picture = *rate_;
    if (most > 0.0f)
      for (int y = 0; y < picture.height(); ++y)
        for (int x = 0; x < picture.width(); ++x) picture.at(x, y) /= most;
  } else {
    return std::nullopt;
  }
  cached_png_ = encode_png(picture);
  cached_version_ = version_;
  cached_view_ = view;
  return cached_png_;
}

std::string ViewServer::stop() {
  std::lock_guard<std::mutex> lock(mutex_);
  const int group = running_group_id.load();
  if (group == 0) return nlohmann::json{{"ok", false}, {"error", words("nothing is rendering", "没有正在进行的渲染")}}.dump();
  stop_requested_ = true;
  ::kill(-group, SIGKILL);
  return nlohmann::json{{"ok", true}}.dump();
}

std::string ViewServer::go_on() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (running_group_id.load() != 0 || state_ == State::Starting || state_ == State::Rendering)
    return nlohmann::json{{"ok", false}, {"error", words("it is rendering already", "已经在渲染了")}}.dump();
  if (samples_done_ >= options_.goal && renderer_identity() == renderer_identity_)
    return nlohmann::json{{"ok", false}, {"error", words("the picture is done", "图像已经完成")}}.dump();
  // A program built again since the picture began: its picture starts afresh (the old samples
  // are another program's), the tree too.
  const std::string identity = renderer_identity();
  if (identity != renderer_identity_) {
    renderer_identity_ = identity;
    std::fill(sum_.begin(), sum_.end(), glm::dvec3(0.0));
    samples_done_ = 0;
    seconds_done_ = 0.0;
    rays_done_ = 0;
    rate_.reset();
    tree_json_.clear();
    tree_levels_ = 0;
    output_.clear();
    ++version_;
  }
  const int first = samples_done_;
  stop_requested_ = false;
  message_.clear();
  state_ = State::Starting;
  pass_started_ = Clock::now();
  lock.unlock();
  if (worker_thread_.joinable()) worker_thread_.join();  // it ended: it set the state above
  worker_thread_ = std::thread([this, first] { render_from(first); });
  return nlohmann::json{{"ok", true}}.dump();
}

std::string ViewServer::trace_json(int x, int y) {
  const auto failure = [](const std::string& error) {
    return nlohmann::json{{"ok", false}, {"error", error}}.dump(-1, ' ', false,
                                                                nlohmann::json::error_handler_t::replace);
  };
  if (x < 0 || y < 0 || x >= options_.camera.width || y >= options_.camera.height)
    return failure(words("that pixel is outside the picture", "这个像素在图像之外"));
  std::vector<std::string> arguments{options_.renderer, "trace", options_.scene_path, "--json", "--pixel",
                                     std::to_string(x), std::to_string(y)};
  // The trace takes the render's options but those only a render has.
  for (std::size_t i = 0; i < options_.render_arguments.size(); ++i) {
    const std::string& word = options_.render_arguments[i];
    if (word == "--threads" || word == "--adaptive" || word == "--adaptive-batch") {
      ++i;
      continue;
    }
    if (word == "--spp-by-noise" || word == "--watertight") continue;
    arguments.push_back(word);
  }
  if (options_.chinese) {
    arguments.push_back("--lang");
    arguments.push_back("zh");
  }
  // One trace at a time: a click while another is traced ends that one (its answer is no longer
  // awaited), so that clicks on code that loops do not pile up processes.
  std::unique_lock<std::mutex> one_trace(trace_mutex_);
  const std::uint64_t mine = ++trace_number_;
  if (const int previous = trace_group_.load()) ::kill(-previous, SIGKILL);
  one_trace.unlock();
  std::lock_guard<std::mutex> tracing(tracing_mutex_);  // the previous one has ended
  if (trace_number_.load() != mine) return failure(words("a later click replaced this trace", "之后的点击取代了这次跟踪"));
  const ChildResult result = run_child(arguments, options_.trace_seconds, 4u << 20, &trace_group_);
  if (trace_number_.load() != mine) return failure(words("a later click replaced this trace", "之后的点击取代了这次跟踪"));
  if (result.started && !result.timed_out && result.exit_code == 0) {
    const nlohmann::json trace = nlohmann::json::parse(result.output, nullptr, false);
    if (trace.is_object() && trace.value("ok", false)) return result.output;
  }
  return failure(describe_child_end(result, words("tracing this pixel", "跟踪这个像素"), options_.chinese));
}

}  // namespace raylab::view
