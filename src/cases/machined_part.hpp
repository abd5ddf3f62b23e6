// A machined part (docs/cases.md): the test bed for curving real CAD boundaries, with every kind
// of feature an engineering part has and a sphere shell has not. A block 1 × 0.6 × 0.4 with
//  - its four vertical edges rounded (fillets tangent to both planes: refs change, no dihedral angle),
//  - a slanted face cut 20° off the top at x = 0 (a shallow ridge, below any feature angle),
//  - a cylindrical through hole (planes meeting a cylinder at 90°),
//  - a spherical pocket in the top face (a sphere meeting a plane at a sharp, non-right angle),
//  - a rectangular pocket whose floor meets its walls through a fillet and whose side walls are
//    `wall` thick: a thin wall, where elements have all their vertices on the boundary.
// Built with gmsh's OpenCASCADE kernel and meshed by gmsh with a uniform size; facet refs are the
// CAD surface tags (what gmsh writes for the model's own meshes), and the CAD points where three or
// more surfaces meet are listed as Corners (the ends of its feature lines).
#pragma once

#include <string>
#include <vector>

#include "cases/gmsh_model.hpp"
#include "mesh/mesh.hpp"

namespace hocav {

struct MachinedPartParameters {
  double size = 0.03;  // target edge length h (about 33,000 tetrahedra)
  double wall = 0.03;  // thickness of the pocket's side walls
};

// Tetrahedra with element ref 1, positively oriented; boundary triangles oriented outward with the
// ref of their CAD surface. Deterministic. Error for a non-positive size, a wall outside (0, 0.1],
// or a size so small that the mesh would exceed 50 million elements.
Mesh<3> generate_machined_part(const MachinedPartParameters& parameters);

// Builds the part's model in the current gmsh model (a GmshSession must be open); returns its
// surfaces, each with its own tag as ref.
std::vector<GmshBoundaryEntity> build_machined_part_model(const MachinedPartParameters& parameters);

// Writes the part's CAD model to a .brep or .step/.stp file (for `hocav curve --surface cad:FILE`).
void write_machined_part_cad(const MachinedPartParameters& parameters, const std::string& path);

}  // namespace hocav
