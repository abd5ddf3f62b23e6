#include "surface/boundary_choice.hpp"

#include "base/error.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav {

BoundaryChoice boundary_choice_named(const std::string& name) {
  if (name == "none") return {BoundaryKind::kNone, ""};
  if (name == "p3") return {BoundaryKind::kP3Surrogate, ""};
  if (name.starts_with("cad:") && name.size() > 4) return {BoundaryKind::kCad, name.substr(4)};
  throw Error("--surface: 'p3', 'cad:FILE' or 'none', not '" + name + "'");
}

template <int D>
std::unique_ptr<BoundaryGeometry<D>> make_boundary_geometry(const BoundaryChoice& choice, const Mesh<D>& mesh,
                                                            CadBoundaryMaker<D> make_cad) {
  switch (choice.kind) {
    case BoundaryKind::kNone: return nullptr;
    case BoundaryKind::kP3Surrogate: return std::make_unique<P3Surrogate<D>>(mesh);
    case BoundaryKind::kCad:
      if (make_cad == nullptr) throw Error(choice.cad_path + ": no CAD reader given for this CAD model");
      return make_cad(choice.cad_path, mesh);
  }
  return nullptr;
}

template std::unique_ptr<BoundaryGeometry<2>> make_boundary_geometry(const BoundaryChoice&, const Mesh<2>&, CadBoundaryMaker<2>);
template std::unique_ptr<BoundaryGeometry<3>> make_boundary_geometry(const BoundaryChoice&, const Mesh<3>&, CadBoundaryMaker<3>);

}  // namespace hocav
