#include "mesh/open_boundary.hpp"

#include <vector>

#include "mesh/simplex.hpp"

namespace hocav {

template <int D>
Index add_facets_on_open_faces(Mesh<D>& mesh, int ref) {
  std::vector<typename Mesh<D>::Facet> open;
  for (Index k = 0; k < mesh.element_count(); ++k)
    for (int face = 0; face <= D; ++face)
      if (mesh.neighbor(k, face) == kNoIndex && mesh.element_face_facet(k, face) == kNoIndex) {
        typename Mesh<D>::Facet facet;
        for (int i = 0; i < D; ++i) facet[i] = mesh.element(k)[face_vertices<D>(face)[i]];
        open.push_back(facet);
      }
  for (const auto& facet : open) mesh.add_facet(facet, ref);
  if (!open.empty()) mesh.build_topology();
  return static_cast<Index>(open.size());
}

template <int D>
std::string close_open_boundary(Mesh<D>& mesh, const std::string& name) {
  return open_boundary_warning(name, add_facets_on_open_faces(mesh, 0));
}

std::string open_boundary_warning(const std::string& name, long long added) {
  if (added == 0) return "";
  return name + ": " + std::to_string(added) + " boundary faces had no facet: facets of ref 0 made for them";
}

template Index add_facets_on_open_faces(Mesh<2>&, int);
template Index add_facets_on_open_faces(Mesh<3>&, int);
template std::string close_open_boundary(Mesh<2>&, const std::string&);
template std::string close_open_boundary(Mesh<3>&, const std::string&);

}  // namespace hocav
