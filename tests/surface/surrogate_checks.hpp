// Checks of a P3 surrogate's edge curves shared by the surface tests (with and without gmsh).
#pragma once

#include <gtest/gtest.h>

#include <array>

#include "surface/p3_surrogate.hpp"
#include "surface_test_meshes.hpp"

namespace hocav::testing {

// The control points of the edge curve of patch f from mesh vertex a to mesh vertex b.
template <int D>
std::array<Vec<D>, 4> edge_curve(const Mesh<D>& mesh, const P3Surrogate<D>& surrogate, Index f, Index a, Index b) {
  const CubicPatch<D>& patch = surrogate.patch(f);
  for (int e = 0; e < CubicPatch<D>::kEdges; ++e) {
    const auto& ends = kPatchEdges<D>[e];
    const Index first = mesh.facet(f)[ends[0]], second = mesh.facet(f)[ends[1]];
    if (first == a && second == b) return {patch.vertex(ends[0]), patch.edge_point(e, 0), patch.edge_point(e, 1), patch.vertex(ends[1])};
    if (first == b && second == a) return {patch.vertex(ends[1]), patch.edge_point(e, 1), patch.edge_point(e, 0), patch.vertex(ends[0])};
  }
  ADD_FAILURE() << "facet " << f << " has no edge " << a << "-" << b;
  return {};
}

// C0: the two patches of every edge have the same edge curve — the same control points, bit for
// bit — and evaluating either patch along the edge gives that curve.
inline void expect_no_cracks(const Mesh<3>& mesh, const P3Surrogate<3>& surrogate) {
  Index shared = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f)
    for (int side = 0; side < 3; ++side) {
      const Index g = surrogate.topology().neighbors[f][side];
      if (g == kNoIndex) continue;
      const Index a = mesh.facet(f)[(side + 1) % 3], b = mesh.facet(f)[(side + 2) % 3];
      const auto curve = edge_curve(mesh, surrogate, f, a, b);
      EXPECT_EQ(curve, edge_curve(mesh, surrogate, g, a, b)) << "facets " << f << " and " << g;
      const int local_edge = (side + 1) % 3;  // kPatchEdges: edge e joins local vertices e and e + 1
      for (double s : {0.1, 0.5, 0.9}) {
        const double w = 1 - s;
        const Vec3 bezier = w * w * w * curve[0] + 3 * w * w * s * curve[1] + 3 * w * s * s * curve[2] + s * s * s * curve[3];
        EXPECT_LT(norm(evaluate(surrogate.patch(f), patch_edge_parameters<3>(local_edge, s)) - bezier), 1e-15);
      }
      ++shared;
    }
  EXPECT_EQ(shared, 3 * mesh.facet_count());  // closed surfaces: every side joins two facets
}

}  // namespace hocav::testing
