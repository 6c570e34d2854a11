#include "raylab/image.h"

#include "image_io/image_io_module.h"
#include "raylab/error.h"

#include <algorithm>
#include <future>
#include <mutex>
#include <stdexcept>
#include <system_error>

namespace raylab {
namespace {

std::string lower_extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// The background load of an ImageIoPreload, if one was started (image.h).
std::mutex preload_mutex;
std::shared_future<void> preload;

void wait_for_preload() {
  std::shared_future<void> pending;
  {
    std::lock_guard<std::mutex> lock(preload_mutex);
    pending = preload;
  }
  if (pending.valid()) pending.wait();
}

// Every image call waits for a background load first: OpenImageIO is then never used from two
// threads at once by the framework.
const image_io::ModuleFunctions& oiio() {
  wait_for_preload();
  return image_io::load_image_io_module();
}

}  // namespace

ImageIoPreload::ImageIoPreload() {
  std::lock_guard<std::mutex> lock(preload_mutex);
  if (preload.valid()) return;  // started already (and the module, once loaded, stays)
  try {
    preload = std::async(std::launch::async, [] {
                try {
                  // The module's one-time work too, so that the first write is as fast as the next.
                  image_io::load_image_io_module().warm_up();
                } catch (...) {
                  // Reported by the first image call, which tries again.
                }
              }).share();
  } catch (const std::system_error&) {
    // No thread to be had: the first image call loads the module itself.
  }
}

ImageIoPreload::~ImageIoPreload() { wait_for_preload(); }

void check_image_extension(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext != "png" && ext != "exr" && ext != "ppm")
    throw InputError(path + ": unknown image extension '." + ext + "' (use .png, .exr or .ppm)");
}

void write_image(const Image& image, const std::string& path) {
  check_image_extension(path);
  const bool linear_float = lower_extension(path) == "exr";  // png, ppm: 8-bit sRGB
  const std::string reason = oiio().write(image, path, linear_float);
  if (!reason.empty()) throw InputError(path + ": cannot write image: " + reason);
}

Image read_image(const std::string& path) {
  Image image;
  const std::string reason = oiio().read(path, image);
  if (!reason.empty()) throw InputError(path + ": cannot read image: " + reason);
  return image;
}

ImageDifference compare_images(const Image& actual, const Image& expected, float threshold) {
  if (actual.width() != expected.width() || actual.height() != expected.height())
    throw std::invalid_argument("compare_images: sizes differ (" + std::to_string(actual.width()) +
                                "x" + std::to_string(actual.height()) + " against " +
                                std::to_string(expected.width()) + "x" +
                                std::to_string(expected.height()) + ")");
  ImageDifference difference;
  const std::string reason = oiio().compare(actual, expected, threshold, difference);
  if (!reason.empty()) throw std::runtime_error("compare_images: " + reason);
  return difference;
}

Image resize_image(const Image& image, int width, int height) {
  Image resized;
  const std::string reason = oiio().resize(image, width, height, resized);
  if (!reason.empty()) throw std::runtime_error("resize_image: " + reason);
  return resized;
}

Image side_by_side_difference(const Image& actual, const Image& expected, float full_scale) {
  Image picture;
  const std::string reason = oiio().side_by_side_difference(actual, expected, full_scale, picture);
  if (!reason.empty()) throw std::runtime_error("side_by_side_difference: " + reason);
  return picture;
}

}  // namespace raylab
