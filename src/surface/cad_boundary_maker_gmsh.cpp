// The CAD reader of boundary_choice.hpp: a CadBoundary, through gmsh. Apart from
// boundary_choice_gmsh.cpp so that the command can take it from its gmsh module instead
// (src/plugin/gmsh_services.hpp).
#include "surface/boundary_choice.hpp"
#include "surface/cad_boundary_gmsh.hpp"

namespace hocav {

template <int D>
std::unique_ptr<BoundaryGeometry<D>> make_cad_boundary(const std::string& cad_path, const Mesh<D>& mesh) {
  return std::make_unique<CadBoundary<D>>(cad_path, mesh);
}

template std::unique_ptr<BoundaryGeometry<2>> make_cad_boundary(const std::string&, const Mesh<2>&);
template std::unique_ptr<BoundaryGeometry<3>> make_cad_boundary(const std::string&, const Mesh<3>&);

}  // namespace hocav
