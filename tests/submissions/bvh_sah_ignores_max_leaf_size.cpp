// Grader self-test submission (stage 05b_bvh_sah): the reference file with one mistake in the
// SAH build: a leaf is made whenever the SAH prefers one, also when it holds more than
// max_leaf_size primitives (e.g. many overlapping boxes, which no split separates). Expected:
// the bonus stage's invariant test fails with "expected at most max_leaf_size".
#include "raylab/stages/04_box.h"
#include "raylab/stages/05_bvh.h"

#include "bvh_submission_traversal.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <stdexcept>
#include <string>

namespace raylab {
namespace {

// Below this depth the SAH builder switches to median splits, which halve the count at every
// level: then no tree is deeper than 30 + log2(primitive count) < kBvhMaxDepth.
constexpr int kSahMaxDepth = 30;
constexpr int kSahBinCount = 16;

void check_max_leaf_size(int max_leaf_size, const char* function) {
  if (max_leaf_size < 1 || max_leaf_size > kBvhMaxLeafSize)
    throw std::invalid_argument(std::string(function) + ": max_leaf_size must be in 1.." +
                                std::to_string(kBvhMaxLeafSize) + ", got " +
                                std::to_string(max_leaf_size));
}

// What both builders share: the primitives' boxes and centroids, the order being built, and
// the node array. Nodes are referred to by index: push_back may move them.
class Builder {
 public:
  Builder(const std::vector<Bounds3>& primitive_bounds, int max_leaf_size)
      : bounds_(primitive_bounds), max_leaf_size_(static_cast<std::uint32_t>(max_leaf_size)) {
    centroids_.reserve(bounds_.size());
    for (const Bounds3& box : bounds_) centroids_.push_back(box.centroid());
    bvh_.primitive_order.resize(bounds_.size());
    std::iota(bvh_.primitive_order.begin(), bvh_.primitive_order.end(), 0u);
    // A binary tree with N leaves has 2N - 1 nodes: one allocation.
    if (!bounds_.empty()) bvh_.nodes.reserve(2 * bounds_.size() - 1);
  }

  Bvh build(bool use_sah) {
    if (bounds_.empty()) return std::move(bvh_);
    bvh_.nodes.emplace_back();
    build_node(0, 0, static_cast<std::uint32_t>(bounds_.size()), 0, use_sah);
    return std::move(bvh_);
  }

