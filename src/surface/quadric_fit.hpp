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

// The unit normal at `point` fitted to `neighbors` (points of the surface near it, `point` itself
// excluded), oriented like `initial` (unit). Returns `initial` when the points do not determine the
// fit (too few, or all on a line), or when the fit turns the normal by more than `max_turn_radians`.
template <int D>
Vec<D> quadric_fitted_normal(const Vec<D>& point, std::span<const Vec<D>> neighbors, const Vec<D>& initial,
                             double max_turn_radians);

}  // namespace hocav
