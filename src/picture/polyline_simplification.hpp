// Fewer points for the same drawing: a polyline's points that lie within a tolerance of the line
// through the points kept around them are dropped (Douglas–Peucker). A section's straight sides,
// sampled as finely as its curved ones, shrink to their two ends.
#pragma once

#include <span>
#include <vector>

#include "geom/vec.hpp"

namespace hocav {

// The kept points, in order; every dropped point lies within `tolerance` of the piece that
// replaces it. The ends are always kept; a closed polyline is given with its first point once.
std::vector<Vec2> simplified_polyline(std::span<const Vec2> points, double tolerance, bool closed);

}  // namespace hocav
