// Boundaries known in closed form (docs/method.md §9, "from the CAD or an analytic geometry when known"):
// spheres (circles in 2D), cylinders (3D) and planes (lines in 2D), one per facet ref, with exact
// projections and normals. For tests and for generated cases whose geometry is known.
#pragma once

#include <utility>
#include <vector>

#include "surface/boundary_geometry.hpp"

namespace hocav {

template <int D>
struct AnalyticSurface {
  enum class Kind { kSphere, kCylinder, kPlane };
  Kind kind = Kind::kSphere;
  Vec<D> origin{};     // the sphere's centre, a point of the cylinder's axis or of the plane
  Vec<D> direction{};  // the cylinder's unit axis or the plane's unit normal
  double radius = 0;

  static AnalyticSurface sphere(const Vec<D>& centre, double radius) { return {Kind::kSphere, centre, {}, radius}; }
  static AnalyticSurface cylinder(const Vec<D>& axis_point, const Vec<D>& axis, double radius) requires(D == 3) {
    return {Kind::kCylinder, axis_point, axis * (1 / norm(axis)), radius};
  }
  static AnalyticSurface plane(const Vec<D>& point, const Vec<D>& normal) { return {Kind::kPlane, point, normal * (1 / norm(normal)), 0}; }

  Vec<D> project(const Vec<D>& x) const;
  // Unit normal at the projection of x: away from the centre or axis, along `direction` for a plane.
  Vec<D> normal(const Vec<D>& x) const;
};

template <int D>
class AnalyticBoundary final : public BoundaryGeometry<D> {
 public:
  // Facets with ref `ref` lie on `surface` (a later surface for the same ref replaces it).
  void add(int ref, const AnalyticSurface<D>& surface);

  // Patches are the positions of the surfaces in the order they were added; the hint is not needed.
  BoundaryPoint<D> project(const Vec<D>& x, const ProjectionQuery& query = {}) const override;
  Vec<D> normal(const Vec<D>& x, const ProjectionQuery& query = {}) const override;

 private:
  std::vector<std::pair<int, AnalyticSurface<D>>> surfaces_;
};

// The geometry of the concentric-shell cases (annulus, sphere shell) centred at the origin: ref 1
// the inner circle/sphere, ref 2 the outer one.
template <int D>
AnalyticBoundary<D> concentric_shell_boundary(double inner_radius, double outer_radius);

extern template class AnalyticBoundary<2>;
extern template class AnalyticBoundary<3>;

}  // namespace hocav
