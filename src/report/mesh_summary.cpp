#include "report/mesh_summary.hpp"

namespace hocav {

template <int D>
std::string mesh_summary(const Mesh<D>& mesh) {
  std::string summary = std::to_string(D) + "D P" + std::to_string(mesh.order()) + ": ";
  summary += std::to_string(mesh.vertex_count()) + " vertices, ";
  summary += std::to_string(mesh.element_count()) + (D == 2 ? " triangles, " : " tetrahedra, ");
  summary += std::to_string(mesh.facet_count()) + (D == 2 ? " boundary edges" : " boundary triangles");
  if (mesh.is_p2()) summary += ", " + std::to_string(mesh.edge_count()) + " P2 nodes";
  return summary;
}

template std::string mesh_summary(const Mesh<2>&);
template std::string mesh_summary(const Mesh<3>&);

}  // namespace hocav
