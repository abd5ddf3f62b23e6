// Ball of a vertex (the elements around it) and shell of an edge (the elements around it), found
// by walking face adjacency from Mesh::vertex_element. Needs Mesh::build_topology().
#pragma once

#include <span>
#include <vector>

#include "mesh/mesh.hpp"

namespace hocav {

// Fills `ball` with the elements that contain vertex v (empty for an unused vertex). Elements
// are reached through faces around v, so a vertex pinching two parts of the mesh lists one part.
template <int D>
void collect_ball(const Mesh<D>& mesh, Index v, std::vector<Index>& ball);

// Fills `shell` with the elements that contain both a and b (empty when (a, b) is not an edge).
template <int D>
void collect_shell(const Mesh<D>& mesh, Index a, Index b, std::vector<Index>& shell);
// The same, from element `start`, which contains both a and b (no walk to find one).
template <int D>
void collect_shell_from(const Mesh<D>& mesh, Index start, Index a, Index b, std::vector<Index>& shell);

// Whether the shell of edge (a, b) (its elements, as collect_shell gives them) goes all around the
// edge inside the domain: no face through the edge is on the domain's boundary or carries a facet.
template <int D>
bool shell_is_closed(const Mesh<D>& mesh, std::span<const Index> shell, Index a, Index b);

// Fills `out` with the vertices of these elements other than a and b, once each, in the order met
// (a shell's ring with the edge's ends; a ball's neighbours with a = b = the centre).
template <int D>
void other_vertices(const Mesh<D>& mesh, std::span<const Index> elements, Index a, Index b, std::vector<Index>& out);

// The local index of vertex v in element k, or -1.
template <int D>
int local_vertex(const Mesh<D>& mesh, Index k, Index v);

}  // namespace hocav
