// A vertex normal from a least-squares quadric (docs/method.md §9: better normals than averaged facet
// normals). In a frame whose last axis is a first guess n0 of the normal, the surface near the
// vertex is a height function z = q(x) + g·x (q quadratic, g the slope); fitting it to neighbouring
// surface points by least squares and tilting n0 by −g gives a normal whose error is O(h²) on any
// smooth surface, where averaged facet normals err by O(h) on irregular meshes. The fit is redone
// once in the frame of its result.
#pragma once

#include <span>

#include "geom/vec.hpp"

namespace hocav {

template <int D>
struct QuadricNormal {
  Vec<D> normal{};
  // The weighted root-mean-square height residual of the fit, in units of the mean neighbour
  // distance: how well one quadric explains the points (0 on a plane; large across a fold or where
  // a fillet meets a plane). Infinite when the fit failed.
  double residual = 0;
};

// The unit normal at `point` fitted to `neighbors` (points of the surface near it, `point` itself
// excluded), oriented like `initial` (unit). Returns `initial` with an infinite residual when the
// points do not determine the fit (too few, or all on a line), or when the fit turns the normal by
// more than `max_turn_radians`.
template <int D>
QuadricNormal<D> quadric_fitted_normal(const Vec<D>& point, std::span<const Vec<D>> neighbors, const Vec<D>& initial,
                                       double max_turn_radians);

// The same with the slopes only (the plane z = g·x): for neighbourhoods too small for the quadric,
// exact when the points lie on a plane through `point`.
template <int D>
QuadricNormal<D> plane_fitted_normal(const Vec<D>& point, std::span<const Vec<D>> neighbors, const Vec<D>& initial,
                                     double max_turn_radians);

}  // namespace hocav
