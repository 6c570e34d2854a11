// Grader self-test submission (stage 04b_quickselect): mistake: it finds the item of position k
// by counting, for each item, how many come before it, and swaps that one to position k; the
// others stay where they were, so the items before k need not come first. (Quadratic too, but
// the sides are the mistake the correctness tests name first.)
#include "raylab/stages/04b_quickselect.h"

#include <stdexcept>
#include <utility>

namespace raylab {

void select_kth(std::uint32_t* items, std::size_t count, std::size_t k, const ItemOrder& order) {
  if (k >= count) throw std::invalid_argument("select_kth: k >= count");
  for (std::size_t i = 0; i < count; ++i) {
    std::size_t before = 0, equal = 0;
    for (std::size_t j = 0; j < count; ++j) {
      if (order.less(order.context, items[j], items[i])) ++before;
      else if (!order.less(order.context, items[i], items[j])) ++equal;
    }
    if (before <= k && k < before + equal) {
      std::swap(items[i], items[k]);
      return;
    }
  }
}

}  // namespace raylab
