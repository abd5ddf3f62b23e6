// Bounding-box tree over boundary patches (docs/method.md §9, projection).
#include "surface/patch_tree.hpp"

#include <algorithm>

namespace hocav {

template <int D>
PatchTree<D>::PatchTree(std::span<const Box<D>> boxes) {
  if (boxes.empty()) return;
  const Index count = checked_index(boxes.size(), "patches");
  order_.resize(boxes.size());
  for (Index p = 0; p < count; ++p) order_[p] = p;
  nodes_.reserve(2 * boxes.size() / kLeafSize + 1);
  nodes_.emplace_back();
  build(boxes, 0, 0, count);
}

template <int D>
void PatchTree<D>::build(std::span<const Box<D>> boxes, Index node, Index begin, Index end) {
  Box<D> box = Box<D>::empty();
  Box<D> centres = Box<D>::empty();
  for (Index i = begin; i < end; ++i) {
    const Box<D>& patch_box = boxes[order_[i]];
    box.add(patch_box);
    centres.add(0.5 * (patch_box.lower + patch_box.upper));
  }
  nodes_[node].box = box;
  if (end - begin <= kLeafSize) {
    nodes_[node].first = begin;
    nodes_[node].count = end - begin;
    return;
  }
  // Split at the median centre along the axis where the centres spread most.
  int axis = 0;
  for (int i = 1; i < D; ++i)
    if (centres.upper[i] - centres.lower[i] > centres.upper[axis] - centres.lower[axis]) axis = i;
  const Index middle = begin + (end - begin) / 2;
  auto centre = [&boxes, axis](Index p) { return boxes[p].lower[axis] + boxes[p].upper[axis]; };
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&centre](Index a, Index b) { return centre(a) < centre(b); });
  const Index children = static_cast<Index>(nodes_.size());
  nodes_[node].first = children;
  nodes_[node].count = 0;
  nodes_.emplace_back();
  nodes_.emplace_back();
  build(boxes, children, begin, middle);
  build(boxes, children + 1, middle, end);
}

template class PatchTree<2>;
template class PatchTree<3>;

}  // namespace hocav
