// Structured cases: the unit square split into right triangles and the unit cube split into six
// tetrahedra per cell (Kuhn subdivision, conforming across cells), boundary facets included.
#pragma once

#include "mesh/mesh.hpp"

namespace hocav {

// n cells per side of length 1 (n >= 1). Boundary facet refs: 2D 1 bottom, 2 right, 3 top, 4 left;
// 3D 1 x=0, 2 x=1, 3 y=0, 4 y=1, 5 z=0, 6 z=1. Element ref 1. Corners tagged; in 3D the cube's 12
// edges are kept as feature lines and tagged as ridges.
Mesh<2> generate_square(int cells_per_side);
Mesh<3> generate_cube(int cells_per_side);

// The number of cells per side for a target size h on a unit side.
int cells_for_size(double h);

}  // namespace hocav
