// Gamma/Medit meshes: .mesh (ASCII) and .meshb (binary, versions 1-4). Keywords and layouts are in
// docs/formats.md, "Gamma / Medit"; P2 node order follows the *P2Ordering keywords when present.
#pragma once

#include <string>

#include "io/mesh_file.hpp"

namespace hocav {

// Reads .mesh or .meshb (chosen by content for binary: the endianness code). Unknown keywords are
// skipped with a warning on stderr.
MeshFileContent read_gamma_mesh(const std::string& path);

// Writes .mesh (version 2) or .meshb (version: 0 = 3, or 4 when counts need 64 bits; 1-4 forced).
template <int D>
void write_gamma_mesh(const std::string& path, const Mesh<D>& mesh, bool binary, int version = 0);

// The Dimension a .mesh/.meshb file declares.
int gamma_mesh_dimension(const std::string& path);

}  // namespace hocav
