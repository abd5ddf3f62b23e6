// Meshes with facets inside the domain (interfaces between element refs, four refs meeting at a
// junction, a baffle), for the tests of the operators that must adapt them.
#pragma once

#include <algorithm>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "../metric/metric_test_support.hpp"
#include "mesh/mesh.hpp"

namespace hocav::mesh_test {

// The first coordinate of element k's centroid.
template <int D>
double centroid_x(const Mesh<D>& mesh, Index k) {
  double x = 0;
  for (Index v : mesh.element(k)) x += mesh.vertex(v)[0] / (D + 1);
  return x;
}

// Face `face` of element k as a facet.
template <int D>
typename Mesh<D>::Facet element_face(const Mesh<D>& mesh, Index k, int face) {
  typename Mesh<D>::Facet facet;
  for (int i = 0; i < D; ++i) facet[i] = mesh.element(k)[face_vertices<D>(face)[i]];
  return facet;
}

// The structured unit square or cube (metric_test::unit_mesh) in two element refs, 1 for x < 0.5
// and 2 past it, with the faces between them as facets of ref 9: an interface inside the domain.
// With topology.
template <int D>
Mesh<D> two_refs_across_an_interface(int cells_per_side) {
  Mesh<D> mesh = metric_test::unit_mesh<D>(cells_per_side);
  for (Index k = 0; k < mesh.element_count(); ++k) {
    mesh.set_element(k, mesh.element(k), centroid_x(mesh, k) < 0.5 ? 1 : 2);
    if (centroid_x(mesh, k) > 0.5) continue;
    for (int face = 0; face <= D; ++face) {
      const typename Mesh<D>::Facet facet = element_face(mesh, k, face);
      if (std::all_of(facet.begin(), facet.end(), [&](Index v) { return mesh.vertex(v)[0] == 0.5; })) mesh.add_facet(facet, 9);
    }
  }
  mesh.build_topology();
  return mesh;
}

// The structured unit square or cube in four element refs by quadrant, 1 + (x > 0.5) + 2 (y > 0.5),
// with the faces between them as facets, of ref 9 on the plane x = 0.5 and 10 on y = 0.5: four
// interfaces meeting at the centre (2D) or along the line x = y = 0.5 (3D). With topology.
template <int D>
Mesh<D> four_refs_by_quadrant(int cells_per_side) {
  Mesh<D> mesh = metric_test::unit_mesh<D>(cells_per_side);
  const auto quadrant = [&](Index k) {
    double x = 0, y = 0;
    for (Index v : mesh.element(k)) x += mesh.vertex(v)[0] / (D + 1), y += mesh.vertex(v)[1] / (D + 1);
    return 1 + (x > 0.5) + 2 * (y > 0.5);
  };
  for (Index k = 0; k < mesh.element_count(); ++k) mesh.set_element(k, mesh.element(k), quadrant(k));
  mesh.build_topology();
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int face = 0; face <= D; ++face) {
      const Index across = mesh.neighbor(k, face);
      if (across == kNoIndex || across < k || mesh.element_ref(across) == mesh.element_ref(k)) continue;
      const typename Mesh<D>::Facet facet = element_face(mesh, k, face);
      const bool on_x = std::all_of(facet.begin(), facet.end(), [&](Index v) { return mesh.vertex(v)[0] == 0.5; });
      mesh.add_facet(facet, on_x ? 9 : 10);
    }
  mesh.build_topology();
  return mesh;
}

// The same in one element ref: the plane x = 0.5 is a baffle of ref 9 (one ref on both sides).
template <int D>
Mesh<D> baffle_across_the_middle(int cells_per_side) {
  Mesh<D> mesh = two_refs_across_an_interface<D>(cells_per_side);
  for (Index k = 0; k < mesh.element_count(); ++k) mesh.set_element(k, mesh.element(k), 1);
  mesh.build_topology();
  return mesh;
}

// `mesh` with its elements in a random order (the same on every process of a distributed test) and
// every other facet turned: the side an inner facet is linked from, and the orientation of a
// baffle's facets, vary along the surface; a file of it has runs of elements scattered over the
// domain, so that a baffle's patch spans every piece. With topology.
template <int D>
Mesh<D> elements_shuffled(const Mesh<D>& mesh) {
  std::vector<Index> order(static_cast<std::size_t>(mesh.element_count()));
  std::iota(order.begin(), order.end(), Index{0});
  std::shuffle(order.begin(), order.end(), std::mt19937(7));
  Mesh<D> out;
  for (Index v = 0; v < mesh.vertex_count(); ++v) out.add_vertex(mesh.vertex(v), mesh.vertex_ref(v));
  for (Index k : order) out.add_element(mesh.element(k), mesh.element_ref(k));
  for (Index f = 0; f < mesh.facet_count(); ++f) {
    typename Mesh<D>::Facet facet = mesh.facet(f);
    if (f % 2) std::swap(facet[0], facet[1]);
    out.add_facet(facet, mesh.facet_ref(f));
  }
  out.build_topology();
  return out;
}

}  // namespace hocav::mesh_test
