#include "raylab/image.h"

#include "image_io/image_io_module.h"
#include "raylab/error.h"

#if !defined(RAYLAB_NO_PNG)
#include <png.h>
#endif

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <future>
#include <iterator>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace raylab {
namespace {

std::string lower_extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// The smallest linear value written as each byte from 1 to 255 (srgb_byte). These are the
// steps of the conversion through which OpenImageIO 2.4 (Debian 12) wrote the kit's 8-bit files
// (its colorconvert from "linear" to "sRGB", then get_pixels to 8 bits), found by converting
// every float from 0 to 1 with it. They are not those of the exact sRGB curve: OpenImageIO
// computes the curve's power with a fast approximation, and the exact curve would move 245 of
// these 255 steps by up to 428 floats, so that about one value in ten thousand would be written
// one step apart from the files written before. (OpenImageIO itself wrote one float otherwise,
// 0x391f22b3, as 1 instead of 0 when it was among the last 3 x width mod 4 values of a row.)
constexpr float kSrgbByteStarts[255] = {
    0.0001517635f, 0.0004552905f, 0.0007588175f, 0.0010623444f, 0.0013658715f, 0.0016693984f, 0.0019729254f, 0.0022764525f,
    0.0025799794f, 0.0028835065f, 0.003188334f, 0.0035092942f, 0.0038483506f, 0.0042057773f, 0.0045818537f, 0.0049768514f,
    0.005391034f, 0.0058246525f, 0.0062779696f, 0.0067512253f, 0.007244695f, 0.007758415f, 0.008292853f, 0.008848222f,
    0.009424745f, 0.010022623f, 0.010642074f, 0.011283303f, 0.011946527f, 0.012631947f, 0.013339761f, 0.014070186f,
    0.014823423f, 0.015599651f, 0.016399074f, 0.017221896f, 0.018068306f, 0.018938486f, 0.019832628f, 0.020750921f,
    0.02169354f, 0.022660691f, 0.023652518f, 0.024669224f, 0.025710981f, 0.026777953f, 0.027870322f, 0.028988259f,
    0.030131925f, 0.031301487f, 0.032497138f, 0.033718992f, 0.03496724f, 0.036243055f, 0.03754397f, 0.03887187f,
    0.040226888f, 0.041609168f, 0.043018848f, 0.044456083f, 0.04592101f, 0.04741375f, 0.04893447f, 0.05048331f,
    0.052060384f, 0.053665873f, 0.055299867f, 0.056962542f, 0.058654036f, 0.060374472f, 0.062123984f, 0.063902706f,
    0.06571077f, 0.06754835f, 0.06941553f, 0.07131247f, 0.07323931f, 0.07519617f, 0.07718318f, 0.07920047f,
    0.08124816f, 0.08332642f, 0.08543534f, 0.08757506f, 0.0897457f, 0.09194741f, 0.0941803f, 0.09644449f,
    0.0987401f, 0.10106727f, 0.10342612f, 0.10581676f, 0.10823935f, 0.11069395f, 0.113180734f, 0.11569978f,
    0.118251264f, 0.1208353f, 0.12345192f, 0.12610132f, 0.12878357f, 0.13149884f, 0.1342472f, 0.13702875f,
    0.13984367f, 0.14269204f, 0.14557396f, 0.14848955f, 0.15143895f, 0.15442224f, 0.1574395f, 0.16049093f,
    0.16357657f, 0.16669653f, 0.16985096f, 0.1730399f, 0.17626353f, 0.17952198f, 0.18281524f, 0.1861435f,
    0.18951309f, 0.19290991f, 0.19634211f, 0.1998099f, 0.20331334f, 0.20685242f, 0.21042743f, 0.21403842f,
    0.21768531f, 0.2213684f, 0.22508761f, 0.22884321f, 0.23263523f, 0.23646365f, 0.24032868f, 0.24423037f,
    0.24816886f, 0.25214413f, 0.25615647f, 0.26020575f, 0.26429224f, 0.26841587f, 0.27257684f, 0.27677527f,
    0.28101122f, 0.2852847f, 0.28959596f, 0.29394493f, 0.29833186f, 0.30275664f, 0.30721956f, 0.3117205f,
    0.3162598f, 0.3208374f, 0.3254534f, 0.33010787f, 0.33480102f, 0.33953282f, 0.3443034f, 0.34911293f,
    0.3539612f, 0.3588487f, 0.36377516f, 0.368741f, 0.37374604f, 0.37879056f, 0.38387445f, 0.38899797f,
    0.39416113f, 0.39936408f, 0.40460673f, 0.4098894f, 0.41521198f, 0.42057478f, 0.42597774f, 0.4314209f,
    0.4369043f, 0.4424283f, 0.44799265f, 0.4535978f, 0.45924342f, 0.4649301f, 0.47065738f, 0.4764256f,
    0.48223493f, 0.48808524f, 0.49397692f, 0.4999098f, 0.50588405f, 0.51189953f, 0.5179567f, 0.5240555f,
    0.53019583f, 0.536378f, 0.542602f, 0.5488678f, 0.5551758f, 0.56152564f, 0.56791794f, 0.57435226f,
    0.580829f, 0.5873481f, 0.5939096f, 0.6005138f, 0.6071607f, 0.61385006f, 0.62058246f, 0.6273575f,
    0.63417566f, 0.6410368f, 0.64794093f, 0.65488833f, 0.66187906f, 0.66891307f, 0.67599064f, 0.68311155f,
    0.6902761f, 0.69748425f, 0.70473605f, 0.7120317f, 0.7193712f, 0.7267548f, 0.73418224f, 0.7416539f,
    0.74916965f, 0.7567296f, 0.76433396f, 0.77198267f, 0.7796759f, 0.78741354f, 0.7951958f, 0.80302304f,
    0.8108948f, 0.8188114f, 0.826773f, 0.8347794f, 0.842831f, 0.85092777f, 0.8590696f, 0.86725676f,
    0.87548923f, 0.88376725f, 0.8920906f, 0.90045965f, 0.90887403f, 0.9173346f, 0.9258406f, 0.93439263f,
    0.9429903f, 0.95163417f, 0.96032387f, 0.9690599f, 0.9778419f, 0.9866704f, 0.9955453f,
};

// srgb_byte for a whole picture, without its binary search per value (a fifth of a Whitted
// render's whole process): the byte at the start of each run of 2^16 floats from 0 up to 1, by
// their bits (16 256 runs), and as a run holds at most one of the steps (the closest two are
// 100 923 floats apart: checked here, else every value takes srgb_byte), one comparison finishes
// it. Outside [0, 1) (negative, 1 and above, NaN): srgb_byte itself. The same bytes as srgb_byte
// for every float.
class SrgbTable {
 public:
  static constexpr int kShift = 16;
  static constexpr std::uint32_t kOne = 0x3f800000u;  // the bits of 1.0f
  SrgbTable() : first_(kOne >> kShift) {
    for (std::size_t k = 0; k + 1 < std::size(kSrgbByteStarts); ++k)
      if ((bits(kSrgbByteStarts[k]) >> kShift) == (bits(kSrgbByteStarts[k + 1]) >> kShift)) return;  // (never)
    for (std::uint32_t run = 0; run < first_.size(); ++run) first_[run] = srgb_byte(from_bits(run << kShift));
    usable_ = true;
  }
  std::uint8_t operator()(float linear) const {
    const std::uint32_t b = bits(linear);
    if (!usable_ || b >= kOne) return srgb_byte(linear);  // (negative values and NaN have the top bits set)
    const std::uint8_t first = first_[b >> kShift];
    return first < 255 && linear >= kSrgbByteStarts[first] ? static_cast<std::uint8_t>(first + 1) : first;
  }

