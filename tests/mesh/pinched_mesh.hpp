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

// Two structured unit cubes (generate_cube(cells), the second's facet refs + 10 and element ref 2)
// that share only the edge x = y = 1 of the first, the second shifted by (1, 1, 0): its cells + 1
// vertices are non-manifold, its cells edges have four boundary faces. With its facets, without
// topology.
inline Mesh<3> cubes_sharing_an_edge(int cells) {
  Mesh<3> mesh = generate_cube(cells);
  const Mesh<3> copy = mesh;
  std::map<std::array<double, 3>, Index> at;
  for (Index v = 0; v < mesh.vertex_count(); ++v) at[{mesh.vertex(v)[0], mesh.vertex(v)[1], mesh.vertex(v)[2]}] = v;
  std::vector<Index> moved(static_cast<std::size_t>(copy.vertex_count()));
  for (Index v = 0; v < copy.vertex_count(); ++v) {
    const Vec3 p = copy.vertex(v) + Vec3{{1, 1, 0}};
    const auto found = at.find({p[0], p[1], p[2]});
    moved[v] = found != at.end() ? found->second : mesh.add_vertex(p);
  }
  for (Index k = 0; k < copy.element_count(); ++k) {
    Mesh<3>::Element element = copy.element(k);
    for (Index& v : element) v = moved[v];
    mesh.add_element(element, 2);
  }
  for (Index f = 0; f < copy.facet_count(); ++f) {
    Mesh<3>::Facet facet = copy.facet(f);
    for (Index& v : facet) v = moved[v];
    mesh.add_facet(facet, copy.facet_ref(f) + 10);
  }
  return mesh;
}

// Two structured unit squares (generate_square(cells), the second's facet refs + 10 and element ref
// 2) that share only the corner (1, 1), the second shifted by (1, 1). With its facets, without
// topology.
inline Mesh<2> squares_sharing_a_corner(int cells) {
  Mesh<2> mesh = generate_square(cells);
  const Mesh<2> copy = mesh;
  Index shared = 0;
  while (mesh.vertex(shared) != Vec2{{1, 1}}) ++shared;
  std::vector<Index> moved(static_cast<std::size_t>(copy.vertex_count()));
  for (Index v = 0; v < copy.vertex_count(); ++v) {
    const Vec2 p = copy.vertex(v) + Vec2{{1, 1}};
    moved[v] = p == mesh.vertex(shared) ? shared : mesh.add_vertex(p);
  }
  for (Index k = 0; k < copy.element_count(); ++k) {
    Mesh<2>::Element element = copy.element(k);
    for (Index& v : element) v = moved[v];
    mesh.add_element(element, 2);
  }
  for (Index f = 0; f < copy.facet_count(); ++f) {
    Mesh<2>::Facet facet = copy.facet(f);
    for (Index& v : facet) v = moved[v];
    mesh.add_facet(facet, copy.facet_ref(f) + 10);
  }
  return mesh;
}

}  // namespace hocav::mesh_test
