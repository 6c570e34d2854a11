// The rule a student's tree breaks (raylab/bvh_tools.h: find_bvh_violation) as a catalogue
// message (messages.def: bvh_rule_...), shown in the run's language. Its English is the
// framework's describe(violation), word for word (messages_are_paired checks every rule).
#pragma once

#include "messages.h"

#include "raylab/bvh_tools.h"

#include <cstdint>
#include <optional>
#include <string>

namespace raylab::grading {

Message bvh_violation_message(const BvhViolation& violation);
// The renderer's BrokenBvh (its what() in English, word for word) from its fields.
Message broken_tree_message(const BvhViolation& violation, std::uint64_t boxes, const std::optional<std::string>& mesh);

}  // namespace raylab::grading
