#include "surface/boundary_choice.hpp"
#include "surface/cad_boundary_gmsh.hpp"

namespace hocav {

template <int D>
std::unique_ptr<BoundaryGeometry<D>> make_cad_boundary(const std::string& cad_path, const Mesh<D>& mesh) {
  return std::make_unique<CadBoundary<D>>(cad_path, mesh);
}

template <int D>
std::unique_ptr<BoundaryGeometry<D>> make_boundary_geometry(const BoundaryChoice& choice, const Mesh<D>& mesh) {
  return make_boundary_geometry<D>(choice, mesh, &make_cad_boundary<D>);
}

template std::unique_ptr<BoundaryGeometry<2>> make_cad_boundary(const std::string&, const Mesh<2>&);
template std::unique_ptr<BoundaryGeometry<3>> make_cad_boundary(const std::string&, const Mesh<3>&);
template std::unique_ptr<BoundaryGeometry<2>> make_boundary_geometry(const BoundaryChoice&, const Mesh<2>&);
template std::unique_ptr<BoundaryGeometry<3>> make_boundary_geometry(const BoundaryChoice&, const Mesh<3>&);

}  // namespace hocav
