// The boundary geometry that a `surface` option names, for adapt and curve: none and the P3
// surrogate made here; a CAD model by hocav._gmsh, imported then (python/cad_geometry.hpp).
#include "base/error.hpp"
#include "binding.hpp"
#include "cad_geometry.hpp"
#include "surface/p3_surrogate.hpp"

namespace hocav::python {
namespace {

// The makers of hocav._gmsh; imports it (loading gmsh) the first time.
const CadGeometryMakers& cad_geometry_makers() {
  const py::object capsule = py::module_::import("hocav._gmsh").attr("cad_geometry_makers");
  void* makers = PyCapsule_GetPointer(capsule.ptr(), kCadGeometryMakersName);  // checks the name
  if (makers == nullptr) throw py::error_already_set();
  return *static_cast<const CadGeometryMakers*>(makers);
}

}  // namespace

template <int D>
GeometryMaker<D> geometry_maker(const std::string& surface) {
  const BoundaryChoice choice = boundary_choice_named(surface);
  if (choice.kind == BoundaryKind::kCad) {
    const MakeBoundaryGeometry<D> make = cad_geometry_makers().of<D>();
    return [make, choice](const Mesh<D>& mesh) { return make(choice, mesh); };
  }
  const bool surrogate = choice.kind == BoundaryKind::kP3Surrogate;
  return [surrogate](const Mesh<D>& mesh) -> std::unique_ptr<BoundaryGeometry<D>> {
    if (!surrogate) return nullptr;
    return std::make_unique<P3Surrogate<D>>(mesh);
  };
}

template GeometryMaker<2> geometry_maker(const std::string&);
template GeometryMaker<3> geometry_maker(const std::string&);

}  // namespace hocav::python
