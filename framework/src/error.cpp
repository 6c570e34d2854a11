#include "raylab/error.h"

namespace raylab {

NotImplemented::NotImplemented(std::string stage_id, std::string function, std::string file)
    : std::logic_error("stage " + stage_id + " is not implemented yet: write " + function +
                       " in " + file),
      stage_id_(std::move(stage_id)),
      function_(std::move(function)) {}

}  // namespace raylab
