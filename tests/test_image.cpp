// Images: write_image / read_image round trips, extension checks, and the comparison tools
// the autograder uses (compare_images, side_by_side_difference).
//
// image.h: .exr keeps linear floats exactly; .png (libpng) and .ppm (the framework's own
// writer) store 8-bit sRGB, so a value comes back within half an 8-bit step of sRGB (checked
// below as 1/255 in sRGB units), and each file holds the bytes OpenImageIO wrote for it before
// (EightBitFilesHoldTheBytesOpenImageIoWrote). Reading goes through OpenImageIO.
#include "raylab/error.h"
#include "raylab/image.h"

#include "test_helpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace raylab {
namespace {

using testing::scratch_dir;

// The sRGB transfer curve (IEC 61966-2-1), linear -> encoded, for comparing 8-bit files.
float linear_to_srgb(float linear) {
  const float v = std::clamp(linear, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

// A 4x3 test image whose every pixel differs: a gradient plus a few special values.
Image make_test_image() {
  Image image(4, 3);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      image.at(x, y) = glm::vec3(x / 3.0f, y / 2.0f, (x + 4 * y) / 11.0f);
  image.at(1, 1) = glm::vec3(0.5f, 0.5f, 0.5f);  // mid grey
  image.at(2, 1) = glm::vec3(0.001f, 0.04f, 0.2f);  // the steep toe of the sRGB curve
  return image;
}

std::uint32_t bits_of(float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

std::string read_bytes(const std::filesystem::path& path, std::size_t count) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(count, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(count));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

TEST(Image, ExrRoundTripKeepsExactFloats) {
  // EXR is the reference-image format: any loss would show up as a grading difference.
  Image image = make_test_image();
  image.at(0, 0) = glm::vec3(2.75f, 1000.5f, 1e-6f);      // HDR and tiny values
  image.at(3, 2) = glm::vec3(0.1f, 1.0f / 3.0f, 0.7f);    // not exact in binary
  const std::string path = (scratch_dir() / "round_trip.exr").string();
  write_image(image, path);
  const Image back = read_image(path);
  ASSERT_EQ(back.width(), image.width()) << path;
  ASSERT_EQ(back.height(), image.height()) << path;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(back.at(x, y)[c], image.at(x, y)[c])
            << path << ", pixel (" << x << ", " << y << ") channel " << c;
}

class EightBitImage : public ::testing::TestWithParam<std::string> {};

TEST_P(EightBitImage, RoundTripWithinOneSrgbStep) {
  const Image image = make_test_image();
  const std::string path = (scratch_dir() / ("round_trip." + GetParam())).string();
  write_image(image, path);
  const Image back = read_image(path);
  ASSERT_EQ(back.width(), image.width()) << path;
  ASSERT_EQ(back.height(), image.height()) << path;
  // Linear 0.5 is stored as sRGB 188/255 = 0.737; reading must undo the curve. Getting 0.737
  // back means the file was read as if its 8-bit values were linear.
  EXPECT_NEAR(back.at(1, 1).x, 0.5f, 0.005f) << path << ": mid grey, written as linear 0.5";
  int wrong = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      for (int c = 0; c < 3; ++c) {
        const float written = image.at(x, y)[c], read = back.at(x, y)[c];
        if (std::abs(linear_to_srgb(read) - linear_to_srgb(written)) > 1.0f / 255.0f &&
            ++wrong <= 5)
          ADD_FAILURE() << path << ", pixel (" << x << ", " << y << ") channel " << c
                        << ": wrote linear " << written << " (sRGB " << linear_to_srgb(written)
                        << "), read back linear " << read << " (sRGB " << linear_to_srgb(read)
                        << "); expected within 1/255 in sRGB";
      }
  EXPECT_EQ(wrong, 0) << "channel values off by more than one 8-bit sRGB step, out of "
                      << 3 * image.width() * image.height();
}

TEST_P(EightBitImage, ValuesOutsideZeroToOneAreClamped) {
  Image image(2, 1);
  image.at(0, 0) = glm::vec3(4.0f, 1.5f, 1.0f);
  image.at(1, 0) = glm::vec3(-1.0f, -0.01f, 0.0f);
  const std::string path = (scratch_dir() / ("clamped." + GetParam())).string();
  write_image(image, path);
  const Image back = read_image(path);
  EXPECT_TRUE(testing::vec3_near(back.at(0, 0), glm::vec3(1.0f), 1e-6f)) << path << ": above 1";
  EXPECT_TRUE(testing::vec3_near(back.at(1, 0), glm::vec3(0.0f), 1e-6f)) << path << ": below 0";
}

INSTANTIATE_TEST_SUITE_P(PngAndPpm, EightBitImage, ::testing::Values("png", "ppm"));

// tests/data/eight_bit_input.exr holds 32 x 23 linear values: NaN, -NaN, +-infinity, -0, the
// smallest denormals, values below 0 and above 1 up to the largest float, the first value of
// each byte from 1 to 255 with the floats just below and above it, a gradient from -0.1 to
// 1.3, and random values in [0, 1]. eight_bit_openimageio.png and .ppm are what the framework
// wrote for it through OpenImageIO 2.4 (Debian 12) at 2c4b51e, before it wrote these formats
// itself. (3 x 32 values to a row, a multiple of 4: OpenImageIO wrote the last 3 x width mod 4
// values of a row through another path, which differs for one float; image.cpp.)
TEST(Image, EightBitFilesHoldTheBytesOpenImageIoWrote) {
  const std::string data = testing::source_path("tests/data/eight_bit");
  const Image input = read_image(data + "_input.exr");
  ASSERT_EQ(input.width(), 32);
  ASSERT_EQ(input.height(), 23);
  const std::filesystem::path dir = scratch_dir();
  // PPM: the same file, header and all.
  write_image(input, (dir / "written.ppm").string());
  const std::string ppm = read_bytes(dir / "written.ppm", 1 << 20);
  const std::string expected_ppm = read_bytes(data + "_openimageio.ppm", 1 << 20);
  ASSERT_EQ(ppm.size(), expected_ppm.size()) << dir / "written.ppm";
  const std::size_t header = ppm.size() - 3 * input.pixels().size();
  EXPECT_EQ(ppm.substr(0, header), expected_ppm.substr(0, header)) << "the PPM header";
  // PNG: the same pixels, read back through OpenImageIO (the chunks around them differ).
  write_image(input, (dir / "written.png").string());
  const Image png = read_image((dir / "written.png").string());
  const Image expected_png = read_image(data + "_openimageio.png");
  ASSERT_EQ(png.width(), input.width());
  ASSERT_EQ(png.height(), input.height());
  int wrong = 0;
  for (int y = 0; y < input.height(); ++y)
    for (int x = 0; x < input.width(); ++x)
      for (int c = 0; c < 3; ++c) {
        const std::size_t i = header + 3 * (static_cast<std::size_t>(y) * input.width() + x) + c;
        const float value = input.at(x, y)[c];
        if (ppm[i] != expected_ppm[i] && ++wrong <= 5)
          ADD_FAILURE() << "PPM, pixel (" << x << ", " << y << ") channel " << c << ", linear " << value
                        << " (bits 0x" << std::hex << bits_of(value) << std::dec << "): wrote "
                        << int(static_cast<unsigned char>(ppm[i])) << ", OpenImageIO wrote "
                        << int(static_cast<unsigned char>(expected_ppm[i]));
        if (png.at(x, y)[c] != expected_png.at(x, y)[c] && ++wrong <= 5)
          ADD_FAILURE() << "PNG, pixel (" << x << ", " << y << ") channel " << c << ", linear " << value
                        << " (bits 0x" << std::hex << bits_of(value) << std::dec << "): reads back as "
                        << png.at(x, y)[c] << ", OpenImageIO's file as " << expected_png.at(x, y)[c];
      }
  EXPECT_EQ(wrong, 0) << "values written otherwise than OpenImageIO wrote them, out of 2 x "
                      << 3 * input.pixels().size();
}

// The PPM writer's bytes (image.cpp converts a picture through a table of runs of floats) are
// srgb_byte's for every value: each float within 3 of a step (from 0 to 1 by their bits) and at
// each end of the table's runs of 2^16 floats, 0 and 1, values outside [0, 1], infinities, NaN,
// and 100 000 random values in [0, 1].
TEST(Image, PpmBytesAreSrgbByteOfEveryValue) {
  std::vector<float> values = {0.0f, -0.0f, 1.0f, -1.0f, 2.0f, 1e30f, -1e30f, std::nanf(""),
                               std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                               std::numeric_limits<float>::denorm_min(), std::nextafter(1.0f, 0.0f)};
  const auto from_bits = [](std::uint32_t b) {
    float value;
    std::memcpy(&value, &b, sizeof value);
    return value;
  };
  for (std::uint32_t run = 0; run < (0x3f800000u >> 16); ++run)
    for (const std::uint32_t b : {run << 16, (run << 16) | 0xffffu}) values.push_back(from_bits(b));
  for (float v = 0.0f; v < 1.0f;) {  // each step from 0 to 1, found by srgb_byte itself
    std::uint32_t low = bits_of(v), high = 0x3f800000u;
    const std::uint8_t byte = srgb_byte(v);
    while (high - low > 1) {  // the first float past v with another byte
      const std::uint32_t middle = low + (high - low) / 2;
      (srgb_byte(from_bits(middle)) == byte ? low : high) = middle;
    }
    for (std::uint32_t b = high - 3; b <= high + 3; ++b) values.push_back(from_bits(b));
    v = from_bits(high);
  }
  std::uint64_t state = 12345;
  for (int i = 0; i < 100000; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    values.push_back(static_cast<float>(state >> 40) / static_cast<float>(1ull << 24));
  }
  while (values.size() % 3 != 0) values.push_back(0.5f);
  const int pixels = static_cast<int>(values.size() / 3);
  Image image(pixels, 1);
  std::memcpy(image.data(), values.data(), values.size() * sizeof(float));
  const std::filesystem::path path = scratch_dir() / "every_value.ppm";
  write_image(image, path.string());
  const std::string ppm = read_bytes(path, 1 << 24);
  ASSERT_GE(ppm.size(), values.size());
  const std::size_t header = ppm.size() - values.size();
  int wrong = 0;
  for (std::size_t i = 0; i < values.size(); ++i)
    if (static_cast<std::uint8_t>(ppm[header + i]) != srgb_byte(values[i]) && ++wrong <= 5)
      ADD_FAILURE() << "linear " << values[i] << " (bits 0x" << std::hex << bits_of(values[i]) << std::dec
                    << "): wrote " << int(static_cast<std::uint8_t>(ppm[header + i])) << ", srgb_byte gives "
                    << int(srgb_byte(values[i]));
  EXPECT_EQ(wrong, 0) << "of " << values.size();
  EXPECT_GT(values.size(), 130000u);
}

TEST(Image, OnlyExrIsWrittenThroughOpenImageIo) {
  EXPECT_TRUE(writes_through_openimageio("out.exr"));
  EXPECT_TRUE(writes_through_openimageio("OUT.EXR"));
  for (const std::string path : {"out.png", "out.ppm", "out.PNG", ""})
    EXPECT_FALSE(writes_through_openimageio(path)) << path;
}

TEST(Image, PpmIsBinaryP6AndPngHasItsSignature) {
  // Students open .ppm files in a text editor to debug: it must be the binary P6 variant that
  // the handout describes.
  const std::filesystem::path dir = scratch_dir();
  write_image(make_test_image(), (dir / "image.ppm").string());
  write_image(make_test_image(), (dir / "image.png").string());
  EXPECT_EQ(read_bytes(dir / "image.ppm", 2), "P6") << dir / "image.ppm";
  EXPECT_EQ(read_bytes(dir / "image.png", 4), "\x89PNG") << dir / "image.png";
}

TEST(Image, PngIsMarkedAsSrgb) {
  // The 8-bit files hold sRGB values; a PNG says so in its sRGB chunk, which viewers read.
  const std::filesystem::path path = scratch_dir() / "marked.png";
  write_image(make_test_image(), path.string());
  const std::string bytes = read_bytes(path, 4096);
  const auto data = bytes.find("IDAT");
  ASSERT_NE(data, std::string::npos) << path << " has no image data";
  EXPECT_NE(bytes.substr(0, data).find("sRGB"), std::string::npos) << path << ": no sRGB chunk before the image data";
}

TEST(Image, WritingWhereNoFileCanBeMadeNamesThePath) {
  for (const std::string extension : {"png", "ppm", "exr"}) {
    const std::string path = (scratch_dir() / "no_such_folder" / ("image." + extension)).string();
    try {
      write_image(make_test_image(), path);
      FAIL() << "write_image(" << path << ") returned instead of throwing InputError";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path + ": cannot write image: "), std::string::npos)
          << "the message should name the file; got: " << e.what();
    }
  }
}

TEST(Image, LoadingTheImageIoEarlyChangesNothing) {
  // An image call while a background load runs waits for it; a second preload starts nothing.
  const Image image = make_test_image();
  const std::string path = (scratch_dir() / "after_early_load.exr").string();
  {
    ImageIoPreload preload;
    ImageIoPreload another;
    write_image(image, path);
  }
  ImageIoPreload after_the_load;
  const Image back = read_image(path);
  ASSERT_EQ(back.width(), image.width()) << path;
  EXPECT_EQ(std::memcmp(back.pixels().data(), image.pixels().data(), sizeof(glm::vec3) * image.pixels().size()), 0) << path;
}

TEST(Image, UnknownExtensionThrowsInputError) {
  const std::filesystem::path dir = scratch_dir();
  for (const std::string name : {"picture.bmp", "picture", "picture.png.txt"}) {
    const std::string path = (dir / name).string();
    EXPECT_THROW(write_image(make_test_image(), path), InputError) << path;
    EXPECT_THROW(check_image_extension(path), InputError) << path;
    EXPECT_FALSE(std::filesystem::exists(path)) << path << " must not be written";
  }
  // Extensions are case-insensitive (Windows users write .PNG).
  EXPECT_NO_THROW(check_image_extension("picture.PNG"));
  EXPECT_NO_THROW(check_image_extension("picture.exr"));
}

TEST(Image, ReadingAMissingFileNamesThePath) {
  const std::string path = (scratch_dir() / "no_such_image.exr").string();
  try {
    read_image(path);
    FAIL() << "read_image(" << path << ") returned instead of throwing InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos)
        << "the message should name the file; got: " << e.what();
  }
}

TEST(CompareImages, IdenticalImagesHaveNoError) {
  const Image image = make_test_image();
  const ImageDifference difference = compare_images(image, image, 1e-6f);
  EXPECT_EQ(difference.max_error, 0.0);
  EXPECT_EQ(difference.mean_error, 0.0);
  EXPECT_EQ(difference.rms_error, 0.0);
  EXPECT_EQ(difference.pixels_over_threshold, 0);
  EXPECT_EQ(difference.fraction_over_threshold, 0.0);
}

TEST(CompareImages, FindsTheOneChangedPixel) {
  // The autograder points students at max_x / max_y: they must be the changed pixel's column
  // and row, not swapped (a non-square image and an off-diagonal pixel tell them apart).
  const Image expected = make_test_image();
  Image actual = expected;
  actual.at(3, 1).y += 0.25f;
  const ImageDifference difference = compare_images(actual, expected, 0.01f);
  EXPECT_EQ(difference.max_x, 3);
  EXPECT_EQ(difference.max_y, 1);
  EXPECT_NEAR(difference.max_error, 0.25, 1e-6);
  EXPECT_EQ(difference.pixels_over_threshold, 1);
  EXPECT_NEAR(difference.fraction_over_threshold, 1.0 / 12.0, 1e-12);
  EXPECT_GT(difference.mean_error, 0.0);
}

TEST(CompareImages, DifferentSizesThrow) {
  EXPECT_THROW(compare_images(Image(4, 3), Image(3, 4), 0.0f), std::invalid_argument);
}

TEST(SideBySideDifference, IsActualExpectedAndHeatMapInARow) {
  const Image expected = make_test_image();
  Image actual = expected;
  actual.at(2, 0) = glm::vec3(1.0f, 0.0f, 1.0f);
  const int w = expected.width(), h = expected.height();
  const Image panel = side_by_side_difference(actual, expected, 0.5f);
  ASSERT_EQ(panel.width(), 3 * w);
  ASSERT_EQ(panel.height(), h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      EXPECT_TRUE(testing::vec3_near(panel.at(x, y), actual.at(x, y), 1e-6f))
          << "left third is `actual`, pixel (" << x << ", " << y << ")";
      EXPECT_TRUE(testing::vec3_near(panel.at(w + x, y), expected.at(x, y), 1e-6f))
          << "middle third is `expected`, pixel (" << x << ", " << y << ")";
    }
  // Heat map: (almost) black where equal, bright where they differ.
  const glm::vec3 equal = panel.at(2 * w + 0, 0), changed = panel.at(2 * w + 2, 0);
  EXPECT_LT(std::max({equal.x, equal.y, equal.z}), 0.01f) << "heat map where equal: " << equal;
  EXPECT_GT(std::max({changed.x, changed.y, changed.z}), 0.5f) << "heat map at the change: " << changed;
}

// The heat map shows the largest of the three channels' differences, whichever channel it is in.
TEST(SideBySideDifference, HeatIsTheLargestChannelsDifference) {
  const Image expected(3, 1, glm::vec3(0.0f));
  Image actual = expected;
  actual.at(0, 0) = glm::vec3(0.25f, 0.0f, 0.0f);
  actual.at(1, 0) = glm::vec3(0.0f, 0.0f, 0.25f);
  actual.at(2, 0) = glm::vec3(0.1f, 0.25f, 0.05f);
  const Image panel = side_by_side_difference(actual, expected, 0.5f);
  const glm::vec3 red = panel.at(6, 0), blue = panel.at(7, 0), green = panel.at(8, 0);
  EXPECT_GT(std::max({red.x, red.y, red.z}), 0.05f) << "a difference of half the full scale is not black: " << red;
  EXPECT_TRUE(testing::vec3_near(red, blue, 1e-5f)) << red << " and " << blue;
  EXPECT_TRUE(testing::vec3_near(red, green, 1e-5f)) << red << " and " << green;
}

}  // namespace
}  // namespace raylab
