// The framework's image I/O through OpenImageIO (EXR files, reading, comparisons), built as the
// shared module raylab_image_io (see image_io_module.h for why). The only file that includes
// OpenImageIO.
#include "image_io_module.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
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

// Collects the EXR encoder's output in memory; write_exr() below puts it in the file in one
// call, and removes a file it could not write whole. One encoder writes into one MemoryOutput,
// from one thread: pwrite does not take a lock (OpenImageIO's EXR writer never calls it from
// two threads).
class MemoryOutput final : public oiio::Filesystem::IOProxy {
 public:
  MemoryOutput() : IOProxy("", Write) {}
  const char* proxytype() const override { return "raylab_memory"; }
  size_t write(const void* data, size_t size) override {
    const size_t written = pwrite(data, size, m_pos);
    m_pos += static_cast<int64_t>(written);
    return written;
  }
  size_t pwrite(const void* data, size_t size, int64_t offset) override {
    if (offset < 0) return 0;
    const auto start = static_cast<size_t>(offset);
    if (bytes_.size() < start + size) bytes_.resize(start + size);
    std::memcpy(bytes_.data() + start, data, size);
    return size;
  }
  size_t size() const override { return bytes_.size(); }
  void reserve(size_t size) { bytes_.reserve(size); }
  const std::vector<unsigned char>& bytes() const { return bytes_; }

 private:
  std::vector<unsigned char> bytes_;
};

// Encodes `image` as an OpenEXR file of linear float values, into `memory` where the writer
// takes an I/O proxy (OpenImageIO 2.4 and 2.5's does); a writer without one writes the file
// `path` itself, and `written_to_file` says so. Returns "" or the reason.
std::string encode_exr(const Image& image, const std::string& path, MemoryOutput& memory, bool& written_to_file) {
  written_to_file = false;
  const oiio::ImageSpec spec(image.width(), image.height(), 3, oiio::TypeDesc::FLOAT);
  std::unique_ptr<oiio::ImageOutput> output = oiio::ImageOutput::create(path);
  if (!output) return failure(oiio::geterror());
  if (output->supports("ioproxy")) {
    memory.reserve(spec.image_bytes() + 1024);
    output->set_ioproxy(&memory);
  } else {
    written_to_file = true;
  }
  if (output->open(path, spec) && output->write_image(spec.format, image.pixels().data()) && output->close())
    return "";
  return failure(output->geterror());
}

std::string write_exr(const Image& image, const std::string& path) {
  return reason_of([&]() -> std::string {
    MemoryOutput memory;
    bool written_to_file = false;
    const std::string reason = encode_exr(image, path, memory, written_to_file);
    if (!reason.empty() || written_to_file) return reason;
    FILE* file = oiio::Filesystem::fopen(path, "wb");
    if (file == nullptr) return std::string("cannot open the file: ") + std::strerror(errno);
    errno = 0;
    const size_t written = std::fwrite(memory.bytes().data(), 1, memory.bytes().size(), file);
    const bool closed = std::fclose(file) == 0;
    if (written == memory.bytes().size() && closed) return "";
    const std::string why = errno != 0 ? std::strerror(errno) : "the file is shorter than the image";
    std::string ignored;
    oiio::Filesystem::remove(path, ignored);  // no truncated image left where a whole one may have been
    return "cannot write the file: " + why;
  });
}

// Encodes a tiny EXR image into memory only (no file is written), so that the first real write
// does not pay OpenImageIO's one-time work: finding its EXR plugin, binding its functions,
// starting its thread pool. Called beside a render by an ImageIoPreload (image.h).
void warm_up() {
  (void)reason_of([]() -> std::string {
    const Image tiny(2, 2, glm::vec3(0.5f));
    MemoryOutput memory;
    bool written_to_file = false;
    std::unique_ptr<oiio::ImageOutput> output = oiio::ImageOutput::create("warm_up.exr");
    if (output && output->supports("ioproxy")) (void)encode_exr(tiny, "warm_up.exr", memory, written_to_file);
    return "";
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
    // The largest of the three channels (ImageBufAlgo::maxchan does it from OpenImageIO 2.3.10 on).
    namespace algo = oiio::ImageBufAlgo;
    difference = algo::max(algo::max(algo::channels(difference, 1, {0}), algo::channels(difference, 1, {1})),
                           algo::channels(difference, 1, {2}));
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
  functions.write_exr = write_exr;
  functions.read = read;
  functions.compare = compare;
  functions.resize = resize;
  functions.side_by_side_difference = side_by_side_difference;
  functions.warm_up = warm_up;
  return functions;
}();

}  // namespace
}  // namespace raylab::image_io

RAYLAB_MODULE_EXPORT const raylab::image_io::ModuleFunctions* raylab_image_io_module_functions() {
  return &raylab::image_io::kFunctions;
}
