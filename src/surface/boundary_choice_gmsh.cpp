#include "surface/boundary_choice.hpp"

namespace hocav {

template <int D>
std::unique_ptr<BoundaryGeometry<D>> make_boundary_geometry(const BoundaryChoice& choice, const Mesh<D>& mesh) {
  return make_boundary_geometry<D>(choice, mesh, &make_cad_boundary<D>);
}

template std::unique_ptr<BoundaryGeometry<2>> make_boundary_geometry(const BoundaryChoice&, const Mesh<2>&);
template std::unique_ptr<BoundaryGeometry<3>> make_boundary_geometry(const BoundaryChoice&, const Mesh<3>&);

}  // namespace hocav
