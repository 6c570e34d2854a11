// Small helpers shared by raylab's framework tests: where the sources are, a scratch folder
// per test, and float comparisons whose failure messages print both values.
#pragma once

#include "raylab/math.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace raylab::testing {

// A file of the source tree (scenes/whitted.json, ...), found wherever the tests run from.
inline std::string source_path(const std::string& relative) {
  return (std::filesystem::path(RAYLAB_SOURCE_DIR) / relative).string();
}

// A fresh, empty folder for the running test's files, named after the test so that tests
// running in parallel (ctest -j) never share one. Left in place afterwards for inspection.
inline std::filesystem::path scratch_dir() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = std::filesystem::path(RAYLAB_TEST_OUTPUT_DIR) /
                              (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void write_text_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << "could not write " << path;
}

// |a - b| <= tolerance per component; on failure both vectors and the tolerance are printed.
inline ::testing::AssertionResult vec3_near(const glm::vec3& actual, const glm::vec3& expected,
                                            float tolerance) {
  const glm::vec3 difference = glm::abs(actual - expected);
  if (difference.x <= tolerance && difference.y <= tolerance && difference.z <= tolerance)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "got " << actual << ", expected " << expected
                                       << " within " << tolerance << " per component (off by "
                                       << difference << ")";
}

}  // namespace raylab::testing
