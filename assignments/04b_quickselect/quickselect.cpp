// Stage 04b_quickselect: the kth smallest of n items.            Handout: docs/04b_quickselect.md
//
// Stage 05's BVH build splits each node at the median of its primitives' centroids. Sorting
// them would cost O(n log n) comparisons per node; selecting the median costs O(n). This stage
// is that selection, and stage 05's build calls it.
//
// WHAT YOU RECEIVE
//   items     an array of count numbers, the caller's items (stage 05: primitive indices)
//   count     how many (0 is allowed when k is not needed: then throw, as k >= count)
//   k         the position wanted, 0 <= k < count
//   order     how two items compare: order.less(order.context, a, b) is true when item a comes
//             before item b. You never see the keys behind the items, only this comparison.
//             Items may be equal: neither less(a, b) nor less(b, a).
//
// WHAT YOU LEAVE
//   The same items, each as often as before, rearranged in place so that
//     - items[k] is the item a sort by `order` would put at position k,
//     - no item before position k comes after items[k],
//     - no item after position k comes before items[k]
//   (what std::nth_element leaves). Throw std::invalid_argument if k >= count.
//
// HOW FAST
//   Expected O(count) comparisons on every input, sorted, reversed and all-equal ones included:
//   pick the pivot at random, partition, and go on in the ONE part that holds position k (a loop
//   is enough, no recursion). The autograder counts every call of order.less.
//
// READ docs/04b_quickselect.md: section 2 (partition), section 3 (quickselect), section 4 (why
//   the expected cost is linear), section 7 (common mistakes, which the autograder's hints name).
//
// HOW TO CHECK
//   build/bin/autograder --stage 04b_quickselect
#include "raylab/error.h"
#include "raylab/stages/04b_quickselect.h"

#include <stdexcept>

namespace raylab {

void select_kth(std::uint32_t* items, std::size_t count, std::size_t k, const ItemOrder& order) {
  (void)items;
  (void)count;
  (void)k;
  (void)order;
  // Delete the line below when you write the function.
  throw NotImplemented("select_kth");
}

}  // namespace raylab