 private:
  void build_node(std::uint32_t node_index, std::uint32_t begin, std::uint32_t end, int depth,
                  bool use_sah) {
    std::uint32_t* order = bvh_.primitive_order.data();
    Bounds3 node_bounds, centroid_bounds;
    for (std::uint32_t i = begin; i < end; ++i) {
      node_bounds.extend(bounds_[order[i]]);
      centroid_bounds.extend(centroids_[order[i]]);
    }
    bvh_.nodes[node_index].bounds = node_bounds;
    const std::uint32_t count = end - begin;

    int axis = node_bounds.longest_axis();
    std::uint32_t middle = begin + count / 2;
    bool make_leaf = count <= max_leaf_size_;
    bool median_split = true;
    if (use_sah && count > 1 && depth < kSahMaxDepth) {
      const SahSplit split = find_sah_split(begin, end, node_bounds, centroid_bounds);
      if (split.found) {
        const float leaf_cost = static_cast<float>(count);
        make_leaf = split.cost >= leaf_cost;  // MISTAKE: a leaf even when count > max_leaf_size
        if (!make_leaf) {
          const std::uint32_t bin_middle = partition_by_bin(begin, end, split, centroid_bounds);
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
      BvhNode& leaf = bvh_.nodes[node_index];
      leaf.first_index = begin;
      leaf.primitive_count = static_cast<std::uint16_t>(count);
      return;
    }
    if (median_split) {
      // The median split (and the SAH's fallback): the median centroid along `axis` in place,
      // smaller ones before it. Ties broken by index so every standard library agrees.
      std::nth_element(order + begin, order + middle, order + end,
                       [&](std::uint32_t a, std::uint32_t b) {
                         const float ca = centroids_[a][axis], cb = centroids_[b][axis];
                         return ca < cb || (ca == cb && a < b);
                       });
    }

    const auto first_child = static_cast<std::uint32_t>(bvh_.nodes.size());
    bvh_.nodes.emplace_back();
    bvh_.nodes.emplace_back();
    BvhNode& inner = bvh_.nodes[node_index];  // after the push_backs: still valid (reserved)
    inner.first_index = first_child;
    inner.primitive_count = 0;
    inner.split_axis = static_cast<std::uint8_t>(axis);
    build_node(first_child, begin, middle, depth + 1, use_sah);
    build_node(first_child + 1, middle, end, depth + 1, use_sah);
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

  // The binned SAH (Wald 2007): drop centroids into 16 bins per axis, then sweep the 15 planes
  // between bins from both sides to price every split in O(bins).
  SahSplit find_sah_split(std::uint32_t begin, std::uint32_t end, const Bounds3& node_bounds,
                          const Bounds3& centroid_bounds) const {
    const std::uint32_t* order = bvh_.primitive_order.data();
    const float node_area = node_bounds.surface_area();
    SahSplit best;
    for (int axis = 0; axis < 3; ++axis) {
      const float axis_min = centroid_bounds.min[axis];
      const float axis_extent = centroid_bounds.max[axis] - axis_min;
      if (!(axis_extent > 0.0f)) continue;  // no plane along this axis separates the centroids
      const float bins_per_unit = static_cast<float>(kSahBinCount) / axis_extent;

      // Step 1: fill the bins.
      std::array<Bounds3, kSahBinCount> bin_bounds;
      std::array<std::uint32_t, kSahBinCount> bin_count{};
      for (std::uint32_t i = begin; i < end; ++i) {
        const int bin = bin_of(centroids_[order[i]][axis], axis_min, bins_per_unit);
        bin_bounds[bin].extend(bounds_[order[i]]);
        ++bin_count[bin];
      }
      // Step 2: sweep from the right: the area and count of everything right of each plane.
      std::array<float, kSahBinCount> right_area{};
      std::array<std::uint32_t, kSahBinCount> right_count{};
      Bounds3 right_box;
      std::uint32_t right_total = 0;
      for (int bin = kSahBinCount - 1; bin > 0; --bin) {
        right_box.extend(bin_bounds[bin]);
        right_total += bin_count[bin];
        right_area[bin] = right_box.surface_area();
        right_count[bin] = right_total;
      }
      // Step 3: sweep from the left and price the split after each bin.
      Bounds3 left_box;
      std::uint32_t left_total = 0;
      for (int bin = 0; bin < kSahBinCount - 1; ++bin) {
        left_box.extend(bin_bounds[bin]);
        left_total += bin_count[bin];
        const std::uint32_t right = right_count[bin + 1];
        if (left_total == 0 || right == 0) continue;
        const float cost = 1.0f + (left_box.surface_area() * static_cast<float>(left_total) +
                                   right_area[bin + 1] * static_cast<float>(right)) /
                                      node_area;
        if (!best.found || cost < best.cost) best = {true, axis, bin, cost};
      }
    }
    // A node of zero area (all primitives at one point) prices every split as infinite or NaN.
    if (best.found && !(best.cost < kInfinity)) best.found = false;
    return best;
  }

  // Puts the primitives of bins 0..last_left_bin first; returns where the right ones start.
  std::uint32_t partition_by_bin(std::uint32_t begin, std::uint32_t end, const SahSplit& split,
                                 const Bounds3& centroid_bounds) {
    std::uint32_t* order = bvh_.primitive_order.data();
    const float axis_min = centroid_bounds.min[split.axis];
    const float bins_per_unit =
        static_cast<float>(kSahBinCount) / (centroid_bounds.max[split.axis] - axis_min);
    std::uint32_t* middle = std::partition(order + begin, order + end, [&](std::uint32_t p) {
      return bin_of(centroids_[p][split.axis], axis_min, bins_per_unit) <= split.last_left_bin;
    });
    return static_cast<std::uint32_t>(middle - order);
  }

  const std::vector<Bounds3>& bounds_;
  std::vector<glm::vec3> centroids_;
  std::uint32_t max_leaf_size_;
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

// The traversal: the shared one of bvh_submission_traversal.h, without mistakes.
std::optional<BvhHit> intersect_bvh(const Bvh& bvh, const Ray& ray, const PrimitiveIntersector& intersector,
                                    bool any_hit, BvhTraversalStats& stats) {
  return submission::traverse_bvh(bvh, ray, intersector, any_hit, stats, submission::TraversalMistakes());
}

}  // namespace raylab
