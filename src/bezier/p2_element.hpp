// One P2 triangle or tetrahedron as a value: its Lagrange nodes and its Bézier control net
// (docs/method.md §8: C_ij = 2 M_ij − (P_i + P_j)/2; vertex nodes are unchanged).
// Nodes are in hocav's local order (src/mesh/simplex.hpp): vertices, then one node per edge in
// Simplex<D>::kEdgeLocalVertices order (triangle v0 v1 v2 m01 m12 m20; tetrahedron
// v0 v1 v2 v3 m01 m12 m20 m03 m13 m23).
#pragma once

#include <array>

#include "base/index.hpp"
#include "geom/vec.hpp"
#include "mesh/mesh.hpp"
#include "mesh/simplex.hpp"

namespace hocav {

template <int D>
inline constexpr int kP2NodeCount = (D + 1) * (D + 2) / 2;

// The local node on the pair of vertices (i, j): vertex i when i == j, else the node of edge {i, j}.
// In Bézier terms it holds the control node of multi-index e_i + e_j.
template <int D>
inline constexpr auto kP2NodeOfPair = [] {
  std::array<std::array<int, D + 1>, D + 1> node{};
  for (int i = 0; i <= D; ++i) node[i][i] = i;
  for (int edge = 0; edge < Simplex<D>::kEdges; ++edge) {
    const auto& ends = edge_vertices<D>(edge);
    node[ends[0]][ends[1]] = node[ends[1]][ends[0]] = D + 1 + edge;
  }
  return node;
}();

template <int D>
constexpr int p2_node_of_pair(int i, int j) {
  return kP2NodeOfPair<D>[i][j];
}

// Lagrange nodes: the vertices and the points of the curved edges at their parameter 1/2.
template <int D>
struct P2Element {
  std::array<Vec<D>, kP2NodeCount<D>> nodes{};

  const Vec<D>& vertex(int i) const { return nodes[i]; }
  const Vec<D>& edge_node(int edge) const { return nodes[D + 1 + edge]; }
};

// Bézier control nodes, same layout as P2Element: the curve of an edge passes through its vertices
// and is pulled toward (not through) its control node.
template <int D>
struct BezierControlNet {
  std::array<Vec<D>, kP2NodeCount<D>> nodes{};

  // C_{e_i + e_j}: vertex i when i == j, else the control node of edge {i, j}.
  const Vec<D>& of_pair(int i, int j) const { return nodes[p2_node_of_pair<D>(i, j)]; }
};

template <int D>
BezierControlNet<D> control_net(const P2Element<D>& element) {
  BezierControlNet<D> net;
  for (int i = 0; i <= D; ++i) net.nodes[i] = element.vertex(i);
  for (int edge = 0; edge < Simplex<D>::kEdges; ++edge) {
    const auto& ends = edge_vertices<D>(edge);
    net.nodes[D + 1 + edge] = 2.0 * element.edge_node(edge) - 0.5 * (element.vertex(ends[0]) + element.vertex(ends[1]));
  }
  return net;
}

// Element k of the mesh; a P1 mesh gives the straight element (edge nodes at the midpoints).
template <int D>
P2Element<D> gather_p2_element(const Mesh<D>& mesh, Index k) {
  P2Element<D> element;
  const auto& vertices = mesh.element(k);
  for (int i = 0; i <= D; ++i) element.nodes[i] = mesh.vertex(vertices[i]);
  for (int edge = 0; edge < Simplex<D>::kEdges; ++edge) {
    const auto& ends = edge_vertices<D>(edge);
    element.nodes[D + 1 + edge] = mesh.is_p2() ? mesh.edge_node(mesh.element_edge(k, edge))
                                               : 0.5 * (element.vertex(ends[0]) + element.vertex(ends[1]));
  }
  return element;
}

// The straight (P1) element's Jacobian det(P_1 − P_0, …, P_D − P_0): D! times its signed measure.
template <int D>
double straight_jacobian(const P2Element<D>& element) {
  const auto& p = element.nodes;
  if constexpr (D == 2)
    return determinant(p[1] - p[0], p[2] - p[0]);
  else
    return determinant(p[1] - p[0], p[2] - p[0], p[3] - p[0]);
}

}  // namespace hocav
