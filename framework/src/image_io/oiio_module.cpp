// The framework's image I/O through OpenImageIO, built as the shared module raylab_image_io
// (see image_io_module.h for why). The only file that includes OpenImageIO.
#include "image_io_module.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <exception>
#include <vector>

#if defined(_WIN32)
#define RAYLAB_MODULE_EXPORT extern "C" __declspec(dllexport)
#else
#define RAYLAB_MODULE_EXPORT extern "C" __attribute__((visibility("default")))
#endif

namespace raylab::image_io {
namespace {

namespace oiio = OIIO;

oiio::ImageBuf to_image_buf(const Image& image) {
  oiio::ImageSpec spec(image.width(), image.height(), 3, oiio::TypeDesc::FLOAT);
  oiio::ImageBuf buf(spec);
  buf.set_pixels(oiio::ROI::All(), oiio::TypeDesc::FLOAT, image.pixels().data());
  return buf;
}

Image from_image_buf(const oiio::ImageBuf& buf) {
  const oiio::ImageSpec& spec = buf.spec();
  Image image(spec.width, spec.height);
  // Take the first three channels (grey is repeated into RGB).
  oiio::ImageBuf rgb = oiio::ImageBufAlgo::channels(
      buf, 3, spec.nchannels >= 3 ? std::vector<int>{0, 1, 2} : std::vector<int>{0, 0, 0});
  rgb.get_pixels(oiio::ROI::All(), oiio::TypeDesc::FLOAT, image.data());
  return image;
}

// OpenImageIO's reason for a failure, never "" (which would read as success).
std::string failure(const std::string& reason) {
  return reason.empty() ? "OpenImageIO gave no reason" : reason;
}

// Runs `body`, turning any exception into the reason string (nothing throws out of a module).
template <typename Body>
std::string reason_of(Body&& body) {
  try {
    return body();
  } catch (const std::exception& error) {
    return error.what();
  } catch (...) {
    return "unknown error in OpenImageIO";
  }
}

std::string write(const Image& image, const std::string& path, bool linear_float) {
  return reason_of([&]() -> std::string {
    oiio::ImageBuf linear = to_image_buf(image);
    if (linear_float) {  // exr: linear float, as in memory
      if (linear.write(path, oiio::TypeDesc::FLOAT)) return "";
      return failure(linear.geterror());
    }
    // png, ppm: 8-bit sRGB
    oiio::ImageBuf srgb = oiio::ImageBufAlgo::colorconvert(linear, "linear", "sRGB");
    srgb = oiio::ImageBufAlgo::clamp(srgb, 0.0f, 1.0f);
    // Quantise in memory and hand the writer 8-bit data: OpenImageIO 2.5's PNM writer flips
    // the rows of float data it is given (its PFM convention) even when it writes an 8-bit PPM.
    oiio::ImageBuf srgb8;
    if (!srgb.has_error() && srgb8.copy(srgb, oiio::TypeDesc::UINT8) &&
        srgb8.write(path, oiio::TypeDesc::UINT8))
      return "";
    return failure(srgb.has_error() ? srgb.geterror() : srgb8.geterror());
  });
}

std::string read(const std::string& path, Image& image) {
  return reason_of([&]() -> std::string {
    oiio::ImageBuf buf(path);
    if (!buf.read(0, 0, true, oiio::TypeDesc::FLOAT)) return failure(buf.geterror());
    const oiio::TypeDesc stored = buf.nativespec().format;  // the file's, not the float copy's
    if (stored == oiio::TypeDesc::UINT8 || stored == oiio::TypeDesc::UINT16)
      buf = oiio::ImageBufAlgo::colorconvert(buf, "sRGB", "linear");
    if (buf.has_error()) return failure(buf.geterror());
    image = from_image_buf(buf);
    return "";
  });
}

std::string compare(const Image& actual, const Image& expected, float threshold,
                    ImageDifference& difference) {
  return reason_of([&]() -> std::string {
    const oiio::ImageBuf a = to_image_buf(actual), b = to_image_buf(expected);
    const auto result = oiio::ImageBufAlgo::compare(a, b, threshold, threshold);
    difference = ImageDifference{};
    difference.mean_error = result.meanerror;
    difference.rms_error = result.rms_error;
    difference.psnr = result.PSNR;
    difference.max_error = result.maxerror;
    difference.max_x = result.maxx;
    difference.max_y = result.maxy;
    difference.pixels_over_threshold = static_cast<long long>(result.nfail);
    const double pixel_count = static_cast<double>(actual.width()) * actual.height();
    difference.fraction_over_threshold =
        pixel_count > 0 ? static_cast<double>(result.nfail) / pixel_count : 0.0;
    return "";
  });
}

std::string resize(const Image& image, int width, int height, Image& resized) {
  return reason_of([&]() -> std::string {
    const oiio::ImageBuf source = to_image_buf(image);
    const oiio::ImageBuf result =
        oiio::ImageBufAlgo::resize(source, "", 0.0f, oiio::ROI(0, width, 0, height, 0, 1, 0, 3));
    if (result.has_error()) return failure(result.geterror());
    resized = from_image_buf(result);
    return "";
  });
}

std::string side_by_side_difference(const Image& actual, const Image& expected, float full_scale,
                                    Image& picture) {
  return reason_of([&]() -> std::string {
    const oiio::ImageBuf a = to_image_buf(actual), b = to_image_buf(expected);
    oiio::ImageBuf difference = oiio::ImageBufAlgo::absdiff(a, b);
    difference = oiio::ImageBufAlgo::maxchan(difference);
    difference = oiio::ImageBufAlgo::mul(difference, 1.0f / full_scale);
    difference = oiio::ImageBufAlgo::clamp(difference, 0.0f, 1.0f);
    difference = oiio::ImageBufAlgo::color_map(difference, 0, "inferno");
    const int w = actual.width(), h = actual.height();
    oiio::ImageBuf canvas(oiio::ImageSpec(3 * w, h, 3, oiio::TypeDesc::FLOAT));
    oiio::ImageBufAlgo::paste(canvas, 0, 0, 0, 0, a);
    oiio::ImageBufAlgo::paste(canvas, w, 0, 0, 0, b);
    // The heat map is a display colour already: store it linear so that PNG output shows it as is.
    difference = oiio::ImageBufAlgo::colorconvert(difference, "sRGB", "linear");
    oiio::ImageBufAlgo::paste(canvas, 2 * w, 0, 0, 0, difference);
    picture = from_image_buf(canvas);
    return "";
  });
}

const ModuleFunctions kFunctions = [] {
  ModuleFunctions functions;
  functions.write = write;
  functions.read = read;
  functions.compare = compare;
  functions.resize = resize;
  functions.side_by_side_difference = side_by_side_difference;
  return functions;
}();

}  // namespace
}  // namespace raylab::image_io

RAYLAB_MODULE_EXPORT const raylab::image_io::ModuleFunctions* raylab_image_io_module_functions() {
  return &raylab::image_io::kFunctions;
}
