// The region between two concentric circles (the annulus, 2D) or spheres (the spherical shell,
// 3D) centred at the origin, meshed by gmsh's OpenCASCADE kernel with a uniform size. A domain with
// curved boundaries and known measure: the test bed for curving boundary edges.
#pragma once

#include <string>
#include <vector>

#include "cases/gmsh_model.hpp"
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

// Builds the shell's CAD model with OpenCASCADE in the current gmsh model (a GmshSession must be
// open) and returns its boundary entities (circles in 2D, spheres in 3D) with the facet refs above.
// Error unless 0 < inner < outer.
template <int D>
std::vector<GmshBoundaryEntity> build_shell_model(double inner_radius, double outer_radius);

// Writes the shell's CAD model to a .brep or .step/.stp file. Read back, its boundary entities
// are numbered by OpenCASCADE (the outer one first: tags 1 outer, 2 inner — not the facet refs),
// so a CAD boundary maps the refs by proximity (surface/cad_boundary_gmsh.hpp).
// It is also the model of the structured shells (cubed-shell, polar-annulus, shear-circle), whose
// boundary vertices lie on the same circles or spheres.
template <int D>
void write_shell_cad(double inner_radius, double outer_radius, const std::string& path);

// Error unless `path` names a CAD file write_shell_cad can write (.brep, .step, .stp).
void check_cad_path(const std::string& path);

}  // namespace hocav
