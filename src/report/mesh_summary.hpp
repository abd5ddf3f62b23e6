// A mesh in one line, as the commands print it: "2D P1: 356 vertices, 605 triangles, 95 boundary edges".
#pragma once

#include <string>

#include "mesh/mesh.hpp"

namespace hocav {

template <int D>
std::string mesh_summary(const Mesh<D>& mesh);

// The same line for a P1 mesh known by its counts (a mesh read in pieces).
std::string p1_mesh_summary(int dimension, Index vertices, Index elements, Index facets);

}  // namespace hocav
