// The structured annulus between two concentric circles centred at the origin: m sectors of angle
// 2π/m and layers of vertices on circles of given radii. Each cell (an isosceles trapezoid) is split
// into two triangles by the diagonal from its lower first corner to its upper second one — its two
// diagonals are equally long, and in 2D any choice conforms. The 2D counterpart of the cubed-sphere
// shell, with the same layerings (radial_layers.hpp).
#pragma once

#include <span>

#include "cases/radial_layers.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

// The angle 2π/m between neighbouring radial lines.
double polar_angular_step(int sectors);

// 2 m (radii − 1).
double polar_annulus_triangle_count(int sectors, std::size_t radii);

// Triangles with element ref 1, positively oriented; boundary edges oriented outward (the domain
// on their left), ref 1 on the inner circle (radii.front()), 2 on the outer one. Vertex ids: layer
// times m plus the sector. Throws Error for fewer than 3 sectors, fewer than two radii or radii not
// increasing from a positive first one.
Mesh<2> generate_polar_annulus(int sectors, std::span<const double> radii);

// The annulus with the layers of `layering` and the sector count whose triangle count is nearest
// `target_triangles`.
Mesh<2> generate_polar_annulus(const ShellLayering& layering, double target_triangles);

}  // namespace hocav
