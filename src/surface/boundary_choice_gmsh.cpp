#include "surface/boundary_choice.hpp"
#include "surface/cad_boundary_gmsh.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {

template <int D>
std::unique_ptr<BoundaryGeometry<D>> make_boundary_geometry(const BoundaryChoice& choice, const Mesh<D>& mesh) {
  switch (choice.kind) {
    case BoundaryKind::kNone: return nullptr;
    case BoundaryKind::kP3Surrogate: return std::make_unique<P3Surrogate<D>>(mesh);
    case BoundaryKind::kCad: return std::make_unique<CadBoundary<D>>(choice.cad_path, mesh);
  }
  return nullptr;
}

template std::unique_ptr<BoundaryGeometry<2>> make_boundary_geometry(const BoundaryChoice&, const Mesh<2>&);
template std::unique_ptr<BoundaryGeometry<3>> make_boundary_geometry(const BoundaryChoice&, const Mesh<3>&);

}  // namespace hocav
