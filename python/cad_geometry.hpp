// What the module hocav._gmsh gives hocav._hocav (docs/python.md, "gmsh"): the library's
// make_boundary_geometry, which reads CAD models through gmsh. Only _gmsh links gmsh, so that
// `import hocav` loads none of its libraries; _hocav imports _gmsh on the first CAD surface and
// takes these function pointers from its capsule. Both modules are built from the same headers, so
// the objects the pointers make and take have one layout on both sides.
#pragma once

#include <memory>

#include "mesh/mesh.hpp"
#include "surface/boundary_choice.hpp"

namespace hocav::python {

template <int D>
using MakeBoundaryGeometry = std::unique_ptr<BoundaryGeometry<D>> (*)(const BoundaryChoice&, const Mesh<D>&);

struct CadGeometryMakers {
  MakeBoundaryGeometry<2> two;
  MakeBoundaryGeometry<3> three;

  template <int D>
  MakeBoundaryGeometry<D> of() const {
    if constexpr (D == 2)
      return two;
    else
      return three;
  }
};

// The capsule's name, checked when _hocav takes the pointer out.
inline constexpr const char* kCadGeometryMakersName = "hocav._gmsh.cad_geometry_makers";

}  // namespace hocav::python
