// Reference solution, stage 05_bvh (and the bonus 5b, binned SAH). The contract is in
// assignments/05_bvh/bvh.cpp and docs/05_bvh.md.
//
// Beyond the contract, for speed (docs/performance.md, "BVH build" and "BVH traversal"): the
// builders move copies of the primitives' boxes in the order being built (contiguous reads
// instead of an index lookup per primitive), the SAH bins all three axes in one pass and gets
// the children's bounds from its partition pass, grows boxes with SSE, prices the three axes'
// splits at once (one per SSE lane) or, in nodes of few primitives, only the splits after used
// bins, trees of 64k primitives and more build their top subtrees on several threads (all of it
// the same tree bit for bit), and the traversal inlines the reference's own box test
// (solutions/04_box/box_slabs.h) and tests both children at their parent; and for the
// reference's own tree over a scene's triangles, reference::intersect_bvh_inlined tests them
// with the reference's own stage-03 test inlined (solutions/03_triangle/moller_trumbore.h).
#include "raylab/stages/04_box.h"
#include "raylab/stages/05_bvh.h"

#include "../04_box/box_slabs.h"
#include "leaf_test.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <future>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>

namespace raylab {
namespace {

// Below this depth the SAH builder switches to median splits, which halve the count at every
// level: then no tree is deeper than 30 + log2(primitive count) < kBvhMaxDepth.
constexpr int kSahMaxDepth = 30;
constexpr int kSahBinCount = 16;
// Nodes of fewer primitives price only the splits after their used bins (sweep_used_bins).
constexpr std::uint32_t kSahDenseSweepMinimum = 32;
// Nodes with at least this many primitives build their two subtrees on two threads, down to
// the depth where there are about twice as many subtrees as cores. Smaller trees (every
// scene of the course, the autograder's meshes) never start a thread.
constexpr std::uint32_t kParallelBuildMinimum = 65536;

using NodeArray = decltype(Bvh::nodes);

void check_max_leaf_size(int max_leaf_size, const char* function) {
  if (max_leaf_size < 1 || max_leaf_size > kBvhMaxLeafSize)
    throw std::invalid_argument(std::string(function) + ": max_leaf_size must be in 1.." +
                                std::to_string(kBvhMaxLeafSize) + ", got " +
                                std::to_string(max_leaf_size));
}

// One primitive as the builders move it: its box, its centroid and the caller's index.
struct Item {
  Bounds3 box;
  glm::vec3 centroid;
  std::uint32_t primitive;
};
static_assert(offsetof(Item, box) == 0 && offsetof(Item, centroid) == 24 && sizeof(Item) == 40,
              "GrowingBox reads 16 bytes from box.min, box.max and centroid");

// A box grown by items' boxes or centroids, as Bounds3::extend does (glm::min(x, y) is
// y < x ? y : x, which is _mm_min_ps(y, x); glm::max likewise): the same bits, but with SSE,
// min and max of three coordinates in one instruction each. Each 16-byte load reads a fourth
// float past the three (box.min: max.x; box.max: centroid.x; centroid: primitive), whose lane
// is never used. The builders' hottest loops (binning and partitioning) grow boxes.
#if RAYLAB_REFERENCE_LEAF_SSE
class GrowingBox {
 public:
  void extend_box(const Item& item) { extend(&item.box.min.x, &item.box.max.x); }
  void extend_centroid(const Item& item) { extend(&item.centroid.x, &item.centroid.x); }
  void extend(const GrowingBox& other) {
    low_ = _mm_min_ps(other.low_, low_);
    high_ = _mm_max_ps(other.high_, high_);
  }
  __m128 low() const { return low_; }
  __m128 high() const { return high_; }
  Bounds3 bounds() const {
    alignas(16) float low[4], high[4];
    _mm_store_ps(low, low_);
    _mm_store_ps(high, high_);
    return {{low[0], low[1], low[2]}, {high[0], high[1], high[2]}};
  }

