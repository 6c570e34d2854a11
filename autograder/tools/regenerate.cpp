// autograder-regenerate: rebuilds autograder/reference/ from the solutions (instructors only;
// built only when solutions/ exists). Deterministic: the same seed gives the same files, so
// CI can check that what is checked in is what the solutions produce.
//
//   autograder-regenerate [--output DIR] [--seed N]
//
// For every stage of stages.json, in order: the reference data its <id>_cases.cpp registers
// (autograder/reference/<id>_cases.json), and the picture of its image test (<id>.png).
#include "grading.h"
#include "support.h"

#include "raylab/image.h"
#include "raylab/stage_table.h"

#include <CLI/CLI.hpp>

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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Regenerate the autograder's reference data from solutions/"};
  std::string output = RAYLAB_REFERENCE_DIR;
  std::uint32_t seed = 2026;
  app.add_option("--output", output, "Folder to write into")->capture_default_str();
  app.add_option("--seed", seed, "Seed of the random cases (a course may grade with its own)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    std::filesystem::create_directories(output);
    for (const StageDescription& stage : stage_table()) {
      const std::string id(stage.id);
      if (const ReferenceData* data = reference_data_of(id)) {
        json document = {{"stage", id}, {"seed", data->seeded ? json(seed) : json(nullptr)}};
        document.update(data->generate(seed));  // each stage draws from its own stream
        write_json(output + "/" + id + "_cases.json", document);
      }
      if (!stage.image_scene.empty()) {
        const std::string image_path = output + "/" + reference_image_name(id);
        write_image(render_stage_image(id), image_path);
        std::cout << "wrote " << image_path << "\n";
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "autograder-regenerate: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
