// A bounding-box tree over the patches of a boundary (docs/method.md §9, projection: "candidate triangles
// from a spatial index"). Each patch lies inside the box of its control points (the convex-hull
// property of Bézier patches), so the distance to a box bounds the distance to its patches from
// below: the nearest-patch search visits the nearer child first and skips every box farther than
// the best patch found so far. Built once; queries are const and share no scratch (thread-safe).
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <span>
#include <vector>

#include "base/index.hpp"
#include "geom/box.hpp"
#include "geom/vec.hpp"

namespace hocav {

template <int D>
class PatchTree {
 public:
  PatchTree() = default;
  // `boxes[p]` bounds patch p.
  explicit PatchTree(std::span<const Box<D>> boxes);

  // Calls `distance2_to(patch, best2)` on the patches that may lie closer to x than the best squared
  // distance returned so far (best2 = +∞ at first; the callback may return +∞ to skip a patch) and
  // returns the best value. Nearer boxes are visited first so the bound tightens fast.
  template <class DistanceTo>
  double nearest(const Vec<D>& x, DistanceTo&& distance2_to) const {
    double best2 = std::numeric_limits<double>::infinity();
    if (nodes_.empty()) return best2;
    std::array<Index, kMaxDepth> stack;
    int size = 0;
    stack[size++] = 0;
    while (size > 0) {
      const Node& node = nodes_[stack[--size]];
      if (node.box.distance2(x) >= best2) continue;
      if (node.count > 0) {
        for (Index i = node.first; i < node.first + node.count; ++i) best2 = std::min(best2, distance2_to(order_[i], best2));
        continue;
      }
      // Children are node.first and node.first + 1: push the farther one first so the nearer pops first.
      const Index near_child = node.first, far_child = node.first + 1;
      const bool swap = nodes_[near_child].box.distance2(x) > nodes_[far_child].box.distance2(x);
      stack[size++] = swap ? near_child : far_child;
      stack[size++] = swap ? far_child : near_child;
    }
    return best2;
  }

 private:
  // Median splits halve the patch count, so the depth is at most log2(2^31) + 1 levels.
  static constexpr int kMaxDepth = 64;
  static constexpr Index kLeafSize = 4;

  struct Node {
    Box<D> box;
    Index first = 0;  // leaf: first position in order_; inner node: the first of its two children
    Index count = 0;  // leaf: number of patches; 0 for an inner node
  };

  void build(std::span<const Box<D>> boxes, Index node, Index begin, Index end);

  std::vector<Node> nodes_;
  std::vector<Index> order_;  // patch ids, grouped by leaf
};

extern template class PatchTree<2>;
extern template class PatchTree<3>;

}  // namespace hocav
