// Distance of a (P1 or P2) boundary to a geometry, by dense sampling (docs/method.md §9).
#include "surface/boundary_distance.hpp"

#include <algorithm>
#include <array>

#include "surface/cubic_patch.hpp"

namespace hocav {

template <int D>
double max_boundary_distance(const Mesh<D>& mesh, const BoundaryGeometry<D>& geometry, int n) {
  double worst = 0;
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    const auto& facet = mesh.facet(f);
    // The facet's quadratic Lagrange nodes: its vertices and one node per edge (straight on P1).
    std::array<Vec<D>, CubicPatch<D>::kEdges> edge_nodes;
    for (int e = 0; e < CubicPatch<D>::kEdges; ++e) {
      const Index a = facet[kPatchEdges<D>[e][0]], b = facet[kPatchEdges<D>[e][1]];
      edge_nodes[e] = mesh.is_p2() ? mesh.edge_node(mesh.find_edge(a, b)) : 0.5 * (mesh.vertex(a) + mesh.vertex(b));
    }
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= (D == 3 ? n - i : 0); ++j) {
        std::array<double, D> lambda{};
        lambda[1] = double(i) / n;
        if constexpr (D == 3) lambda[2] = double(j) / n;
        lambda[0] = 1;
        for (int k = 1; k < D; ++k) lambda[0] -= lambda[k];
        // P2 shape functions: λ_i (2λ_i − 1) at vertices, 4 λ_a λ_b on edges.
        Vec<D> point{};
        for (int k = 0; k < D; ++k) point += lambda[k] * (2 * lambda[k] - 1) * mesh.vertex(facet[k]);
        for (int e = 0; e < CubicPatch<D>::kEdges; ++e)
          point += 4 * lambda[kPatchEdges<D>[e][0]] * lambda[kPatchEdges<D>[e][1]] * edge_nodes[e];
        worst = std::max(worst, geometry.project(point, {.ref = mesh.facet_ref(f)}).distance);
      }
  }
  return worst;
}

template double max_boundary_distance(const Mesh<2>&, const BoundaryGeometry<2>&, int);
template double max_boundary_distance(const Mesh<3>&, const BoundaryGeometry<3>&, int);

}  // namespace hocav