 private:
  void extend(const float* low, const float* high) {
    low_ = _mm_min_ps(_mm_loadu_ps(low), low_);
    high_ = _mm_max_ps(_mm_loadu_ps(high), high_);
  }
  __m128 low_ = _mm_set1_ps(kInfinity), high_ = _mm_set1_ps(-kInfinity);
};
#else
class GrowingBox {
 public:
  void extend_box(const Item& item) { box_.extend(item.box); }
  void extend_centroid(const Item& item) { box_.extend(item.centroid); }
  void extend(const GrowingBox& other) { box_.extend(other.box_); }
  Bounds3 bounds() const { return box_; }

 private:
  Bounds3 box_;
};
#endif

// What both builders share: the items in the order being built and the node array. Nodes are
// referred to by index: push_back may move them.
class Builder {
 public:
  Builder(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size)
      : max_leaf_size_(static_cast<std::uint32_t>(max_leaf_size)) {
    items_.reserve(primitive_bounds.size());
    for (std::size_t i = 0; i < primitive_bounds.size(); ++i)
      items_.push_back({primitive_bounds[i], primitive_bounds[i].centroid(), static_cast<std::uint32_t>(i)});
    // A binary tree with N leaves has 2N - 1 nodes: one allocation.
    if (!items_.empty()) bvh_.nodes.reserve(2 * items_.size() - 1);
  }

  Bvh build(bool use_sah) {
    if (items_.empty()) return std::move(bvh_);
    bvh_.nodes.emplace_back();
    const auto count = static_cast<std::uint32_t>(items_.size());
    int parallel_depth = 0;  // 2^parallel_depth >= 2 x cores
    for (unsigned tasks = 1; tasks < 2 * std::max(1u, std::thread::hardware_concurrency()); tasks *= 2)
      ++parallel_depth;
    parallel_depth_ = parallel_depth;
    build_node(bvh_.nodes, 0, 0, count, 0, use_sah, bounds_of(0, count));
    bvh_.primitive_order.resize(items_.size());
    for (std::size_t i = 0; i < items_.size(); ++i) bvh_.primitive_order[i] = items_[i].primitive;
    return std::move(bvh_);
  }

 private:
  // The box of a range of items, and the box of their centroids.
  struct RangeBounds {
    Bounds3 boxes, centroids;
  };

  // RangeBounds as it grows (GrowingBox).
  struct GrowingRange {
    GrowingBox boxes, centroids;
    void extend(const Item& item) {
      boxes.extend_box(item);
      centroids.extend_centroid(item);
    }
    RangeBounds bounds() const { return {boxes.bounds(), centroids.bounds()}; }
  };

  RangeBounds bounds_of(std::uint32_t begin, std::uint32_t end) const {
    GrowingRange bounds;
    for (std::uint32_t i = begin; i < end; ++i) bounds.extend(items_[i]);
    return bounds.bounds();
  }