 private:
  static std::uint32_t bits(float value) {
    std::uint32_t b;
    std::memcpy(&b, &value, sizeof b);
    return b;
  }
  static float from_bits(std::uint32_t b) {
    float value;
    std::memcpy(&value, &b, sizeof value);
    return value;
  }
  std::vector<std::uint8_t> first_;
  bool usable_ = false;
};

// The pixels as 8-bit sRGB, row by row, R G B.
std::vector<unsigned char> srgb_bytes(const Image& image) {
  static const SrgbTable to_byte;
  std::vector<unsigned char> bytes(image.pixels().size() * 3);
  unsigned char* out = bytes.data();
  for (const glm::vec3& pixel : image.pixels())
    for (int c = 0; c < 3; ++c) *out++ = to_byte(pixel[c]);
  return bytes;
}

// Binary PPM (P6): a text header, then the bytes. Returns "" or the reason.
std::string write_ppm(const Image& image, const std::string& path) {
  const std::string header =
      "P6\n" + std::to_string(image.width()) + " " + std::to_string(image.height()) + "\n255\n";
  const std::vector<unsigned char> bytes = srgb_bytes(image);
  std::ofstream file(path, std::ios::binary);
  if (!file) return std::string("cannot open the file: ") + std::strerror(errno);
  file << header;
  file.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  file.close();
  if (file) return "";
  std::remove(path.c_str());  // no truncated image left where a whole one may have been
  return "cannot write the whole file";
}

#if !defined(RAYLAB_NO_PNG)
// libpng's simplified API's description of an 8-bit RGB picture of the image's size.
png_image png_of(const Image& image) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width());
  png.height = static_cast<png_uint_32>(image.height());
  png.format = PNG_FORMAT_RGB;
  // Speed before size: the Whitted scene's 1280x960 PNG is written in 1 ms instead of 22 ms
  // (0.125 s against 0.147 s for the whole render), 66 KB instead of 42 KB; the pixels the same.
  png.flags = PNG_IMAGE_FLAG_FAST;
  return png;
}
std::string png_reason(const png_image& png) { return png.message[0] != '\0' ? png.message : "libpng gave no reason"; }
#endif

