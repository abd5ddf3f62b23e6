// Exact projections onto spheres, cylinders and planes (docs/method.md §9).
#include "surface/analytic_boundary.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "base/error.hpp"

namespace hocav {
namespace {

// The unit vector along v; an arbitrary unit vector orthogonal to `axis` when v vanishes (a point
// on a sphere's centre or a cylinder's axis is equally close to every point of it).
template <int D>
Vec<D> direction_or_any(const Vec<D>& v, const Vec<D>& axis) {
  const double length = norm(v);
  if (length > 0) return v * (1 / length);
  Vec<D> any{};
  any[0] = 1;
  if (std::abs(dot(any, axis)) > 0.5) {
    any[0] = 0;
    any[1] = 1;
  }
  any -= dot(any, axis) * axis;
  return any * (1 / norm(any));
}

}  // namespace

template <int D>
Vec<D> AnalyticSurface<D>::normal(const Vec<D>& x) const {
  switch (kind) {
    case Kind::kSphere: return direction_or_any<D>(x - origin, direction);
    case Kind::kCylinder: {
      const Vec<D> offset = x - origin;
      return direction_or_any<D>(offset - dot(offset, direction) * direction, direction);
    }
    case Kind::kPlane: break;
  }
  return direction;
}

template <int D>
Vec<D> AnalyticSurface<D>::project(const Vec<D>& x) const {
  if (kind == Kind::kPlane) return x - dot(x - origin, direction) * direction;
  // Sphere and cylinder: the point at `radius` from the centre or axis, along the normal.
  const Vec<D> offset = x - origin;
  const Vec<D> on_axis = kind == Kind::kSphere ? origin : origin + dot(offset, direction) * direction;
  return on_axis + radius * normal(x);
}

template <int D>
void AnalyticBoundary<D>::add(int ref, const AnalyticSurface<D>& surface) {
  for (auto& [known_ref, known_surface] : surfaces_)
    if (known_ref == ref) {
      known_surface = surface;
      return;
    }
  surfaces_.emplace_back(ref, surface);
}

template <int D>
BoundaryPoint<D> AnalyticBoundary<D>::project(const Vec<D>& x, const ProjectionQuery& query) const {
  BoundaryPoint<D> best;
  best.distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < surfaces_.size(); ++i) {
    const auto& [ref, surface] = surfaces_[i];
    if (query.ref && ref != *query.ref) continue;
    const Vec<D> point = surface.project(x);
    const double distance = norm(point - x);
    if (best.patch == kNoIndex || distance < best.distance) best = {point, distance, static_cast<Index>(i), ref};
  }
  if (best.patch == kNoIndex)
    throw Error(query.ref ? "the analytic boundary has no surface with ref " + std::to_string(*query.ref)
                          : std::string("the analytic boundary has no surface"));
  return best;
}

template <int D>
Vec<D> AnalyticBoundary<D>::normal(const Vec<D>& x, const ProjectionQuery& query) const {
  return surfaces_[project(x, query).patch].second.normal(x);
}

template <int D>
AnalyticBoundary<D> concentric_shell_boundary(double inner_radius, double outer_radius) {
  AnalyticBoundary<D> boundary;
  boundary.add(1, AnalyticSurface<D>::sphere({}, inner_radius));
  boundary.add(2, AnalyticSurface<D>::sphere({}, outer_radius));
  return boundary;
}

template struct AnalyticSurface<2>;
template struct AnalyticSurface<3>;
template class AnalyticBoundary<2>;
template class AnalyticBoundary<3>;
template AnalyticBoundary<2> concentric_shell_boundary(double, double);
template AnalyticBoundary<3> concentric_shell_boundary(double, double);

}  // namespace hocav
