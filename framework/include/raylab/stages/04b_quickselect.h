// Stage 04b_quickselect: the kth smallest of n items, in expected linear time.
// Write it in assignments/04b_quickselect/quickselect.cpp; handout: docs/04b_quickselect.md.
#pragma once

#include <cstddef>
#include <cstdint>

namespace raylab {

// How two items compare: order.less(order.context, a, b) is true when item a comes before item
// b. Items are the caller's numbers (stage 05's build passes primitive indices and compares
// their centroids); you never see the keys behind them, only this comparison. Some items may be
// equal (neither comes before the other). A plain function pointer and the caller's context, for
// the reason stage 05's PrimitiveIntersector gives.
struct ItemOrder {
  using LessFunction = bool (*)(const void* context, std::uint32_t a, std::uint32_t b);
  LessFunction less = nullptr;
  const void* context = nullptr;
};

// Rearranges items[0 .. count - 1] in place so that items[k] is the item a sort by `order` would
// put at position k, no item before position k comes after it, and no item after position k
// comes before it (what std::nth_element does). The array holds the same items afterwards, each
// as often as before. Expected O(count) comparisons on every input, sorted, reversed or all
// equal ones included. Throws std::invalid_argument if k >= count.
void select_kth(std::uint32_t* items, std::size_t count, std::size_t k, const ItemOrder& order);

}  // namespace raylab
