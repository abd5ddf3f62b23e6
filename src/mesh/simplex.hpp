// Local numbering of triangles and tetrahedra, shared by the mesh, the file formats and the kernels.
// Edges follow the Gamma/VTK P2 order; face i is opposite vertex i and oriented outward for a
// positively oriented element.
#pragma once

#include <array>
#include <cstddef>

namespace hocav {

template <int D>
struct Simplex;

template <>
struct Simplex<2> {
  static constexpr int kVertices = 3;
  static constexpr int kEdges = 3;
  static constexpr int kFaces = 3;
  static constexpr int kFaceVertexCount = 2;
  // P2 node order: v0 v1 v2 m01 m12 m20.
  static constexpr std::array<std::array<int, 2>, 3> kEdgeLocalVertices{{{0, 1}, {1, 2}, {2, 0}}};
  static constexpr std::array<std::array<int, 2>, 3> kFaceLocalVertices{{{1, 2}, {2, 0}, {0, 1}}};
};

template <>
struct Simplex<3> {
  static constexpr int kVertices = 4;
  static constexpr int kEdges = 6;
  static constexpr int kFaces = 4;
  static constexpr int kFaceVertexCount = 3;
  // P2 node order: v0 v1 v2 v3 m01 m12 m20 m03 m13 m23.
  static constexpr std::array<std::array<int, 2>, 6> kEdgeLocalVertices{{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};
  static constexpr std::array<std::array<int, 3>, 4> kFaceLocalVertices{{{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};
};

// The local vertices of face `face` of a D-simplex (opposite vertex `face`, outward).
template <int D>
constexpr const auto& face_vertices(int face) {
  return Simplex<D>::kFaceLocalVertices[static_cast<std::size_t>(face)];
}

template <int D>
constexpr const std::array<int, 2>& edge_vertices(int edge) {
  return Simplex<D>::kEdgeLocalVertices[static_cast<std::size_t>(edge)];
}

// Whether an entity's vertex list names a vertex twice.
template <typename Id, std::size_t N>
bool repeats_a_vertex(const std::array<Id, N>& vertices) {
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (vertices[i] == vertices[j]) return true;
  return false;
}

}  // namespace hocav
