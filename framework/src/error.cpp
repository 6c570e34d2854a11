#include "raylab/error.h"

#include "raylab/stage_table.h"

namespace raylab {
namespace {

const StageDescription* owning_stage(const std::string& function) {
  const StageDescription* stage = stage_of_function(function);
  // A stub throws only for functions the table lists; a name it does not list is a bug here.
  if (!stage) throw std::logic_error(function + " throws NotImplemented but stages.json lists no such function");
  return stage;
}

std::string files_text(const StageDescription& stage) {
  std::string text;
  for (std::string_view file : stage.files) text += (text.empty() ? "assignments/" : " or assignments/") + std::string(file);
  return text;
}

}  // namespace

NotImplemented::NotImplemented(const std::string& function)
    : NotImplemented(function, *owning_stage(function)) {}

NotImplemented::NotImplemented(const std::string& function, const StageDescription& stage)
    : std::logic_error("stage " + std::string(stage.id) + " is not implemented yet: write " + function + " in " +
                       files_text(stage) + " (handout: " + stage.handout_reference() + ")"),
      stage_id_(stage.id),
      function_(function) {}

}  // namespace raylab
