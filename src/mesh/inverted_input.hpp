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

// Its two halves, for a mesh read in pieces (whose processes decide together): two vertices of every
// element swapped, and the warning for an input of `element_count` elements.
template <int D>
void reorient_every_element(Mesh<D>& mesh);
std::string inverted_input_warning(const std::string& name, long long element_count);

}  // namespace hocav
