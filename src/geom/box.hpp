// An axis-aligned box: the bound of a set of points (a patch's control points, a part's vertices).
#pragma once

#include <algorithm>
#include <limits>

#include "geom/vec.hpp"

namespace hocav {

template <int D>
struct Box {
  Vec<D> lower, upper;

  static Box empty() {
    Box box;
    for (int i = 0; i < D; ++i) {
      box.lower[i] = std::numeric_limits<double>::infinity();
      box.upper[i] = -std::numeric_limits<double>::infinity();
    }
    return box;
  }
  void add(const Vec<D>& point) {
    for (int i = 0; i < D; ++i) {
      lower[i] = std::min(lower[i], point[i]);
      upper[i] = std::max(upper[i], point[i]);
    }
  }
  // The union: an empty box adds nothing.
  void add(const Box& box) {
    for (int i = 0; i < D; ++i) {
      lower[i] = std::min(lower[i], box.lower[i]);
      upper[i] = std::max(upper[i], box.upper[i]);
    }
  }
  double distance2(const Vec<D>& x) const {
    double sum = 0;
    for (int i = 0; i < D; ++i) {
      const double outside = std::max({lower[i] - x[i], x[i] - upper[i], 0.0});
      sum += outside * outside;
    }
    return sum;
  }
  bool is_empty() const { return lower[0] > upper[0]; }
  // Whether the two boxes share a point (faces included).
  bool overlaps(const Box& other) const {
    for (int i = 0; i < D; ++i)
      if (other.upper[i] < lower[i] || upper[i] < other.lower[i]) return false;
    return true;
  }
};

}  // namespace hocav
