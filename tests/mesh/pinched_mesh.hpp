// A mesh the ball walks see only half of, for the tests of what works around it.
#pragma once

#include <map>

#include "cases/structured.hpp"
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

// The mesh with a copy of itself shifted by `shift` (the copy's element ref 2 and facet refs + 10),
// the copy's vertices that land on one of the mesh's merged with it. With its facets, without
// topology.
template <int D>
Mesh<D> with_shifted_copy(Mesh<D> mesh, const Vec<D>& shift) {
  const Mesh<D> copy = mesh;
  std::map<std::array<double, D>, Index> at;
  for (Index v = 0; v < mesh.vertex_count(); ++v) at[mesh.vertex(v).c] = v;
  std::vector<Index> moved(static_cast<std::size_t>(copy.vertex_count()));
  for (Index v = 0; v < copy.vertex_count(); ++v) {
    const Vec<D> p = copy.vertex(v) + shift;
    const auto found = at.find(p.c);
    moved[v] = found != at.end() ? found->second : mesh.add_vertex(p);
  }
  const auto mapped = [&](auto ids) {
    for (Index& v : ids) v = moved[v];
    return ids;
  };
  for (Index k = 0; k < copy.element_count(); ++k) mesh.add_element(mapped(copy.element(k)), 2);
  for (Index f = 0; f < copy.facet_count(); ++f) mesh.add_facet(mapped(copy.facet(f)), copy.facet_ref(f) + 10);
  return mesh;
}

// Two structured unit cubes (generate_cube(cells)) that share only the edge x = y = 1 of the first:
// its cells + 1 vertices are non-manifold, its cells edges have four boundary faces.
inline Mesh<3> cubes_sharing_an_edge(int cells) { return with_shifted_copy<3>(generate_cube(cells), Vec3{{1, 1, 0}}); }

// Two structured unit squares (generate_square(cells)) that share only the corner (1, 1).
inline Mesh<2> squares_sharing_a_corner(int cells) { return with_shifted_copy<2>(generate_square(cells), Vec2{{1, 1}}); }

}  // namespace hocav::mesh_test