  // Builds the node nodes[node_index] for items [begin, end), whose bounds the caller computed,
  // appending its descendants to `nodes`.
  void build_node(NodeArray& nodes, std::uint32_t node_index, std::uint32_t begin, std::uint32_t end,
                  int depth, bool use_sah, const RangeBounds& bounds) {
    Item* items = items_.data();
    const Bounds3& node_bounds = bounds.boxes;
    const Bounds3& centroid_bounds = bounds.centroids;
    nodes[node_index].bounds = node_bounds;
    const std::uint32_t count = end - begin;

    int axis = node_bounds.longest_axis();
    std::uint32_t middle = begin + count / 2;
    bool make_leaf = count <= max_leaf_size_;
    bool median_split = true;
    RangeBounds left, right;  // the children's, when the SAH partition computed them
    if (use_sah && count > 1 && depth < kSahMaxDepth) {
      const SahSplit split = find_sah_split(begin, end, node_bounds, centroid_bounds);
      if (split.found) {
        const float leaf_cost = static_cast<float>(count);
        make_leaf = count <= max_leaf_size_ && split.cost >= leaf_cost;
        if (!make_leaf) {
          const std::uint32_t bin_middle = partition_by_bin(begin, end, split, centroid_bounds, left, right);
          if (bin_middle > begin && bin_middle < end) {  // always, as both sides had primitives
            axis = split.axis;
            middle = bin_middle;
            median_split = false;
          }
        }
      } else {
        axis = centroid_bounds.longest_axis();  // all centroids equal: a median split by count
      }
    }
    if (make_leaf) {
      BvhNode& leaf = nodes[node_index];
      leaf.first_index = begin;
      leaf.primitive_count = static_cast<std::uint16_t>(count);
      return;
    }
    if (median_split) {
      // The median split (and the SAH's fallback): the median centroid along `axis` in place,
      // smaller ones before it. Ties broken by index so every standard library agrees.
      std::nth_element(items + begin, items + middle, items + end, [axis](const Item& a, const Item& b) {
        const float ca = a.centroid[axis], cb = b.centroid[axis];
        return ca < cb || (ca == cb && a.primitive < b.primitive);
      });
      left = bounds_of(begin, middle);
      right = bounds_of(middle, end);
    }

    const auto first_child = static_cast<std::uint32_t>(nodes.size());
    nodes.emplace_back();
    nodes.emplace_back();
    BvhNode& inner = nodes[node_index];  // after the push_backs: still valid (reserved)
    inner.first_index = first_child;
    inner.primitive_count = 0;
    inner.split_axis = static_cast<std::uint8_t>(axis);
    if (count >= kParallelBuildMinimum && depth < parallel_depth_ &&
        build_children_in_parallel(nodes, first_child, begin, middle, end, depth, use_sah, left, right))
      return;
    build_node(nodes, first_child, begin, middle, depth + 1, use_sah, left);
    build_node(nodes, first_child + 1, middle, end, depth + 1, use_sah, right);
  }

  // The two subtrees on two threads (the items' ranges are disjoint), each into its own node
  // array whose element 0 is the subtree's root, then appended: left's descendants, then
  // right's, exactly where the one-thread build puts them, so the tree is the same bit for bit.
  // False if no thread could be started (then the caller builds them itself).
  bool build_children_in_parallel(NodeArray& nodes, std::uint32_t first_child, std::uint32_t begin,
                                  std::uint32_t middle, std::uint32_t end, int depth, bool use_sah,
                                  const RangeBounds& left, const RangeBounds& right) {
    NodeArray left_nodes(1), right_nodes(1);
    left_nodes.reserve(2 * (middle - begin) - 1);
    right_nodes.reserve(2 * (end - middle) - 1);
    std::future<void> left_done;
    try {
      left_done = std::async(std::launch::async, [&] {
        build_node(left_nodes, 0, begin, middle, depth + 1, use_sah, left);
      });
    } catch (const std::system_error&) {
      return false;  // e.g. a process limit on threads
    }
    build_node(right_nodes, 0, middle, end, depth + 1, use_sah, right);
    left_done.get();
    append_subtree(nodes, first_child, left_nodes);
    append_subtree(nodes, first_child + 1, right_nodes);
    return true;
  }

  // Puts subtree[0] at nodes[at] and appends the rest, moving inner nodes' child indices.
  static void append_subtree(NodeArray& nodes, std::uint32_t at, const NodeArray& subtree) {
    const auto offset = static_cast<std::uint32_t>(nodes.size() - 1);  // subtree[i] -> nodes[offset + i]
    auto moved = [offset](BvhNode node) {
      if (!node.is_leaf()) node.first_index += offset;
      return node;
    };
    nodes[at] = moved(subtree[0]);
    for (std::size_t i = 1; i < subtree.size(); ++i) nodes.push_back(moved(subtree[i]));
  }

  struct SahSplit {
    bool found = false;
    int axis = 0;
    int last_left_bin = 0;  // bins 0..last_left_bin go left
    float cost = 0.0f;
  };

  static int bin_of(float centroid, float axis_min, float bins_per_unit) {
    const int bin = static_cast<int>((centroid - axis_min) * bins_per_unit);
    return std::min(std::max(bin, 0), kSahBinCount - 1);
  }

  using BinBoxes = std::array<std::array<GrowingBox, kSahBinCount>, 3>;
  using BinCounts = std::array<std::array<std::uint32_t, kSahBinCount>, 3>;

