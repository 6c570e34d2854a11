// The rule a student's tree breaks (raylab/bvh_tools.h: find_bvh_violation) as a catalogue
// message (messages.def: bvh_rule_...), shown in the run's language. Its English is the
// framework's describe(violation), word for word (messages_are_paired checks every rule).
#pragma once

#include "messages.h"

#include "raylab/bvh_tools.h"

namespace raylab::grading {

Message bvh_violation_message(const BvhViolation& violation);

}  // namespace raylab::grading
