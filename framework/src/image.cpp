#include "raylab/image.h"

#include "raylab/error.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <stdexcept>

namespace raylab {
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

std::string lower_extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

}  // namespace

Image::Image(int width, int height, glm::vec3 fill)
    : width_(width), height_(height),
      pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), fill) {
  if (width < 0 || height < 0) throw std::invalid_argument("image: negative size");
}

void check_image_extension(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext != "png" && ext != "exr" && ext != "ppm")
    throw InputError(path + ": unknown image extension '." + ext + "' (use .png, .exr or .ppm)");
}

void write_image(const Image& image, const std::string& path) {
  check_image_extension(path);
  const std::string ext = lower_extension(path);
  oiio::ImageBuf linear = to_image_buf(image);
  if (ext == "exr") {  // linear float, as in memory
    if (linear.write(path, oiio::TypeDesc::FLOAT)) return;
    throw InputError(path + ": cannot write image: " + linear.geterror());
  }
  // png, ppm: 8-bit sRGB
  oiio::ImageBuf srgb = oiio::ImageBufAlgo::colorconvert(linear, "linear", "sRGB");
  srgb = oiio::ImageBufAlgo::clamp(srgb, 0.0f, 1.0f);
  if (!srgb.has_error() && srgb.write(path, oiio::TypeDesc::UINT8)) return;
  throw InputError(path + ": cannot write image: " + srgb.geterror());
}

Image read_image(const std::string& path) {
  oiio::ImageBuf buf(path);
  if (!buf.read(0, 0, true, oiio::TypeDesc::FLOAT))
    throw InputError(path + ": cannot read image: " + buf.geterror());
  const oiio::TypeDesc stored = buf.nativespec().format;  // the file's, not the float copy's
  if (stored == oiio::TypeDesc::UINT8 || stored == oiio::TypeDesc::UINT16)
    buf = oiio::ImageBufAlgo::colorconvert(buf, "sRGB", "linear");
  if (buf.has_error()) throw InputError(path + ": cannot read image: " + buf.geterror());
  return from_image_buf(buf);
}

ImageDifference compare_images(const Image& actual, const Image& expected, float threshold) {
  if (actual.width() != expected.width() || actual.height() != expected.height())
    throw std::invalid_argument("compare_images: sizes differ (" + std::to_string(actual.width()) +
                                "x" + std::to_string(actual.height()) + " against " +
                                std::to_string(expected.width()) + "x" +
                                std::to_string(expected.height()) + ")");
  const oiio::ImageBuf a = to_image_buf(actual), b = to_image_buf(expected);
  const auto result = oiio::ImageBufAlgo::compare(a, b, threshold, threshold);
  ImageDifference difference;
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
  return difference;
}

Image resize_image(const Image& image, int width, int height) {
  const oiio::ImageBuf source = to_image_buf(image);
  const oiio::ImageBuf resized =
      oiio::ImageBufAlgo::resize(source, "", 0.0f, oiio::ROI(0, width, 0, height, 0, 1, 0, 3));
  if (resized.has_error()) throw std::runtime_error("resize_image: " + resized.geterror());
  return from_image_buf(resized);
}

Image side_by_side_difference(const Image& actual, const Image& expected, float full_scale) {
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
  return from_image_buf(canvas);
}

}  // namespace raylab
