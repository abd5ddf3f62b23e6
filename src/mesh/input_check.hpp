// A mesh given to the adaptation or the curving: first prepared as the file formats allow it to
// come (all elements inverted, boundary faces without facets), then checked: refused when `hocav
// stats` calls it inconsistent, its defects that the operators work around (open boundary,
// non-manifold parts, overlaps) named for a warning.
#pragma once

#include <functional>
#include <string>

#include "mesh/mesh.hpp"

namespace hocav {

// Throws Error naming `path` and the first problem of an inconsistent mesh; returns "" or the
// summary of its defects, which the caller shows as a warning.
template <int D>
std::string check_input_mesh(const Mesh<D>& mesh, const std::string& path);

// Reorients a mesh given all inverted (inverted_input.hpp) and gives the faces of the domain's
// boundary without a facet one of ref 0 (open_boundary.hpp), each said through `warn` (may be empty)
// naming `path`.
template <int D>
void prepare_input_mesh(Mesh<D>& mesh, const std::string& path, const std::function<void(const std::string&)>& warn);

}  // namespace hocav