  // The same search as sweep_bins and the loop after it, over the bins that hold primitives
  // only: for a node of few primitives most bins are empty. The split after an empty bin
  // divides the primitives as the split after the last bin before it that holds some, at the
  // same price, and comes later, so it is never the first cheapest: only the splits after used
  // bins are priced, from the same counts and the same boxes, grown in the same order (an empty
  // bin, +infinity to -infinity, changes no box it is added to, even one holding a NaN).
  static SahSplit sweep_used_bins(const BinBoxes& bins, const BinCounts& bin_count,
                                  const std::array<bool, 3>& splittable, float node_area) {
    SahSplit best;
    for (int axis = 0; axis < 3; ++axis) {
      if (!splittable[axis]) continue;
      int used[kSahBinCount], used_count = 0;
      for (int bin = 0; bin < kSahBinCount; ++bin)
        if (bin_count[axis][bin] > 0) used[used_count++] = bin;
      float right_area[kSahBinCount];
      std::uint32_t right_count[kSahBinCount];
      GrowingBox right_box;
      std::uint32_t right_total = 0;
      for (int i = used_count - 1; i > 0; --i) {
        right_box.extend(bins[axis][used[i]]);
        right_total += bin_count[axis][used[i]];
        right_area[i] = right_box.bounds().surface_area();
        right_count[i] = right_total;
      }
      GrowingBox left_box;
      std::uint32_t left_total = 0;
      for (int i = 0; i + 1 < used_count; ++i) {
        left_box.extend(bins[axis][used[i]]);
        left_total += bin_count[axis][used[i]];
        const float cost = 1.0f + (left_box.bounds().surface_area() * static_cast<float>(left_total) +
                                   right_area[i + 1] * static_cast<float>(right_count[i + 1])) /
                                      node_area;
        if (!best.found || cost < best.cost) best = {true, axis, used[i], cost};
      }
    }
    return best;
  }

