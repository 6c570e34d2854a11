// Grader self-test submission (stage 04b_quickselect): mistake: a random pivot, but Lomuto's
// partition sends every item equal to the pivot to the same side, so on all-equal keys each pass
// splits off one item: about n^2 / 2 comparisons there, linear on distinct keys.
#include "raylab/stages/04b_quickselect.h"

#include <random>
#include <stdexcept>
#include <utility>

namespace raylab {

void select_kth(std::uint32_t* items, std::size_t count, std::size_t k, const ItemOrder& order) {
  if (k >= count) throw std::invalid_argument("select_kth: k >= count");
  std::mt19937 random(2024);
  std::size_t begin = 0, end = count;
  while (end - begin > 1) {
    std::swap(items[end - 1], items[begin + random() % (end - begin)]);
    const std::uint32_t pivot = items[end - 1];
    std::size_t store = begin;
    for (std::size_t i = begin; i + 1 < end; ++i)
      if (order.less(order.context, items[i], pivot)) std::swap(items[i], items[store++]);
    std::swap(items[store], items[end - 1]);
    if (k == store) return;
    if (k < store) end = store;
    else begin = store + 1;
  }
}

}  // namespace raylab
