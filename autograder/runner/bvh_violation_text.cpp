#include "bvh_violation_text.h"

#include <sstream>
#include <string>

namespace raylab::grading {
namespace {

std::string box_words(const Bounds3& box) {  // as the framework writes a box ("[empty]" is the framework's word)
  std::ostringstream out;
  out << box;
  return out.str();
}

MessageArg box_arg(std::string name, const Bounds3& box) {
  if (box.is_empty()) return MessageArg(std::move(name), Message(MessageId::value_box_empty));
  return MessageArg(std::move(name), box_words(box));
}

}  // namespace

Message bvh_violation_message(const BvhViolation& v) {
  using Rule = BvhViolation::Rule;
  const MessageArg index("index", std::to_string(v.index)), value("value", std::to_string(v.value)),
      count("count", std::to_string(v.count)), limit("limit", std::to_string(v.limit));
  switch (v.rule) {
    case Rule::OrderSize: return {MessageId::bvh_rule_order_size, {count, limit}};
    case Rule::OrderOutOfRange:
      return {MessageId::bvh_rule_order_out_of_range, {index, value, {"last", std::to_string(v.limit - 1)}}};
    case Rule::OrderTwice: return {MessageId::bvh_rule_order_twice, {index, value, {"last", std::to_string(v.limit - 1)}}};
    case Rule::NodesWithoutPrimitives: return MessageId::bvh_rule_nodes_without_primitives;
    case Rule::NoNodes: return {MessageId::bvh_rule_no_nodes, {limit}};
    case Rule::TooDeep: return {MessageId::bvh_rule_too_deep, {index, value, limit}};
    case Rule::LeafTooBig: return {MessageId::bvh_rule_leaf_too_big, {index, count, limit}};
    case Rule::LeafPastEnd:
      return {MessageId::bvh_rule_leaf_past_end, {index, value, {"last", std::to_string(v.value + v.count - 1)}, limit}};
    case Rule::PrimitiveInTwoLeaves: return {MessageId::bvh_rule_primitive_in_two_leaves, {value}};
    case Rule::LeafBoxTooSmall:
      return {MessageId::bvh_rule_leaf_box_too_small, {index, value, box_arg("box", v.box), box_arg("other_box", v.other_box)}};
    case Rule::BadSplitAxis: return {MessageId::bvh_rule_bad_split_axis, {index, value}};
    case Rule::ChildBoxTooSmall:
      return {MessageId::bvh_rule_child_box_too_small,
              {index, value, box_arg("box", v.box), box_arg("other_box", v.other_box)}};
    case Rule::ReachedTwice: return {MessageId::bvh_rule_reached_twice, {index}};
    case Rule::BadChildren:
      return {MessageId::bvh_rule_bad_children,
              {index, value, {"second", std::to_string(v.value + 1)}, limit,
               {"note", v.value == 0 ? std::vector<Message>{MessageId::bvh_rule_bad_children_push_back}
                                     : std::vector<Message>{}}}};
    case Rule::Unreached: return {MessageId::bvh_rule_unreached, {index}};
    case Rule::PrimitiveInNoLeaf: return {MessageId::bvh_rule_primitive_in_no_leaf, {value}};
  }
  return MessageId::bvh_rule_nodes_without_primitives;  // not reached: every rule is above
}

Message broken_tree_message(const BvhViolation& violation, std::uint64_t boxes, const std::optional<std::string>& mesh) {
  const MessageArg mesh_arg = mesh ? MessageArg("mesh", *mesh) : MessageArg("mesh", Message(MessageId::stage_broken_tree_objects));
  return {MessageId::stage_broken_tree,
          {{"boxes", std::to_string(boxes)}, mesh_arg, {"violation", bvh_violation_message(violation)}}};
}

}  // namespace raylab::grading
