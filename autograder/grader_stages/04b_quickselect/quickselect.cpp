// The grader's own select_kth (stages.json "grader_versions"): stage 05's build is graded with
// it, so a mistake in the student's stage 04b costs points there only. The standard library's
// selection, on the caller's order.
#include "raylab/stages/04b_quickselect.h"

#include <algorithm>
#include <stdexcept>

namespace raylab {

void select_kth(std::uint32_t* items, std::size_t count, std::size_t k, const ItemOrder& order) {
  if (k >= count) throw std::invalid_argument("select_kth: k must be less than count");
  std::nth_element(items, items + k, items + count,
                   [&order](std::uint32_t a, std::uint32_t b) { return order.less(order.context, a, b); });
}

}  // namespace raylab
