// Reference solution, stage 04b_quickselect. The contract is in
// assignments/04b_quickselect/quickselect.cpp and docs/04b_quickselect.md.
//
// Quickselect with a three-way partition (Dijkstra's): a pivot drawn at random from the range,
// the range split into the items before it, equal to it and after it, and the search goes on in
// the one part that holds position k. Equal items end in the middle part, so all-equal input
// takes one pass. The generator's seed is fixed: the same input gives the same result.
#include "raylab/stages/04b_quickselect.h"

#include <stdexcept>
#include <utility>

namespace raylab {

void select_kth(std::uint32_t* items, std::size_t count, std::size_t k, const ItemOrder& order) {
  if (k >= count) throw std::invalid_argument("select_kth: k must be less than count");
  std::uint64_t state = 0x9E3779B97F4A7C15ull;  // splitmix64
  auto random_below = [&state](std::size_t n) {
    state += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = state;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return static_cast<std::size_t>((z ^ (z >> 31)) % n);
  };
  std::size_t begin = 0, end = count;  // position k lies in [begin, end)
  while (end - begin > 1) {
    const std::uint32_t pivot = items[begin + random_below(end - begin)];
    // [begin, less_end): before the pivot; [less_end, i): equal; [greater_begin, end): after.
    std::size_t less_end = begin, i = begin, greater_begin = end;
    while (i < greater_begin) {
      if (order.less(order.context, items[i], pivot)) {
        std::swap(items[i++], items[less_end++]);
      } else if (order.less(order.context, pivot, items[i])) {
        std::swap(items[i], items[--greater_begin]);
      } else {
        ++i;
      }
    }
    if (k < less_end) end = less_end;
    else if (k >= greater_begin) begin = greater_begin;
    else return;  // k is among the items equal to the pivot
  }
}

}  // namespace raylab
