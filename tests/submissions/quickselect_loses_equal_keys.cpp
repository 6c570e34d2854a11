// Grader self-test submission (stage 04b_quickselect): mistake: the partition gathers the items
// before the pivot and those after it, and writes the pivot back once in the middle: every other
// item equal to the pivot is lost (its place gets a copy of the pivot). Right on distinct keys.
#include "raylab/stages/04b_quickselect.h"

#include <random>
#include <stdexcept>
#include <vector>

namespace raylab {

void select_kth(std::uint32_t* items, std::size_t count, std::size_t k, const ItemOrder& order) {
  if (k >= count) throw std::invalid_argument("select_kth: k >= count");
  std::mt19937 random(7);
  std::size_t begin = 0, end = count;
  while (end - begin > 1) {
    const std::uint32_t pivot = items[begin + random() % (end - begin)];
    std::vector<std::uint32_t> before, after;
    for (std::size_t i = begin; i < end; ++i) {
      if (order.less(order.context, items[i], pivot)) before.push_back(items[i]);
      else if (order.less(order.context, pivot, items[i])) after.push_back(items[i]);
    }
    std::size_t at = begin;
    for (std::uint32_t item : before) items[at++] = item;
    const std::size_t equal_begin = at;
    while (at < end - after.size()) items[at++] = pivot;  // the pivot copied over its equals
    const std::size_t equal_end = at;
    for (std::uint32_t item : after) items[at++] = item;
    if (k < equal_begin) end = equal_begin;
    else if (k >= equal_end) begin = equal_end;
    else return;
  }
}

}  // namespace raylab
