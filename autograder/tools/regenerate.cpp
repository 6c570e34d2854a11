// autograder-regenerate: rebuilds autograder/reference/ from the solutions (instructors only;
// built only when solutions/ exists). Deterministic: the same seed gives the same files, so
// CI can check that what is checked in is what the solutions produce.
//
//   autograder-regenerate [--output DIR] [--seed N] [--check REFERENCE_DIR]
//   autograder-regenerate --compare GENERATED_DIR --check REFERENCE_DIR
//
// For every stage of stages.json, in order: the reference data its <id>_cases.cpp registers
// (autograder/reference/<id>_cases.json), and the picture of its image test (<id>.png).
//
// --check compares what it wrote with REFERENCE_DIR (the checked-in data; a ctest does this)
// and exits 1 naming every file that differs. With --compare it writes nothing and compares
// GENERATED_DIR, an earlier run's --output, instead (a ctest checks that --check catches stale
// data on the folder the test of the checked-in data regenerated). Numbers may differ in their last bits across
// C libraries (with Debian 13's tanf, 15 of stage 01's 200 ray directions move by up to 1.2e-7), so
// JSON numbers are compared to kNumberUlps float ulps (of the number, or of 1 if smaller) and images pixel by pixel with a small
// tolerance; everything else (the set of files, keys, strings, array lengths) exactly.
#include "grading.h"
#include "kit_folders.h"
#include "support.h"

#include "raylab/image.h"
#include "raylab/stage_table.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace {

using namespace raylab;
using namespace raylab::grading;
using nlohmann::json;

void write_json(const std::string& path, const json& value) {
  std::ofstream out(path);
  out << value.dump(1) << "\n";
  if (!out) throw std::runtime_error("cannot write " + path);
  std::cout << "wrote " << path << "\n";
}

// --check: how far regenerated data may be from the checked-in data and still be current.
constexpr double kNumberUlps = 4.0;             // float ulps of max(|a|, |b|, 1)
constexpr float kPixelThreshold = 1.0f / 64.0f; // linear; one 8-bit sRGB step is < 0.01
constexpr double kPixelsAllowedOver = 1e-3;     // fraction of pixels over it

bool numbers_close(double a, double b) {
  if (a == b) return true;
  // At least 1: a component of a unit vector is as exact as the vector, not as its own size
  // (Debian 13's rays differ from Debian 12's by 2.6e-8 in a component of size 0.01).
  const double scale = std::max({std::abs(a), std::abs(b), 1.0});
  return std::abs(a - b) <= kNumberUlps * double(std::numeric_limits<float>::epsilon()) * scale;
}

// The first place where `generated` and `checked_in` differ ("" if they agree), as a JSON
// pointer with both values.
std::string first_difference(const json& generated, const json& checked_in, const std::string& where) {
  if (generated.is_number() && checked_in.is_number()) {
    if (numbers_close(generated.get<double>(), checked_in.get<double>())) return "";
  } else if (generated.type() == checked_in.type() && generated.is_array() &&
             generated.size() == checked_in.size()) {
    for (std::size_t i = 0; i < generated.size(); ++i)
      if (auto d = first_difference(generated[i], checked_in[i], where + "/" + std::to_string(i)); !d.empty()) return d;
    return "";
  } else if (generated.type() == checked_in.type() && generated.is_object() &&
             generated.size() == checked_in.size()) {
    for (const auto& [key, value] : generated.items()) {
      if (!checked_in.contains(key)) return where + "/" + key + ": not in the checked-in file";
      if (auto d = first_difference(value, checked_in[key], where + "/" + key); !d.empty()) return d;
    }
    return "";
  } else if (generated == checked_in) {
    return "";
  }
  std::string a = generated.dump(), b = checked_in.dump();
  if (a.size() > 80) a = a.substr(0, 77) + "...";
  if (b.size() > 80) b = b.substr(0, 77) + "...";
  return (where.empty() ? "/" : where) + ": regenerated " + a + ", checked in " + b;
}

