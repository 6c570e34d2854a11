// Grader self-test submission (stage 04b_quickselect): mistake: it compares positions instead of
// the items stored there (order.less(context, i, j) with i and j indices into the array), as if
// the items were 0 .. count - 1.
#include "raylab/stages/04b_quickselect.h"

#include <stdexcept>
#include <utility>

namespace raylab {

void select_kth(std::uint32_t* items, std::size_t count, std::size_t k, const ItemOrder& order) {
  if (k >= count) throw std::invalid_argument("select_kth: k >= count");
  for (std::size_t i = 0; i <= k; ++i)  // a selection sort of the first k + 1 positions
    for (std::size_t j = i + 1; j < count; ++j)
      if (order.less(order.context, static_cast<std::uint32_t>(j), static_cast<std::uint32_t>(i)))
        std::swap(items[i], items[j]);
}

}  // namespace raylab
