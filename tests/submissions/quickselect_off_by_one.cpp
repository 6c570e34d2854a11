// Grader self-test submission (stage 04b_quickselect): mistake: it selects position k - 1 (for
// k > 0), as if k counted from 1. A correct three-way quickselect otherwise.
#include "raylab/stages/04b_quickselect.h"

#include <random>
#include <stdexcept>
#include <utility>

namespace raylab {

void select_kth(std::uint32_t* items, std::size_t count, std::size_t k, const ItemOrder& order) {
  if (k >= count) throw std::invalid_argument("select_kth: k >= count");
  if (k > 0) --k;  // "the kth smallest" read as counting from 1
  std::mt19937 random(99);
  std::size_t begin = 0, end = count;
  while (end - begin > 1) {
    const std::uint32_t pivot = items[begin + random() % (end - begin)];
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
