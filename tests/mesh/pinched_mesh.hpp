// A mesh the ball walks see only half of, for the tests of what works around it.
#pragma once

#include "mesh/mesh.hpp"

namespace hocav::mesh_test {

// Two positive tetrahedra that share only vertex 0 (no face, no edge): a walk around vertex 0
// through faces reaches one of them. Without topology.
inline Mesh<3> pinched_tetrahedra() {
  Mesh<3> mesh;
  for (const Vec3& p :
       {Vec3{{0, 0, 0}}, Vec3{{1, 0, 0}}, Vec3{{0, 1, 0}}, Vec3{{0, 0, 1}}, Vec3{{-1, 0, 0}}, Vec3{{0, -1, 0}}, Vec3{{0, 0, -1}}})
    mesh.add_vertex(p);
  mesh.add_element({0, 1, 2, 3});
  mesh.add_element({0, 5, 4, 6});
  return mesh;
}

}  // namespace hocav::mesh_test
