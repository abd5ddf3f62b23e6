#include "mesh/inverted_input.hpp"

#include <utility>

#include "mesh/measure.hpp"

namespace hocav {

template <int D>
void reorient_every_element(Mesh<D>& mesh) {
  const bool had_topology = mesh.has_topology(), had_edges = mesh.has_edges() && mesh.edge_count() > 0;
  for (Index k = 0; k < mesh.element_count(); ++k) {
    auto vertices = mesh.element(k);
    std::swap(vertices[D - 1], vertices[D]);
    mesh.set_element(k, vertices, mesh.element_ref(k));
  }
  if (had_edges) mesh.build_edges();  // the elements' local edges follow their vertices
  if (had_topology) mesh.build_topology();
}

std::string inverted_input_warning(const std::string& name, long long element_count) {
  return name + ": every one of its " + std::to_string(element_count) +
         " elements is negatively oriented (the other convention): reoriented";
}

template <int D>
std::string reorient_inverted_mesh(Mesh<D>& mesh, const std::string& name) {
  if (mesh.is_p2() || mesh.element_count() == 0) return "";
  for (Index k = 0; k < mesh.element_count(); ++k)
    if (!(element_measure(mesh, k) < 0)) return "";
  reorient_every_element(mesh);
  return inverted_input_warning(name, mesh.element_count());
}

template void reorient_every_element(Mesh<2>&);
template void reorient_every_element(Mesh<3>&);
template std::string reorient_inverted_mesh(Mesh<2>&, const std::string&);
template std::string reorient_inverted_mesh(Mesh<3>&, const std::string&);

}  // namespace hocav
