// A side's normal at a vertex of a feature line from a circle fitted in the line's normal plane
// (docs/surface.md, "Where a fillet meets a plane"). A fillet only one or two edges wide spans up to
// a quarter circle: no quadric height function follows it from one side, and averaged facet normals
// lean by half a facet's turn. Projected along the feature line's tangent t, the side's points of
// a cylindrical fillet (axis along t) lie on its circle, and those of a plane containing t on a
// line. In a frame x (across), y (along t), z (normal), the surface
// x² + z² + D x + E z + B y + F y² = 0 through the vertex, fitted by least squares, has the normal
// (D, B, E) there: exact on cylinders along t (F = 0) and on spheres (F = 1, whatever t); points
// that project onto a line through the vertex give that line's normal (a plane).
#pragma once

#include <optional>
#include <span>

#include "geom/vec.hpp"

namespace hocav {

// The unit normal at `point` of the side whose points (the vertex excluded) are `neighbors`, for a
// feature line of unit tangent `tangent` there, oriented like `initial`; none when the points do
// not determine it (fewer than kSectionFitPoints, a singular system) or do not lie on the fitted
// surface (within a thousandth of their mean distance: the model does not describe them).
inline constexpr int kSectionFitPoints = 5;
std::optional<Vec3> section_circle_normal(const Vec3& point, const Vec3& tangent, std::span<const Vec3> neighbors, const Vec3& initial);

}  // namespace hocav
