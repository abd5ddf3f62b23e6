// The structured shell between two concentric spheres centred at the origin: the cube's surface
// grid, n × n cells per face, mapped onto the unit sphere by the equiangular map (each coordinate
// c in [−1, 1] of the cube becomes tan(π/4 c), then the point is normalized; grid lines are great
// circles π/(2n) apart along the face axes), and extruded radially through layers of given radii.
//
// Each quad is split into two triangles along its shorter diagonal, each triangle × layer prism
// into three tetrahedra whose side diagonals start at the prism's smallest vertex id: a side quad's
// diagonal depends only on its own vertex ids, so neighbouring prisms agree (conforming) and no
// Steiner point is needed. Vertex ids grow with the layer, so the rule reads: in the side quad of
// surface vertices a < b, the diagonal runs from a on the lower sphere to b on the upper one.
// No gmsh, deterministic, linear time; memory is the mesh plus the surface grid.
#pragma once

#include <span>
#include <vector>

#include "cases/radial_layers.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

// The grid's angular step π/(2n) for n cells per cube side.
double cubed_sphere_angular_step(int cells_per_side);

// 36 n² (radii − 1): 6 faces × n² quads × 2 triangles × 3 tetrahedra per layer.
double cubed_sphere_shell_tet_count(int cells_per_side, std::size_t radii);

// Tetrahedra with element ref 1, positively oriented; boundary triangles oriented outward, ref 1
// on the inner sphere (radii.front()) and 2 on the outer one (radii.back()). Vertex ids: layer
// times (6 n² + 2) plus the vertex's id on the surface grid. Throws Error for n < 1, fewer than
// two radii, radii not increasing from a positive first one, or more than 2³¹ entities.
Mesh<3> generate_cubed_sphere_shell(int cells_per_side, std::span<const double> radii);

// The shell with the layers of `layering` at the resolution whose tetrahedron count is nearest
// `target_tets`.
Mesh<3> generate_cubed_sphere_shell(const ShellLayering& layering, double target_tets);

}  // namespace hocav
