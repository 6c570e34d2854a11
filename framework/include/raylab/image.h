// Float linear-RGB images in memory, and their files.
//
// On disk, by the extension: .png and .ppm (binary P6) are 8-bit sRGB (srgb_byte below), the
// PNG written with libpng and the PPM by the framework itself; .exr keeps linear float values
// and goes through OpenImageIO, as does reading any file and comparing images. The framework
// loads OpenImageIO (about 260 shared libraries) only on the first call that needs it
// (framework/src/image_io/), so that programs that write no EXR and read no image never do.
#pragma once

#include "raylab/math.h"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace raylab {

class Image {
 public:
  Image() = default;
  Image(int width, int height, glm::vec3 fill = glm::vec3(0.0f))
      : width_(width), height_(height),
        pixels_(static_cast<std::size_t>(width < 0 ? 0 : width) *
                    static_cast<std::size_t>(height < 0 ? 0 : height),
                fill) {
    if (width < 0 || height < 0) throw std::invalid_argument("image: negative size");
  }

  int width() const { return width_; }
  int height() const { return height_; }
  // (x, y) = (column, row), row 0 at the top.
  glm::vec3& at(int x, int y) { return pixels_[static_cast<std::size_t>(y) * width_ + x]; }
  const glm::vec3& at(int x, int y) const {
    return pixels_[static_cast<std::size_t>(y) * width_ + x];
  }
  const std::vector<glm::vec3>& pixels() const { return pixels_; }
  glm::vec3* data() { return pixels_.data(); }  // row-major, RGB float

 private:
  int width_ = 0, height_ = 0;
  std::vector<glm::vec3> pixels_;
};

// Writes by the path's extension (.png, .exr, .ppm). Throws InputError with the path and the
// reason if the extension is unknown or the file cannot be written.
void write_image(const Image& image, const std::string& path);

// Throws InputError if `path` does not end in an extension write_image knows; call it before
// long work whose result would then be lost.
void check_image_extension(const std::string& path);

// The bytes of the PNG file write_image would write for `image` (`raylab view` serves them).
// Throws std::runtime_error if it cannot.
std::string encode_png(const Image& image);

// Whether write_image(image, path) goes through OpenImageIO (an .exr file).
bool writes_through_openimageio(const std::string& path);

// The byte a .png or .ppm file stores for a linear value: the sRGB curve applied, clamped to
// [0, 1] and rounded to 8 bits, exactly as OpenImageIO 2.4 converted it when it wrote these
// files: below 0 (and -infinity) 0, above 1 (and +infinity, NaN) 255.
std::uint8_t srgb_byte(float linear);

// Loads OpenImageIO (0.16 s on the course's Debian machines: the dynamic loader binds the ~260
// shared libraries it brings) on a background thread from its construction, for a program that
// will write an EXR file: the load then overlaps its work (a render) instead of following it.
// Every OpenImageIO call below waits until that load is done (a failed load is reported by the
// call as it would have been without it), and so does the destructor: keep the object until the
// images are written, and do not leave the program (std::exit) while it lives, as the exit
// would destroy OpenImageIO's static objects under the load. Only the first object of a
// process starts a load (later ones wait for it); where no thread can be started, none does,
// and the first image call loads OpenImageIO itself. A render that fails after the load
// started (a stage not written yet) waits for it too, up to about 0.2 s, before it reports.
class ImageIoPreload {
 public:
  ImageIoPreload();
  ~ImageIoPreload();
  ImageIoPreload(const ImageIoPreload&) = delete;
  ImageIoPreload& operator=(const ImageIoPreload&) = delete;
};

// Reads any format OpenImageIO knows into linear RGB (8-bit files are taken as sRGB).
// Throws InputError with the path and reason if it cannot.
Image read_image(const std::string& path);

// How two images of the same size differ, per channel value (OpenImageIO's compare).
struct ImageDifference {
  double mean_error = 0.0;
  double rms_error = 0.0;
  double psnr = 0.0;
  double max_error = 0.0;
  int max_x = 0, max_y = 0;           // where max_error is
  long long pixels_over_threshold = 0;  // pixels with a channel differing by more than threshold
  double fraction_over_threshold = 0.0;
};

// Compares two images of the same size (throws std::invalid_argument otherwise).
ImageDifference compare_images(const Image& actual, const Image& expected, float threshold);

// The image resampled to width x height with OpenImageIO's default filter (to compare images
// of different sizes).
Image resize_image(const Image& image, int width, int height);

// A side-by-side picture for students: actual | expected | difference heat map
// (black = equal, through red to yellow = a difference of `full_scale` or more).
Image side_by_side_difference(const Image& actual, const Image& expected, float full_scale);

}  // namespace raylab