  // cost[bin][axis]: the SAH price of splitting after `bin` along `axis` (traversal cost 1,
  // primitive cost 1): 1 + (area left x count left + area right x count right) / node area.
  // Step 2 sweeps from the right for the area and count of everything right of each plane;
  // step 3 from the left, pricing each plane. `cost` must be 16-byte aligned (alignas(16)).
  static void sweep_bins(const BinBoxes& bins, const BinCounts& bin_count, float node_area,
                         float cost[kSahBinCount][4]) {
    alignas(16) float count_left[kSahBinCount][4] = {}, count_right[kSahBinCount][4] = {};
    for (int axis = 0; axis < 3; ++axis) {
      std::uint32_t left = 0, right = 0;
      for (int bin = 0; bin < kSahBinCount - 1; ++bin) {
        left += bin_count[axis][bin];
        count_left[bin][axis] = static_cast<float>(left);
      }
      for (int bin = kSahBinCount - 1; bin > 0; --bin) {
        right += bin_count[axis][bin];
        count_right[bin][axis] = static_cast<float>(right);
      }
    }
#if RAYLAB_REFERENCE_LEAF_SSE
    // The three axes at once, one per lane, each lane doing the scalar sweep's operations
    // (Bounds3::extend and surface_area) in the same order: the same bits.
    __m128 low[3][kSahBinCount], high[3][kSahBinCount];  // [coordinate][bin], a lane per axis
    for (int bin = 0; bin < kSahBinCount; ++bin) {
      __m128 x = bins[0][bin].low(), y = bins[1][bin].low(), z = bins[2][bin].low(), w = _mm_setzero_ps();
      _MM_TRANSPOSE4_PS(x, y, z, w);
      low[0][bin] = x, low[1][bin] = y, low[2][bin] = z;
      x = bins[0][bin].high(), y = bins[1][bin].high(), z = bins[2][bin].high(), w = _mm_setzero_ps();
      _MM_TRANSPOSE4_PS(x, y, z, w);
      high[0][bin] = x, high[1][bin] = y, high[2][bin] = z;
    }
    const auto surface_area = [](const __m128 box_low[3], const __m128 box_high[3]) {
      const __m128 ex = _mm_sub_ps(box_high[0], box_low[0]), ey = _mm_sub_ps(box_high[1], box_low[1]),
                   ez = _mm_sub_ps(box_high[2], box_low[2]);
      const __m128 area = _mm_mul_ps(_mm_set1_ps(2.0f), _mm_add_ps(_mm_add_ps(_mm_mul_ps(ex, ey), _mm_mul_ps(ey, ez)),
                                                                   _mm_mul_ps(ez, ex)));
      const __m128 empty = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(box_low[0], box_high[0]), _mm_cmpgt_ps(box_low[1], box_high[1])),
                                     _mm_cmpgt_ps(box_low[2], box_high[2]));
      return _mm_andnot_ps(empty, area);  // an empty box: 0
    };
    __m128 right_area[kSahBinCount];
    __m128 box_low[3], box_high[3];
    for (int c = 0; c < 3; ++c) box_low[c] = _mm_set1_ps(kInfinity), box_high[c] = _mm_set1_ps(-kInfinity);
    for (int bin = kSahBinCount - 1; bin > 0; --bin) {
      for (int c = 0; c < 3; ++c) {
        box_low[c] = _mm_min_ps(low[c][bin], box_low[c]);
        box_high[c] = _mm_max_ps(high[c][bin], box_high[c]);
      }
      right_area[bin] = surface_area(box_low, box_high);
    }
    for (int c = 0; c < 3; ++c) box_low[c] = _mm_set1_ps(kInfinity), box_high[c] = _mm_set1_ps(-kInfinity);
    const __m128 area_of_node = _mm_set1_ps(node_area);
    for (int bin = 0; bin < kSahBinCount - 1; ++bin) {
      for (int c = 0; c < 3; ++c) {
        box_low[c] = _mm_min_ps(low[c][bin], box_low[c]);
        box_high[c] = _mm_max_ps(high[c][bin], box_high[c]);
      }
      const __m128 left = _mm_mul_ps(surface_area(box_low, box_high), _mm_load_ps(count_left[bin]));
      const __m128 right = _mm_mul_ps(right_area[bin + 1], _mm_load_ps(count_right[bin + 1]));
      _mm_store_ps(cost[bin], _mm_add_ps(_mm_set1_ps(1.0f), _mm_div_ps(_mm_add_ps(left, right), area_of_node)));
    }
#else
    for (int axis = 0; axis < 3; ++axis) {
      std::array<float, kSahBinCount> right_area{};
      Bounds3 right_box;
      for (int bin = kSahBinCount - 1; bin > 0; --bin) {
        right_box.extend(bins[axis][bin].bounds());
        right_area[bin] = right_box.surface_area();
      }
      Bounds3 left_box;
      for (int bin = 0; bin < kSahBinCount - 1; ++bin) {
        left_box.extend(bins[axis][bin].bounds());
        cost[bin][axis] = 1.0f + (left_box.surface_area() * count_left[bin][axis] +
                                  right_area[bin + 1] * count_right[bin + 1][axis]) /
                                     node_area;
      }
    }
#endif
  }