std::set<std::string> files_in(const std::string& folder) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    if (entry.is_regular_file()) names.insert(entry.path().filename().string());
  return names;
}

// Compares every file; prints one line per file that differs and returns how many did.
int check_against(const std::string& generated_dir, const std::string& reference_dir) {
  int stale = 0;
  const std::set<std::string> generated = files_in(generated_dir), checked_in = files_in(reference_dir);
  for (const std::string& name : checked_in)
    if (!generated.count(name)) {
      std::cerr << reference_dir << "/" << name << ": checked in, but no stage generates it\n";
      ++stale;
    }
  for (const std::string& name : generated) {
    const std::string fresh = generated_dir + "/" + name, old = reference_dir + "/" + name;
    std::string problem;
    if (!checked_in.count(name)) {
      problem = "generated, but not checked in";
    } else if (name.size() > 5 && name.substr(name.size() - 5) == ".json") {
      std::ifstream a(fresh), b(old);
      problem = first_difference(json::parse(a), json::parse(b), "");
    } else {
      const Image a = read_image(fresh), b = read_image(old);
      if (a.width() != b.width() || a.height() != b.height()) {
        problem = "the image's size changed";
      } else {
        const ImageDifference d = compare_images(a, b, kPixelThreshold);
        if (d.fraction_over_threshold > kPixelsAllowedOver) {
          std::ostringstream text;
          text << d.pixels_over_threshold << " pixels differ by more than " << kPixelThreshold
               << " (largest " << d.max_error << " at " << d.max_x << ", " << d.max_y << ")";
          problem = text.str();
        }
      }
    }
    if (!problem.empty()) {
      std::cerr << old << ": " << problem << "\n";
      ++stale;
    }
  }
  return stale;
}

constexpr std::uint32_t kReleasedSeed = 2026;  // autograder/reference/, which students have

// Writes every stage's reference data and picture into `output`.
void write_reference_data(const std::string& output, std::uint32_t seed) {
  std::filesystem::create_directories(output);
  for (const StageDescription& stage : stage_table()) {
    const std::string id(stage.id);
    if (const ReferenceData* data = reference_data_of(id)) {
      // The seed as the failures name it ("200 of 200 reference rays differ (seed 2026)"): a
      // course's own seed stays private (tools/gradescope/setup.sh), so its cases say "private".
      const json seed_shown = seed == kReleasedSeed ? json(seed) : json("private");
      json document = {{"stage", id}, {"seed", data->seeded ? seed_shown : json(nullptr)}};
      document.update(data->generate(seed));  // each stage draws from its own stream
      write_json(output + "/" + id + "_cases.json", document);
    }
    if (!stage.image_scene.empty()) {
      const std::string image_path = output + "/" + reference_image_name(id);
      write_image(render_stage_image(id), image_path);
      std::cout << "wrote " << image_path << "\n";
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Regenerate the autograder's reference data from solutions/"};
  std::string output = kit_reference_folder();
  std::uint32_t seed = kReleasedSeed;
  app.add_option("--output", output, "Folder to write into")->capture_default_str();
  app.add_option("--seed", seed, "Seed of the random cases (a course may grade with its own)")->capture_default_str();
  std::string check;
  app.add_option("--check", check, "Compare what was written with this folder (the checked-in data); exit 1 if it is out of date");
  std::string compare;
  app.add_option("--compare", compare, "Write nothing: compare this folder, an earlier run's --output, with --check's")
      ->needs(app.get_option("--check"))
      ->excludes(app.get_option("--output"))
      ->excludes(app.get_option("--seed"));
  CLI11_PARSE(app, argc, argv);
  if (!compare.empty()) output = compare;
  try {
    if (compare.empty()) write_reference_data(output, seed);
    if (!check.empty()) {
      if (const int stale = check_against(output, check); stale > 0) {
        std::cerr << "autograder-regenerate: " << check << " is out of date (" << stale
                  << " files): run `cmake --build build --target regenerate` and commit the result "
                     "(docs/instructors.md)\n";
        return 1;
      }
      std::cout << check << " is current\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "autograder-regenerate: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
