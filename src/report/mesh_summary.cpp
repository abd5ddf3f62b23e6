#include "report/mesh_summary.hpp"

namespace hocav {

namespace {

std::string counts_summary(int dimension, int order, Index vertices, Index elements, Index facets) {
  std::string summary = std::to_string(dimension) + "D P" + std::to_string(order) + ": ";
  summary += std::to_string(vertices) + " vertices, ";
  summary += std::to_string(elements) + (dimension == 2 ? " triangles, " : " tetrahedra, ");
  summary += std::to_string(facets) + (dimension == 2 ? " boundary edges" : " boundary triangles");
  return summary;
}

}  // namespace

template <int D>
std::string mesh_summary(const Mesh<D>& mesh) {
  std::string summary = counts_summary(D, mesh.order(), mesh.vertex_count(), mesh.element_count(), mesh.facet_count());
  if (mesh.is_p2()) summary += ", " + std::to_string(mesh.edge_count()) + " P2 nodes";
  return summary;
}

std::string p1_mesh_summary(int dimension, Index vertices, Index elements, Index facets) {
  return counts_summary(dimension, 1, vertices, elements, facets);
}

template std::string mesh_summary(const Mesh<2>&);
template std::string mesh_summary(const Mesh<3>&);

}  // namespace hocav