  // The binned SAH (Wald 2007): drop centroids into 16 bins per axis (all three axes in one
  // pass over the items), then sweep the 15 planes between bins from both sides to price
  // every split in O(bins).
  SahSplit find_sah_split(std::uint32_t begin, std::uint32_t end, const Bounds3& node_bounds,
                          const Bounds3& centroid_bounds) const {
    const Item* items = items_.data();
    const float node_area = node_bounds.surface_area();
    std::array<float, 3> axis_min{}, bins_per_unit{};
    std::array<bool, 3> splittable{};
    for (int axis = 0; axis < 3; ++axis) {
      axis_min[axis] = centroid_bounds.min[axis];
      const float axis_extent = centroid_bounds.max[axis] - axis_min[axis];
      splittable[axis] = axis_extent > 0.0f;  // else no plane along it separates the centroids
      bins_per_unit[axis] = splittable[axis] ? static_cast<float>(kSahBinCount) / axis_extent : 0.0f;
    }

    // Step 1: fill the bins of the three axes.
    BinBoxes growing_bins;
    BinCounts bin_count{};
    for (std::uint32_t i = begin; i < end; ++i) {
      const Item& item = items[i];
      for (int axis = 0; axis < 3; ++axis) {
        const int bin = bin_of(item.centroid[axis], axis_min[axis], bins_per_unit[axis]);
        growing_bins[axis][bin].extend_box(item);
        ++bin_count[axis][bin];
      }
    }
    SahSplit best;
    if (end - begin < kSahDenseSweepMinimum) {
      best = sweep_used_bins(growing_bins, bin_count, splittable, node_area);
    } else {
      // Steps 2 and 3 price the split after each bin: cost[bin][axis] (meaningless where a
      // side has no primitives: skipped below).
      alignas(16) float cost[kSahBinCount][4];
      sweep_bins(growing_bins, bin_count, node_area, cost);
      for (int axis = 0; axis < 3; ++axis) {
        if (!splittable[axis]) continue;
        std::uint32_t left_total = 0, right_total = 0;
        for (int bin = 0; bin < kSahBinCount; ++bin) right_total += bin_count[axis][bin];
        for (int bin = 0; bin < kSahBinCount - 1; ++bin) {
          left_total += bin_count[axis][bin];
          if (left_total == 0 || left_total == right_total) continue;  // a side without primitives
          if (!best.found || cost[bin][axis] < best.cost) best = {true, axis, bin, cost[bin][axis]};
        }
      }
    }
    // A node of zero area (all primitives at one point) prices every split as infinite or NaN.
    if (best.found && !(best.cost < kInfinity)) best.found = false;
    return best;
  }

  // Puts the items of bins 0..last_left_bin first and returns where the right ones start;
  // computes both sides' bounds on the way (no second pass). The swaps are std::partition's
  // (from both ends inwards), so the order is the same as with it.
  std::uint32_t partition_by_bin(std::uint32_t begin, std::uint32_t end, const SahSplit& split,
                                 const Bounds3& centroid_bounds, RangeBounds& left,
                                 RangeBounds& right) {
    Item* items = items_.data();
    const int axis = split.axis;
    const float axis_min = centroid_bounds.min[axis];
    const float bins_per_unit = static_cast<float>(kSahBinCount) / (centroid_bounds.max[axis] - axis_min);
    auto goes_left = [&](const Item& item) {
      return bin_of(item.centroid[axis], axis_min, bins_per_unit) <= split.last_left_bin;
    };
    std::uint32_t first = begin, last = end;
    GrowingRange growing_left, growing_right;
    for (;;) {
      while (first < last && goes_left(items[first])) growing_left.extend(items[first++]);
      while (first < last && !goes_left(items[last - 1])) growing_right.extend(items[--last]);
      if (first == last) break;
      std::swap(items[first], items[--last]);  // items[first] goes left, items[last] right
      growing_left.extend(items[first++]);
      growing_right.extend(items[last]);
    }
    left = growing_left.bounds();
    right = growing_right.bounds();
    return first;
  }

  std::vector<Item> items_;
  std::uint32_t max_leaf_size_;
  int parallel_depth_ = 0;
  Bvh bvh_;
};

}  // namespace

Bvh build_bvh(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  check_max_leaf_size(max_leaf_size, "build_bvh");
  return Builder(primitive_bounds, max_leaf_size).build(/*use_sah=*/false);
}

Bvh build_bvh_sah(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size) {
  check_max_leaf_size(max_leaf_size, "build_bvh_sah");
  return Builder(primitive_bounds, max_leaf_size).build(/*use_sah=*/true);
}

