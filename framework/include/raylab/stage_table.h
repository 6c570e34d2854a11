// The stages of raylab as stages.json lists them (the one list: docs/instructors.md). CMake
// reads stages.json when it configures the build and writes the table below from it
// (cmake/RaylabStages.cmake), so this is always the same list the build compiled.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace raylab {

struct StageDescription {
  std::string_view id;                       // "05b_bvh_sah": the stage's name everywhere
  std::string_view title;                    // "binned SAH build"
  std::string_view title_zh;                 // "分桶 SAH 构建": the title in Simplified Chinese
                                             // (empty while a new row is not translated yet)
  std::vector<std::string_view> files;       // the files to write, under assignments/
  std::vector<std::string_view> functions;   // the functions to write in them
  std::string_view handout;                  // "docs/05_bvh.md"
  std::string_view handout_section;          // "5", or empty: the whole handout
  std::string_view image_scene;              // the scene of its image test, or empty: none
  std::string_view image_shows;              // what that picture shows: "ray_directions",
                                             // "spheres" or "everything"
  std::string_view server_suffix;            // "-with-grader-07-08": its stage server links the
                                             // grader's own stages 07 and 08 ("grader_versions"),
                                             // or empty: the one that links every stage's code
  int points = 0;                            // what its tests add up to
  bool bonus = false;

  // "05b": the id up to its first '_', which --stage also accepts (and "5b").
  std::string_view short_id() const { return id.substr(0, id.find('_')); }
  // "docs/05_bvh.md, section 5"
  std::string handout_reference() const;
  // "bonus: binned SAH build"
  std::string display_title() const;
};

// Every stage, in teaching order.
const std::vector<StageDescription>& stage_table();

// The stage named `name`: its id ("05b_bvh_sah"), its short id ("05b"), or the short id
// without leading zeros ("5b"); nullptr when there is none.
const StageDescription* find_stage_description(std::string_view name);

// The stage whose functions include `function`, or nullptr.
const StageDescription* stage_of_function(std::string_view function);

// "01_camera_rays, 02_sphere, ..., 06_robustness": for messages that list the valid names.
std::string stage_ids_text();

}  // namespace raylab
