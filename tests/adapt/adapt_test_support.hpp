// What the adaptation tests share: the structured unit square or cube (the metric tests' own), and
// the checker's verdict on a mesh that must be consistent and closed (a facet on every boundary face).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../metric/metric_test_support.hpp"
#include "adapt/adaptation_metric.hpp"
#include "mesh/consistency.hpp"
#include "surface/analytic_boundary.hpp"

namespace hocav::adapt_test {

using metric_test::unit_mesh;

template <int D>
void expect_closed_and_consistent(const Mesh<D>& mesh) {
  ConsistencyOptions options;
  options.require_boundary_facets = true;
  ASSERT_EQ(check_consistency(mesh, options), std::vector<std::string>{});
}

// The uniform metric of size h.
template <int D>
AdaptationMetric<D> uniform_metric(double h) {
  AnalyticMetricSpec spec;  // "uniform" unless named
  spec.h = h;
  return AdaptationMetric<D>(spec, {});
}

// The unit square's or cube's sides as planes (generate_square's and generate_cube's refs).
template <int D>
AnalyticBoundary<D> unit_box_sides() {
  AnalyticBoundary<D> sides;
  for (int axis = 0; axis < D; ++axis)
    for (int side = 0; side < 2; ++side) {
      Vec<D> point{}, normal{};
      point[axis] = side;
      normal[axis] = 1;
      // 2D refs: 1 bottom (y = 0), 2 right (x = 1), 3 top, 4 left; 3D: 1 + 2 axis + side.
      const int ref = D == 3 ? 1 + 2 * axis + side : (axis == 1 ? (side == 0 ? 1 : 3) : (side == 1 ? 2 : 4));
      sides.add(ref, AnalyticSurface<D>::plane(point, normal));
    }
  return sides;
}

}  // namespace hocav::adapt_test
