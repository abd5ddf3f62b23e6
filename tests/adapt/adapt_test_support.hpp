// What the adaptation tests share: the structured unit square or cube (the metric tests' own), the
// star of a closed boundary from a vertex, and the checker's verdict on a mesh that must be
// consistent and closed (a facet on every boundary face).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "../metric/metric_test_support.hpp"
#include "adapt/adaptation_metric.hpp"
#include "mesh/consistency.hpp"
#include "mesh/measure.hpp"
#include "surface/analytic_boundary.hpp"

namespace hocav::adapt_test {

using metric_test::unit_mesh;

template <int D>
void expect_closed_and_consistent(const Mesh<D>& mesh) {
  ConsistencyOptions options;
  options.require_boundary_facets = true;
  ASSERT_EQ(check_consistency(mesh, options), std::vector<std::string>{});
}

// Whether every element has a positive measure.
template <int D>
bool every_element_positive(const Mesh<D>& mesh) {
  for (Index k = 0; k < mesh.element_count(); ++k)
    if (!(element_measure(mesh, k) > 0)) return false;
  return true;
}

// The star of a closed boundary from one inner vertex (the last point): an element on every face of
// `faces` (either orientation), and a facet on each, of ref 1 when all its vertices lie on the plane
// x[D - 1] = 0 (the bottom), 2 otherwise.
template <int D>
Mesh<D> star_of(const std::vector<Vec<D>>& points, const std::vector<std::array<Index, D>>& faces) {
  Mesh<D> mesh;
  for (const Vec<D>& point : points) mesh.add_vertex(point);
  const Index center = mesh.vertex_count() - 1;
  for (const auto& face : faces) {
    typename Mesh<D>::Element element{};
    std::copy(face.begin(), face.end(), element.begin());
    element[D] = center;
    std::array<Vec<D>, D + 1> corners;
    for (int i = 0; i <= D; ++i) corners[i] = mesh.vertex(element[i]);
    if (signed_measure<D>(corners) < 0) std::swap(element[0], element[1]);
    mesh.add_element(element, 1);
    const bool bottom = std::all_of(face.begin(), face.end(), [&](Index v) { return mesh.vertex(v)[D - 1] == 0; });
    typename Mesh<D>::Facet facet;  // the face opposite the center, as the elements orient it
    for (int i = 0; i < D; ++i) facet[i] = element[face_vertices<D>(D)[i]];
    mesh.add_facet(facet, bottom ? 1 : 2);
  }
  mesh.build_topology();
  return mesh;
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
