// An input mesh whose every element is negatively oriented: a mesh written with the other
// orientation convention, which hocav's operators (positive elements) would refuse. mmg reorients
// such input; so does the adaptation and the curving, with a warning. A mesh with only some
// elements inverted stays an error (the consistency check names it).
#pragma once

#include <string>

#include "mesh/mesh.hpp"

namespace hocav {

// When every element of a P1 mesh has a negative measure, swaps two vertices of each (its faces,
// facets and edges are the same) and rebuilds the topology it had; returns the warning to show
// (naming `name`, the input), or "" when it changed nothing.
template <int D>
std::string reorient_inverted_mesh(Mesh<D>& mesh, const std::string& name);

}  // namespace hocav
