#include "raylab/stage_table.h"

namespace raylab {

std::string StageDescription::handout_reference() const {
  std::string text(handout);
  if (!handout_section.empty()) text += ", section " + std::string(handout_section);
  return text;
}

std::string StageDescription::display_title() const {
  return (bonus ? "bonus: " : "") + std::string(title);
}

const StageDescription* find_stage_description(std::string_view name) {
  // "05b" and "5b" both name 05b_bvh_sah: compare the short ids without leading zeros.
  const auto without_leading_zeros = [](std::string_view text) {
    while (text.size() > 1 && text.front() == '0') text.remove_prefix(1);
    return text;
  };
  for (const StageDescription& stage : stage_table())
    if (name == stage.id || name == stage.short_id() ||
        (!name.empty() && without_leading_zeros(name) == without_leading_zeros(stage.short_id())))
      return &stage;
  return nullptr;
}

const StageDescription* stage_of_function(std::string_view function) {
  for (const StageDescription& stage : stage_table())
    for (std::string_view name : stage.functions)
      if (name == function) return &stage;
  return nullptr;
}

std::string stage_ids_text() {
  std::string text;
  for (const StageDescription& stage : stage_table()) {
    if (!text.empty()) text += ", ";
    text += stage.id;
  }
  return text;
}

}  // namespace raylab
