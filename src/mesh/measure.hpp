// Signed P1 measure (area in 2D, volume in 3D) of a straight simplex; positive when the vertices
// are in the orientation of the reference element.
#pragma once

#include "mesh/mesh.hpp"

namespace hocav {

inline double signed_measure(const Vec2& p0, const Vec2& p1, const Vec2& p2) {
  return 0.5 * determinant(p1 - p0, p2 - p0);
}

inline double signed_measure(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  return determinant(p1 - p0, p2 - p0, p3 - p0) / 6.0;
}

template <int D>
double element_measure(const Mesh<D>& mesh, Index k) {
  const auto& e = mesh.element(k);
  if constexpr (D == 2)
    return signed_measure(mesh.vertex(e[0]), mesh.vertex(e[1]), mesh.vertex(e[2]));
  else
    return signed_measure(mesh.vertex(e[0]), mesh.vertex(e[1]), mesh.vertex(e[2]), mesh.vertex(e[3]));
}

}  // namespace hocav
