// The check of a mesh given to the adaptation or the curving: refused when `hocav stats` calls it
// inconsistent, its defects that the operators work around (open boundary, non-manifold parts,
// overlaps) named for a warning.
#pragma once

#include <string>

#include "mesh/mesh.hpp"

namespace hocav {

// Throws Error naming `path` and the first problem of an inconsistent mesh; returns "" or the
// summary of its defects, which the caller shows as a warning.
template <int D>
std::string check_input_mesh(const Mesh<D>& mesh, const std::string& path);

}  // namespace hocav
