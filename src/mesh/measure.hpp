// Signed P1 measure (area in 2D, volume in 3D) of a straight simplex; positive when the vertices
// are in the orientation of the reference element. And the size of a mesh's bounding box.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

inline double signed_measure(const Vec2& p0, const Vec2& p1, const Vec2& p2) { return 0.5 * determinant(p1 - p0, p2 - p0); }

inline double signed_measure(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  return determinant(p1 - p0, p2 - p0, p3 - p0) / 6.0;
}

// The same for D + 1 points.
template <int D>
double signed_measure(const std::array<Vec<D>, D + 1>& p) {
  if constexpr (D == 2)
    return signed_measure(p[0], p[1], p[2]);
  else
    return signed_measure(p[0], p[1], p[2], p[3]);
}

template <int D>
double element_measure(const Mesh<D>& mesh, Index k) {
  const auto& e = mesh.element(k);
  if constexpr (D == 2)
    return signed_measure(mesh.vertex(e[0]), mesh.vertex(e[1]), mesh.vertex(e[2]));
  else
    return signed_measure(mesh.vertex(e[0]), mesh.vertex(e[1]), mesh.vertex(e[2]), mesh.vertex(e[3]));
}

// The sum of the signed P1 measures of the elements (the domain's area or volume when every
// element is positive).
template <int D>
double total_measure(const Mesh<D>& mesh) {
  double sum = 0;
  for (Index k = 0; k < mesh.element_count(); ++k) sum += element_measure(mesh, k);
  return sum;
}

// Per vertex, the summed absolute measure of its elements.
template <int D>
std::vector<double> vertex_element_measures(const Mesh<D>& mesh) {
  std::vector<double> sums(static_cast<std::size_t>(mesh.vertex_count()), 0.0);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    const double measure = std::abs(element_measure(mesh, k));
    for (Index v : mesh.element(k)) sums[static_cast<std::size_t>(v)] += measure;
  }
  return sums;
}

// The length of the diagonal of the vertices' axis-aligned bounding box (0 for no vertex).
template <int D>
double bounding_box_diagonal(const Mesh<D>& mesh) {
  if (mesh.vertex_count() == 0) return 0;
  Vec<D> low = mesh.vertex(0), high = low;
  for (const auto& x : mesh.vertices())
    for (int i = 0; i < D; ++i) {
      low[i] = std::min(low[i], x[i]);
      high[i] = std::max(high[i], x[i]);
    }
  return norm(high - low);
}

}  // namespace hocav