// PNG through libpng's simplified API, which marks the file as sRGB (its sRGB chunk) and
// removes a file it could not write whole. Returns "" or the reason.
std::string write_png(const Image& image, const std::string& path) {
#if defined(RAYLAB_NO_PNG)
  (void)image;
  (void)path;
  return "this build has no libpng and no OpenImageIO (configured with RAYLAB_WITH_OPENIMAGEIO=OFF, "
         "where CMake found no libpng), so it cannot write .png files (.ppm it can)";
#else
  const std::vector<unsigned char> bytes = srgb_bytes(image);
  png_image png = png_of(image);
  if (png_image_write_to_file(&png, path.c_str(), 0, bytes.data(), 0, nullptr) != 0) return "";
  return png_reason(png);
#endif
}

}  // namespace

std::string encode_png(const Image& image) {
#if defined(RAYLAB_NO_PNG)
  (void)image;
  throw std::runtime_error("this build has no libpng, so it cannot make a PNG picture");
#else
  const std::vector<unsigned char> bytes = srgb_bytes(image);
  // The size first, then the bytes (each call takes a fresh description).
  png_image measure = png_of(image), write = png_of(image);
  png_alloc_size_t size = 0;
  if (png_image_write_to_memory(&measure, nullptr, &size, 0, bytes.data(), 0, nullptr) == 0 || size == 0)
    throw std::runtime_error("cannot make a PNG picture: " + png_reason(measure));
  std::string encoded(size, '\0');
  if (png_image_write_to_memory(&write, encoded.data(), &size, 0, bytes.data(), 0, nullptr) == 0)
    throw std::runtime_error("cannot make a PNG picture: " + png_reason(write));
  encoded.resize(size);
  return encoded;
#endif
}

namespace {

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

// Every OpenImageIO call waits for a background load first: OpenImageIO is then never used
// from two threads at once by the framework.
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

std::uint8_t srgb_byte(float linear) {
  // How many steps start at or below the value; NaN compares false with every one: 255.
  const float* const starts = std::begin(kSrgbByteStarts);
  return static_cast<std::uint8_t>(std::upper_bound(starts, std::end(kSrgbByteStarts), linear) - starts);
}

void check_image_extension(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext != "png" && ext != "exr" && ext != "ppm")
    throw InputError(path + ": unknown image extension '." + ext + "' (use .png, .exr or .ppm)");
}

bool writes_through_openimageio(const std::string& path) { return lower_extension(path) == "exr"; }

void write_image(const Image& image, const std::string& path) {
  check_image_extension(path);
  const std::string ext = lower_extension(path);
  const std::string reason = ext == "png"   ? write_png(image, path)
                             : ext == "ppm" ? write_ppm(image, path)
                                            : oiio().write_exr(image, path);
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
