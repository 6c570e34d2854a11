// Grader self-test submission (stage 04b_quickselect): mistake: the pivot is always the first
// item of the range (with a three-way partition, so equal keys are no trouble). Right on every
// input, linear on random keys, but on sorted or reversed keys each partition splits off one
// item: about n^2 / 2 comparisons.
#include "raylab/stages/04b_quickselect.h"

#include <stdexcept>
#include <utility>

namespace raylab {

void select_kth(std::uint32_t* items, std::size_t count, std::size_t k, const ItemOrder& order) {
  if (k >= count) throw std::invalid_argument("select_kth: k >= count");
  std::size_t begin = 0, end = count;
  while (end - begin > 1) {
    const std::uint32_t pivot = items[begin];
    std::size_t less_end = begin, i = begin, greater_begin = end;
    while (i < greater_begin) {
      if (order.less(order.context, items[i], pivot)) std::swap(items[i++], items[less_end++]);
      else if (order.less(order.context, pivot, items[i])) std::swap(items[i], items[--greater_begin]);
      else ++i;
    }
    if (k < less_end) end = less_end;
    else if (k >= greater_begin) begin = greater_begin;
    else return;
  }
}

}  // namespace raylab