namespace {

// One loop for both queries (any_hit is a flag, not a second copy of the loop). Both children
// of an inner node are tested at once, at the parent (they share a cache line), with the box
// test inlined (box_slabs.h); the nearer by entry distance is visited next and the farther
// waits on a fixed stack with its entry distance, so that it is skipped without a second box
// test if a closer hit is found meanwhile. The counts are the contract's: one node visited per
// box tested, one primitive tested per primitive test.
//
// test_leaf(search, begin, end, any_hit, closest, tested) tests a leaf's primitives
// (leaf_test.h); a template parameter, so that the reference's triangle test is inlined.
template <typename TestLeaf>
std::optional<BvhHit> traverse(const Bvh& bvh, const Ray& ray, bool any_hit, BvhTraversalStats& stats,
                               const TestLeaf& test_leaf) {
  const glm::vec3 ray_direction_inverse = ray_direction_inverse_of(ray);
  const glm::vec3 origin = ray.origin;
  const BvhNode* nodes = bvh.nodes.data();

  Ray search = ray;
  std::optional<BvhHit> closest;
  struct Waiting {
    std::uint32_t node;
    float t_enter;
  };
  Waiting stack[kBvhMaxDepth];
  int stack_size = 0;
  std::uint64_t nodes_visited = 1, primitives_tested = 0;  // locals: kept in registers

  float root_enter;
  std::uint32_t node_index = 0;
  bool have_node = reference::ray_enters_box(origin, ray_direction_inverse, nodes[0].bounds,
                                             search.t_min, search.t_max, root_enter);
  while (have_node) {
    const BvhNode& node = nodes[node_index];
    if (!node.is_leaf()) {
      const std::uint32_t first = node.first_index;
      float enter_first, enter_second;
      const bool hit_first = reference::ray_enters_box(origin, ray_direction_inverse, nodes[first].bounds,
                                                       search.t_min, search.t_max, enter_first);
      const bool hit_second = reference::ray_enters_box(origin, ray_direction_inverse, nodes[first + 1].bounds,
                                                        search.t_min, search.t_max, enter_second);
      nodes_visited += 2;
      // Without a branch on which child is nearer (random rays make it unpredictable): the
      // farther is written to the stack in any case and kept only when both were hit.
      const bool second_is_near = hit_second && (!hit_first || enter_second < enter_first);
      // (stack_size <= this node's depth, below kBvhMaxDepth: the tree checks reject deeper trees)
      stack[stack_size] = second_is_near ? Waiting{first, enter_first} : Waiting{first + 1, enter_second};
      stack_size += (hit_first && hit_second) ? 1 : 0;
      if (hit_first || hit_second) {
        node_index = second_is_near ? first + 1 : first;
        continue;
      }
    } else {
      test_leaf(search, node.first_index, node.first_index + node.primitive_count, any_hit, closest,
                primitives_tested);
      if (any_hit && closest) break;
    }
    // Next: the nearest waiting node that a closer hit has not ruled out.
    have_node = false;
    while (stack_size > 0) {
      const Waiting waiting = stack[--stack_size];
      if (waiting.t_enter <= search.t_max) {
        node_index = waiting.node;
        have_node = true;
        break;
      }
    }
  }
  stats.nodes_visited += nodes_visited;
  stats.primitives_tested += primitives_tested;
  return closest;
}

}  // namespace

std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray,
                                    const PrimitiveIntersector& intersector, bool any_hit,
                                    BvhTraversalStats& stats) {
  if (bvh.nodes.empty()) return std::nullopt;
  return reference::with_leaf_test(intersector, bvh.primitive_order.data(), [&](const auto& test_leaf) {
    return traverse(bvh, ray, any_hit, stats, test_leaf);
  });
}

// The same, the reference's own Moller-Trumbore inlined in the leaf loop instead of two
// indirect calls per triangle (intersector.test into the framework, the framework into
// stage 03) (leaf_test.h).
std::optional<BvhHit> reference::intersect_bvh_inlined(const Bvh& bvh, const Ray& ray, const LeafTriangles& triangles,
                                                       bool any_hit, BvhTraversalStats& stats) {
  if (bvh.nodes.empty()) return std::nullopt;
  return with_leaf_test(triangles, bvh.primitive_order.data(), [&](const auto& test_leaf) {
    return traverse(bvh, ray, any_hit, stats, test_leaf);
  });
}

}  // namespace raylab
