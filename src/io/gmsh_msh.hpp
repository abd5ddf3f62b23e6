// Gmsh .msh 4.1 ASCII meshes: lines (1, 8), triangles (2, 9), tetrahedra (4, 11), points (15);
// physical tags become refs. Node orders are in docs/formats.md, "Gmsh .msh 4.1".
#pragma once

#include <string>

#include "io/mesh_file.hpp"

namespace hocav {

MeshFileContent read_gmsh_msh(const std::string& path);

template <int D>
void write_gmsh_msh(const std::string& path, const Mesh<D>& mesh);

int gmsh_msh_dimension(const std::string& path);

}  // namespace hocav
