// The boundary geometry that a `surface` option names, for adapt and curve: the library's
// make_boundary_geometry, given the CAD reader of hocav._gmsh when the surface is a CAD model
// (imported then: python/cad_geometry.hpp).
#include "binding.hpp"
#include "cad_geometry.hpp"

namespace hocav::python {
namespace {

// The readers of hocav._gmsh; imports it (loading gmsh) the first time.
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
  const CadBoundaryMaker<D> make_cad = choice.kind == BoundaryKind::kCad ? cad_geometry_makers().of<D>() : nullptr;
  return [choice, make_cad](const Mesh<D>& mesh) { return make_boundary_geometry<D>(choice, mesh, make_cad); };
}

template GeometryMaker<2> geometry_maker(const std::string&);
template GeometryMaker<3> geometry_maker(const std::string&);

}  // namespace hocav::python
