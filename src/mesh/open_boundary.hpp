// Facets for the faces of the domain's boundary that carry none: a volume mesh given without its
// boundary triangles (2D: edges), as mesh generators often write one. mmg makes them the same way;
// without them the adaptation takes the boundary's vertices for inner ones.
#pragma once

#include <string>

#include "mesh/mesh.hpp"

namespace hocav {

// Adds a facet of ref `ref` on every face with no element across it and no facet, ordered outward
// (as the face of its element), and rebuilds the topology when it adds any. Returns how many.
template <int D>
Index add_facets_on_open_faces(Mesh<D>& mesh, int ref);

// The same with ref 0, for an input mesh: returns the warning to show (naming `name`, the input),
// or "" when every boundary face had its facet.
template <int D>
std::string close_open_boundary(Mesh<D>& mesh, const std::string& name);

// That warning for `added` facets made ("" for none); a mesh read in pieces sums them first.
std::string open_boundary_warning(const std::string& name, long long added);

}  // namespace hocav
