// A mesh in one line, as the commands print it: "2D P1: 356 vertices, 605 triangles, 95 boundary edges".
#pragma once

#include <string>

#include "mesh/mesh.hpp"

namespace hocav {

template <int D>
std::string mesh_summary(const Mesh<D>& mesh);

}  // namespace hocav
