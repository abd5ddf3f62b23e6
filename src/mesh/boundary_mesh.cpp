#include "mesh/boundary_mesh.hpp"

namespace hocav {

template <int D>
Mesh<D> boundary_mesh_of(const Mesh<D>& mesh) {
  Mesh<D> boundary;
  for (Index v = 0; v < mesh.vertex_count(); ++v) boundary.add_vertex(mesh.vertex(v), mesh.vertex_ref(v));
  for (Index f = 0; f < mesh.facet_count(); ++f) boundary.add_facet(mesh.facet(f), mesh.facet_ref(f));
  for (Index l = 0; l < mesh.line_count(); ++l) boundary.add_line(mesh.line(l), mesh.line_ref(l));
  boundary.corners() = mesh.corners();
  boundary.required_vertices() = mesh.required_vertices();
  boundary.ridges() = mesh.ridges();
  boundary.required_edges() = mesh.required_edges();
  boundary.required_triangles() = mesh.required_triangles();
  return boundary;
}

template Mesh<2> boundary_mesh_of(const Mesh<2>&);
template Mesh<3> boundary_mesh_of(const Mesh<3>&);

}  // namespace hocav
