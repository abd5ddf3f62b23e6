// The region between two concentric circles (the annulus, 2D) or spheres (the spherical shell,
// 3D) centred at the origin, meshed by gmsh's OpenCASCADE kernel with a uniform size. A domain with
// curved boundaries and known measure: the test bed for curving boundary edges.
#pragma once

#include "mesh/mesh.hpp"

namespace hocav {

struct ShellParameters {
  double inner_radius = 0.5;
  double outer_radius = 1.0;
  double size = 0.1;  // the target edge length h
};

// Triangles (2D) or tetrahedra (3D) with element ref 1, positively oriented; boundary facets on
// every boundary face, oriented outward, ref 1 on the inner circle/sphere and 2 on the outer one.
// Boundary vertices lie on their circle/sphere to rounding. Deterministic: the same parameters give
// the same mesh. Throws Error for radii not 0 < inner < outer, a non-positive size, or a size so
// small that the mesh would exceed 50 million elements.
Mesh<2> generate_annulus(const ShellParameters& parameters);
Mesh<3> generate_sphere_shell(const ShellParameters& parameters);

}  // namespace hocav
