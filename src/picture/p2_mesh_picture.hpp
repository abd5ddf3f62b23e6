// The picture of a 2D P2 mesh, exact: each curved edge is the parabola of its P2 map, drawn as the
// quadratic Bézier curve with control point 2m − (a + b)/2 (ends a, b, Lagrange mid node m), each
// triangle filled with the colour of its value.
#pragma once

#include <span>

#include "bezier/p2_element.hpp"
#include "mesh/mesh.hpp"
#include "picture/mesh_figure.hpp"

namespace hocav {

// The outline of a P2 triangle in page coordinates: three quadratic Bézier pieces.
SvgPath p2_triangle_path(const P2Element<2>& element, const PageTransform& transform);

// `element_values[k]`: the value triangle k is coloured by.
SvgCanvas p2_mesh_picture(const Mesh<2>& mesh, std::span<const double> element_values, const MeshFigureOptions& options);

}  // namespace hocav
